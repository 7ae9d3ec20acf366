"""Public entry points: :func:`synthesize` and :func:`new_state`."""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from typing import Any

import numpy as np

from .._errors import InputError
from .._method import MethodSpec, Param, as_region, check_context, empty_result, free_region, is_empty, seed_record, stamp
from ..arrangement import Arrangement
from ..region import Region
from ._grow import brush as _brush
from ._grow import fill as _fill
from ._metric import average_neighborhood_distance
from ._palette import Palette, Selection
from ._patch import patch_initialize
from ._prepare import prepare
from ._state import SynthParams, SynthState

__all__ = ["synthesize", "new_state", "as_selection", "set_selection", "SPEC"]

SPEC = MethodSpec(
    name="synth",
    command="synth",
    entry="strew.synth:synthesize",
    paper="Davison, Samavati, Jacob, Interactive example-palettes for discrete element texture synthesis, 2018",
    summary="Synthesize a texture from exemplars by fast region growing (Davison et al.).",
    progress_message="synth",
    region_required=False,
    input=Param("exemplars", "any", help="Exemplars: a Palette, Selection, Arrangement, or a list or dict of them.", section="§5.5",
                parse="palette-files", metavar="EXEMPLAR..."),
    params=(
        Param("selection", "any", None, help="Exemplars of the palette to use: a name, names, {name: weight} or {name: Region}.",
              flag="--select", cli="multiple", parse="selection", metavar="NAME[:W]|NAME=REGION",
              cli_help="Exemplars of the palette to use, with weights (shares of the region), or each with the region file it fills "
                       "(repeatable; default all).", section="§5.5"),
        Param("fill_point", "point", None, unit="document units", help="Filler: grow from this point until no room is left.",
              flag="--fill", parse="point", metavar="X,Y", section="§5.4"),
        Param("brush_points", "points", None, help="Generative brush: (m, 2) points along a stroke.", cli=False, section="§5.4"),
        Param("brush_radius", "any", None, unit="document units", help="Brush radius, one or one per brush point.", parse="number",
              section="§5.4"),
        Param("init", "str", "grow", choices=("grow", "patch"), help="Region growing, or Ma et al.'s patch initialisation.", section="§5, §6.4"),
        Param("k", "int", 5, low=1, help="k-coherence set size.", section="§5.1"),
        Param("c", "float", 2.0, low=1, low_open=True, what="the ratio constant", help="Ratio constant rejecting poor candidates.", section="§5.1"),
        Param("optimize", "str", "horizon", choices=("horizon", "global", "none"), help="Optimise the horizon, every element, or nothing.",
              section="§5.2-5.3, §6.4"),
        Param("kind_cost", "float", 1.0, low=0, help="Kind mismatch cost omega, in units of the squared pairing threshold.", section="§4, Eq. 1"),
        Param("time_budget", "float", None, low=0, unit="seconds", help="init patch: seconds of global optimisation after the patches.",
              cli=False, section="§6.4"),
        Param("patch_rounds", "int", None, low=0, help="init patch: rounds of global optimisation instead (deterministic) [default: 5 on the CLI].",
              section="§6.4"),
        Param("keep_voids", "bool", False, help="Keep void elements (column 'void') instead of hiding them.", cli="flag", section="§5.6"),
        Param("measure", "bool", True, help="Record the final average neighbourhood distance (Eq. 5) in meta.", cli=False, section="Eq. 5"),
        Param("trace", "any", None, help="A list receiving (seconds, elements, Eq. 5) after every iteration.", cli=False, section="Fig. 17"),
        Param("seed_separation", "float", None, low=0, low_open=True, help="Seeds at least this fraction of their neighbourhood radius apart.",
              cli=False, section="§5.1"),
        Param("relaxation", "float", None, low=0, high=1, low_open=True, help="Fraction of the least-squares step taken.", cli=False,
              section="§5.3"),
        Param("frozen_weight", "float", None, low=0, help="Weight of a frozen element's old position.", cli=False, section="§5.3"),
        Param("frozen_prediction_weight", "float", None, low=0, help="Factor on predictions for frozen elements.", cli=False, section="§5.3"),
        Param("horizon_anchor", "float", None, low=0, help="Weight keeping horizon elements near their old positions.", cli=False,
              section="extension"),
        Param("max_failures", "int", None, low=1, help="Failures after which a free-space point is dropped.", cli=False, section="§5.1"),
        Param("check_energy", "bool", None, help="Keep an optimisation step only when it lowers Eq. 2.", cli=False, section="§5.3"),
        Param("yield_window", "int", None, low=0, help="Iterations whose horizon elements yield to a larger size class.", cli=False,
              section="extension of §7"),
        Param("noise_floor", "float", None, low=0, help="Optimisation moves shortened by the element's prediction spread, by at most "
              "this fraction of its radius (keeps the exemplar's jitter; near-regular exemplars that are not jittered lattices).", cli=False, section="extension of §5.2-5.3"),
    ),
)

