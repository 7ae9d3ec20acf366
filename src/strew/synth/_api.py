"""Public entry points: :func:`synthesize` and :func:`new_state`."""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from typing import Any

import numpy as np

from .._errors import InputError
from ..arrangement import Arrangement
from ..region import Region
from ._grow import brush as _brush
from ._grow import fill as _fill
from ._metric import average_neighborhood_distance
from ._palette import Palette, Selection
from ._patch import patch_initialize
from ._prepare import prepare
from ._state import SynthParams, SynthState

__all__ = ["synthesize", "new_state", "as_selection", "set_selection"]

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
    region: Region | None = None,
    *,
    selection: Any = None,
    fill_point: tuple[float, float] | None = None,
    brush_points: np.ndarray | None = None,
    brush_radius: float | np.ndarray | None = None,
    init: str = "grow",
    k: int = 5,
    c: float = 2.0,
    optimize: str = "horizon",
    kind_cost: float = 1.0,
    time_budget: float | None = None,
    patch_rounds: int | None = None,
    keep_voids: bool = False,
    measure: bool = True,
    trace: list | None = None,
    rng: int | np.random.Generator | None = None,
    progress: Callable | None = None,
    should_cancel: Callable | None = None,
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
    region : Region
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
    progress, should_cancel : callables, optional

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
    if init not in ("grow", "patch"):
        raise InputError(f"init: expected grow or patch, got {init!r}")
    if region is None and brush_points is None:
        raise InputError("synth: give a region (or a size) to fill, or a brush stroke")
    if region is not None:  # refuse work beyond the limits before starting (issue 17)
        from .._limits import check_work, element_area

        check_work("--size/--region", region=region, per_element=min(element_area(a) for a in as_selection(exemplars, selection).exemplars()))
    state = new_state(exemplars, region, selection=selection, k=k, c=c, optimize=optimize, kind_cost=kind_cost, rng=rng, **params)
    if trace is not None:
        state.trace = trace
    if init == "patch":
        if brush_points is not None or fill_point is not None:
            raise InputError("init patch: fills the whole region; it takes no --fill or --brush")
        patch_initialize(state, time_budget=float(time_budget or 0.0), rounds=patch_rounds, progress=progress, should_cancel=should_cancel)
    elif brush_points is not None:
        if brush_radius is None:
            raise InputError("brush: give a brush radius")
        _brush(state, np.asarray(brush_points, float), brush_radius, progress=progress, should_cancel=should_cancel)
    else:
        _fill(state, fill_point, progress=progress, should_cancel=should_cancel)
    meta: dict[str, Any] = {"synth": {"iterations": state.iterations, "elements_with_voids": state.n}}
    if measure:
        d = average_neighborhood_distance(state, sample=1000) if state.n else None
        meta["synth"]["average_neighborhood_distance"] = d
    return state.to_arrangement(keep_voids=keep_voids, meta=meta)