def as_selection(exemplars: Any, selection: Any = None) -> Selection:
    """Normalise exemplars (a Palette, a Selection, one Arrangement, a list or a dict of
    them) and a selection (name, names, or ``{name: weight}``) to a :class:`Selection`."""
    if isinstance(exemplars, Selection):
        if selection is not None:
            return exemplars.palette.select(selection)
        return exemplars
    if isinstance(exemplars, Palette):
        palette = exemplars
    elif isinstance(exemplars, Arrangement):
        palette = Palette.from_arrangement(exemplars)
    elif isinstance(exemplars, Mapping):
        palette = Palette(exemplars)
    elif isinstance(exemplars, Iterable):
        palette = Palette.from_arrangements(list(exemplars))
    else:
        raise InputError(f"exemplars: expected a Palette or Arrangement(s), got {type(exemplars).__name__}")
    return palette.select(selection)


def new_state(
    exemplars: Any,
    region: Region | None = None,
    *,
    selection: Any = None,
    k: int = 5,
    c: float = 2.0,
    optimize: str = "horizon",
    kind_cost: float = 1.0,
    rng: int | np.random.Generator | None = None,
    **params: Any,
) -> SynthState:
    """An empty output for the tools (:func:`fill`, :func:`brush`, :func:`erase`).

    Parameters
    ----------
    exemplars : Palette, Selection, Arrangement, list or dict of Arrangement
    region : Region, optional
    selection : str, list of str or dict of str to float, optional
        Which exemplars of the palette drive synthesis, with weights.
    k, c, optimize, kind_cost, params
        See :class:`SynthParams`.
    """
    prm = SynthParams(k=k, c=c, optimize=optimize, kind_cost=kind_cost, **params)
    sel = as_selection(exemplars, selection)
    prep = prepare(sel, k=prm.k, kind_cost=prm.kind_cost)
    return SynthState(prep, region, prm, rng)


def set_selection(state: SynthState, selection: Any) -> None:
    """Switch the selection that drives ``state`` (a name, names or ``{name: weight}``).

    The output keeps its elements; later fills and strokes use the new selection, so
    textures of different scales can share one output (§4.1, §5.5).
    """
    sel = state.prep.palette.select(selection)
    state.prep.set_selection(sel)


def synthesize(
    exemplars: Any,
    region: Region | Any = None,
    *,
    context: Arrangement | None = None,
    rng: int | np.random.Generator | None = None,
    progress: Callable | None = None,
    should_cancel: Callable | None = None,
    _balance_drop: Any = None,
    **params: Any,
) -> Arrangement:
    """Synthesize a discrete element texture from exemplars (Davison et al. 2018).

    Fills ``region`` by region growing (§5) from its centre, from ``fill_point`` (the
    filler, §5.4), or along a brush stroke (``brush_points`` with ``brush_radius``,
    §5.4). ``init="patch"`` uses Ma et al.'s patch initialisation with global
    optimisation instead (§6.4 baseline).

    Parameters
    ----------
    exemplars : Palette, Selection, Arrangement, list or dict of Arrangement
        Exemplar columns ``radius``, ``neighborhood_radius`` and ``void`` are honoured.
    region : Region, shapely polygon, ``"WxH"`` or (W, H), optional
        Required unless a brush stroke is given.
    context : Arrangement, optional
        Fixed elements to synthesize around (issues 15, 18, 19; needs ``region``). They
        are never overlapped (the region less their footprint), and those near the
        region whose kind names are kinds of the selection are already-synthesized
        neighbours: each takes the attributes of its best-matching exemplar element
        (Eq. 1), neighbourhood matching and optimisation see them (frozen, §5.2), and
        growth starts from them, so a tile grown beside finished ones continues their
        texture (see ``_context``). They are not part of the result.
    selection : str, list of str or dict of str to float, optional
    fill_point : (2,) float, optional
    brush_points : (m, 2) float, optional
    brush_radius : float or (m,) float, optional
    init : {"grow", "patch"}
    k : int
        k-coherence set size (5).
    c : float
        Ratio constant of the generation step (2).
    optimize : {"horizon", "global", "none"}
    kind_cost : float
        Kind mismatch cost omega, in units of the squared pairing threshold.
    time_budget : float, optional
        For ``init="patch"``: seconds of global optimisation after the patches (0).
    patch_rounds : int, optional
        For ``init="patch"``: rounds of global optimisation instead (deterministic).
    keep_voids : bool
        Keep void elements (flagged in the ``void`` column) instead of hiding them.
    measure : bool
        Record the final average neighbourhood distance (Eq. 5, on a sample of 1,000
        elements) in ``meta["synth"]``.
    trace : list, optional
        Receives ``(seconds, elements, average neighbourhood distance)`` after every
        iteration (Eq. 5 on a sample of 200 elements; time spent measuring excluded).
    rng : int or Generator or None
        Recorded in ``meta`` (``seed`` or ``rng_state``) with every parameter.
    progress, should_cancel : callables, optional
    **params
        Keyword only, checked against :data:`SPEC` first: the names above from
        ``selection`` on, and the :class:`SynthParams` fields (``seed_separation``,
        ``relaxation``, ...).

    Returns
    -------
    Arrangement
        With columns ``radius``, ``neighborhood_radius`` (per-element parameters copied
        from the exemplar, §4.1) and ``exemplar``; ``meta["synth"]`` holds the final
        average neighbourhood distance and the number of iterations.

    Examples
    --------
    >>> from strew import Arrangement, Region, Shape
    >>> import numpy as np
    >>> g = np.mgrid[0:6, 0:6].reshape(2, -1).T * 10.0
    >>> ex = Arrangement({"sq": Shape.rectangle(6, 6)}, [0] * len(g), g[:, 0], g[:, 1])
    >>> out = synthesize(ex, Region.rectangle(100, 100), rng=1)
    >>> len(out) > 80
    True
    """
    prm = SPEC.validate(params)
    gen, seed = seed_record(rng)
    region = as_region(region)
    ctx = check_context(context)
    if ctx is not None and region is None:
        raise InputError("context: needs a region (the context's elements are kept out of it)")
    sel = as_selection(exemplars, prm["selection"])
    free = free_region(region, ctx)
    if is_empty(free):
        arr = empty_result({kk: v for a in sel.exemplars() for kk, v in a.shapes.items()}, region,
                           "the region is empty" if ctx is None else "the context covers the region")
    else:
        arr = _synthesize(sel, free, rng=gen, progress=progress, should_cancel=should_cancel, context=ctx, _balance_drop=_balance_drop, **prm)
        if free is not region:
            arr = arr.replace(region=region)
    record = {**prm, "trace": None}  # an output receiver, not a setting
    given = exemplars if isinstance(exemplars, (Arrangement, list, tuple, Mapping)) else list(sel.exemplars())
    return stamp(arr, SPEC, given, record, seed, region=region, context=ctx)


def _synthesize(
    exemplars: Selection,
    region: Region | None,
    *,
    selection: Any,
    fill_point: tuple[float, float] | None,
    brush_points: np.ndarray | None,
    brush_radius: float | np.ndarray | None,
    init: str,
    k: int,
    c: float,
    optimize: str,
    kind_cost: float,
    time_budget: float | None,
    patch_rounds: int | None,
    keep_voids: bool,
    measure: bool,
    trace: list | None,
    rng: np.random.Generator,
    progress: Callable | None,
    should_cancel: Callable | None,
    context: Arrangement | None = None,
    _balance_drop: Any = None,
    **params: Any,
) -> Arrangement:
    """Synthesis on checked arguments; see :func:`synthesize`. ``_balance_drop``
    (private, set by :func:`strew.tiles.run_tile`): the part of a tile's region whose
    elements the tile drops (``SynthState._balance_drop``, read by
    ``_grow._prefer_balanced``)."""
    selection = None  # already applied to ``exemplars``
    params = {key: v for key, v in params.items() if v is not None}
    if init not in ("grow", "patch"):
        raise InputError(f"init: expected grow or patch, got {init!r}")
    if region is None and brush_points is None:
        raise InputError("region: give a region (or a size) to fill, or a brush stroke")
    if region is not None:  # refuse work beyond the limits before starting (issue 17)
        from .._limits import check_work, element_area

        check_work("region", region=region, per_element=min(element_area(a) for a in as_selection(exemplars, selection).exemplars()))
    state = new_state(exemplars, region, selection=selection, k=k, c=c, optimize=optimize, kind_cost=kind_cost, rng=rng, **params)
    if trace is not None:
        state.trace = trace
    state._balance_drop = _balance_drop
    with_context = False
    if context is not None and len(context) and region is not None:
        from ._context import add_context

        with_context = len(add_context(state, context)) > 0
    if init == "patch":
        if brush_points is not None or fill_point is not None:
            raise InputError("init: 'patch' fills the whole region; it takes no fill_point or brush_points")
        patch_initialize(state, time_budget=float(time_budget or 0.0), rounds=patch_rounds, progress=progress, should_cancel=should_cancel)
    elif brush_points is not None:
        if brush_radius is None:
            raise InputError("brush_radius: needed with brush_points")
        _brush(state, np.asarray(brush_points, float), brush_radius, progress=progress, should_cancel=should_cancel)
    elif with_context and fill_point is None and len(state.prep.selection.names) == 1 and state.prep.selection.regions is None:
        from ._context import fill_with_context

        fill_with_context(state, progress=progress, should_cancel=should_cancel)
    else:
        _fill(state, fill_point, progress=progress, should_cancel=should_cancel)
    meta: dict[str, Any] = {"synth": {"iterations": state.iterations, "elements_with_voids": int((~state.fixed).sum())}}
    if measure:
        d = average_neighborhood_distance(state, sample=1000) if state.n else None
        meta["synth"]["average_neighborhood_distance"] = d
    return state.to_arrangement(keep_voids=keep_voids, meta=meta)
