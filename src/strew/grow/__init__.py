"""Example-based growth from one seed (Ijiri, Měch, Igarashi, Miller, Eurographics 2008).

:func:`analyze` builds the connectivity of a reference arrangement (§4);
:func:`grow` synthesises a larger arrangement from it by local growth (§5) with three
rotation modes, the spray, flow-field and boundary tools, per-element variation and a
least-squares relaxation. :func:`flip_edge` edits the connectivity (Fig. 3) and
:func:`relax_positions` is the relaxation of Eq. 5 / Eq. 6 on its own.
:class:`SprayGrowth` is the spray tool as one growth that follows a stroke (§3, §5.1).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Mapping, Sequence
from typing import Any

import numpy as np

from .._errors import InputError
from .._method import MethodSpec, Param, as_region, check_context, empty_result, free_region, is_empty, seed_record, stamp
from ..arrangement import Arrangement
from ..region import Region
from ._analysis import Reference, analyze, default_priority, delaunay_edges, flip_edge, size_priority
from ._growth import GrowParams, grow_reference
from ._match import matching_set, match_references, order_target
from ._relax import relax_positions
from ._spray import SprayGrowth

__all__ = [
    "grow",
    "SprayGrowth",
    "analyze",
    "flip_edge",
    "Reference",
    "delaunay_edges",
    "matching_set",
    "match_references",
    "order_target",
    "relax_positions",
    "size_priority",
    "lattice_periods",
    "MODES",
    "SPEC",
]

MODES = ("fixed", "rotate", "flow")
#: periodic tiles: the most a lattice exemplar's centres are moved (relative) to fit a
#: tile that its periods do not divide (see ``_grow_snapped``)
MAX_STRETCH = 0.05

SPEC = MethodSpec(
    name="grow",
    command="grow",
    entry="strew.grow:grow",
    paper="Ijiri, Mech, Igarashi, Miller, An Example-based Procedural System for Element Arrangement, 2008",
    summary="Grow from an exemplar, element by element, from one seed (Ijiri et al.).",
    progress_message="grow",
    region_required=False,
    input=Param("exemplar", "any", help="The reference arrangement (or its analysis).", section="§4", parse="arrangement-file", metavar="EXEMPLAR"),
    params=(
        Param("count", "int", None, low=1, help="Stop at this many elements [default: fill the region].", section="§5", metavar="N"),
        Param("start", "point", None, unit="document units", help="The initial seed [default: the region's centre].", parse="point",
              metavar="X,Y", section="§5.1"),
        Param("start_kind", "str", None, help="Symbol id (kind) of the initial seed.", metavar="KIND", section="§5.1"),
        Param("mode", "str", "fixed", choices=MODES, help="Rotation mode: keep, best-fit rotate, or follow the flow field.", section="§5.3"),
        Param("flow", "any", None, help="Flow field: callable (m, 2) points -> (m, 2) directions; implies mode flow on the CLI.",
              cli_help="Flow-field strokes (SVG or JSON); implies --mode flow unless --mode is given.", parse="flow-strokes", metavar="FILE",
              section="§5.3, Fig. 1e"),
        Param("boundary", "any", None, help="Boundary strokes that no edge of the growth crosses.", parse="strokes", metavar="FILE",
              cli_help="Boundary strokes (SVG or JSON) that stop growth.", section="Fig. 1f"),
        Param("spray", "any", None, help="Spray path: only seeds within spray_radius of it grow.", parse="stroke", metavar="FILE",
              cli_help="Spray path (SVG or JSON): only seeds within --spray-radius of it grow.", section="§3, Fig. 1c"),
        Param("spray_radius", "float", None, low=0, low_open=True, unit="document units", help="Radius of the spray tool.", section="§3"),
        Param("priority", "any", None, help="Seed priority per kind [default: larger kinds first when kinds differ in size and mix, else 0].",
              cli="multiple", parse="kind-numbers", metavar="KIND=P", section="§5.1"),
        Param("jitter_scale", "float", 0.0, low=0, high=1, high_open=True, help="Relative scale noise S: x(1 +- S).", section="§3"),
        Param("jitter_rotation", "float", 0.0, low=0, unit="radians", help="Rotation noise (+-).", parse="degrees",
              cli_help="Rotation noise in degrees (+-).", section="§3"),
        Param("jitter_color", "float", 0.0, low=0, help="Colour noise C: fill x(1 +- C).", section="§3"),
        Param("relax", "bool", True, help="The windowed least-squares relaxation.", flag="--no-relax", cli="no-flag",
              cli_help="Turn off the least-squares relaxation.", section="§5.5"),
        Param("flips", "any", (), help="Edges (i, j) of the exemplar's connectivity to flip first.", flag="--flip", cli="multiple",
              parse="index-pairs", metavar="I,J", cli_help="Flip edge I,J of the exemplar's connectivity (repeatable).", section="§4, Fig. 3"),
        Param("connectivity", "bool", False, help="Write the grown connectivity into the document (entry 'connectivity').", cli="flag"),
        Param("avoid_overlaps", "bool", None, help="Refuse placements and relaxation steps that would make elements overlap "
              "[default: on, unless the exemplar's own elements overlap; then off, with a warning].", cli=False,
              section="extension"),
        Param("relax_every", "int", 16, low=1, help="Growth steps between two windowed relaxations.", cli=False, section="§5.5"),
        Param("periodic", "bool", False, cli="flag",
              help="Make a seamless repeat tile of a rectangular region (--size WxH): growth, matching, merging and "
                   "overlap tests wrap around its edges.", section="extension (issue 18)"),
    ),
)


def _polyline(a: Any, name: str) -> np.ndarray:
    try:
        p = np.asarray(a, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"{name}: must be a polyline of (x, y) points") from None
    if p.ndim != 2 or p.shape[1] != 2 or len(p) < 1:
        raise InputError(f"{name}: must be a polyline of (x, y) points, got shape {p.shape}")
    if not np.all(np.isfinite(p)):
        raise InputError(f"{name}: NaN or inf coordinate")
    return p


def grow(
    exemplar: Arrangement | Reference,
    region: Region | Any = None,
    *,
    context: Arrangement | None = None,
    rng: int | np.random.Generator | None = None,
    progress: Callable[[int, int | None, str], None] | None = None,
    should_cancel: Callable[[], bool] | None = None,
    **params: Any,
) -> Arrangement:
    """Grow an arrangement from one seed, element by element, after a reference (§5).

    Parameters
    ----------
    exemplar : Arrangement or Reference
        The reference arrangement, or its analysis from :func:`analyze`.
    count : int, optional
        Stop at this many elements. Without it, growth fills ``region`` (or the spray
        area) until no seed can grow.
    region : Region, optional
        Elements lie wholly inside it (also positional: ``grow(exemplar, region)``).
    context : Arrangement, optional
        Fixed elements to grow around (issue 15): obstacles that are never overlapped
        (the region less their footprint). Not yet used as neighbourhood context.
    start : (x, y), optional
        The initial seed; by default the region's centre (the spray path's start with
        ``spray``, the origin otherwise).
    start_kind : str, optional
        Symbol id of the initial seed (§5.1: a seed may carry one); any kind by default.
    mode : {"fixed", "rotate", "flow"}
        §5.3: keep the reference orientation, rotate it to the best fit (Eq. 4), or turn
        its local x axis to the flow direction at the seed.
    flow : callable, optional
        ``flow(points (m, 2)) -> (m, 2)`` directions, e.g. :func:`strew.fields.flow_field`;
        required by ``mode="flow"``.
    boundary : iterable of (k, 2) float, optional
        Boundary strokes: no edge of the growth crosses them (Fig. 1f).
    spray : (k, 2) float, optional
        Spray path: only seeds within ``spray_radius`` of it grow (Fig. 1c).
    spray_radius : float, optional
        Required with ``spray``.
    priority : mapping of kind name to float, optional
        §5.1: a seed grows only when no seed of higher priority lies within ``5 * l``
        (``l`` the mean reference edge length). Kinds default to 0; seeds without a
        symbol id take the lowest priority. Without it, kinds of different sizes are
        ranked larger first (:func:`size_priority`), unless they lie apart in bands or
        patches (fixed and rotate modes, :func:`strew.grow._analysis.default_priority`);
        ``{}`` turns that off.
    jitter_scale : float
        Relative scale noise: each scale is multiplied by ``1 + U(-s, s)`` (§3).
    jitter_rotation : float
        Rotation noise in radians: ``U(-r, r)`` is added (§3).
    jitter_color : float
        Colour noise: hex fill colours are multiplied by ``1 + U(-c, c)`` (§3); the
        result is the ``color`` column.
    relax : bool
        Windowed least-squares relaxation (§5.5), on by default.
    flips : iterable of (i, j)
        Edges of the exemplar's connectivity to flip first (exemplar indices).
    connectivity : bool
        Store the grown connectivity as the document entry ``connectivity``
        (``{"count": n, "edges": [[i, j], ...]}``).
    avoid_overlaps : bool, optional
        Refuse placements and relaxation steps that would make elements overlap (an
        extension: Ijiri's growth has none). By default on, unless the exemplar's own
        elements overlap: then every copy of a neighbourhood would collide, so it is
        off and a :class:`~strew._feedback.ResultWarning` says so.
    relax_every : int
        Growth steps between two windowed relaxations.
    periodic : bool
        Grow a seamless repeat tile of the rectangular ``region`` (issue 18; not in the
        paper): the growth lives on the torus, its seeds wrap around the tile's edges
        and meet the elements grown from the other side there (Fig. 6b merges them), and
        the output keeps each element once at its canonical place with
        ``meta["periodic"]`` (:mod:`strew._periodic`). A lattice exemplar
        (:func:`lattice_periods`) repeats exactly only in a multiple of its periods: in
        another tile (fixed mode) it is grown in the nearest multiple and its centres
        are moved by at most :data:`MAX_STRETCH` to fill the tile, where that leaves no
        overlap; otherwise its rows meet at the tile's edges with a gap or
        dislocations. Either way a :class:`~strew._feedback.ResultWarning` names the
        sizes that repeat it unchanged. Not with ``context`` or ``spray``.
    rng : int, Generator or None
        Ties between equally good references and the jitter draw from it. Recorded in
        ``meta`` (``seed`` or ``rng_state``) with every parameter (:data:`SPEC`).
    progress, should_cancel
        See :mod:`strew._progress`.
    **params
        ``count`` ... ``relax_every`` above, keyword only, checked against :data:`SPEC`
        first (old name ``flip`` is accepted for ``flips``).

    Returns
    -------
    Arrangement
        The grown elements with columns ``sub_id`` (the exemplar element each copies)
        and, when colours vary or the exemplar has one, ``color``.

    Examples
    --------
    >>> from strew.grow._exemplars import hex_exemplar
    >>> out = grow(hex_exemplar(), count=50, rng=1)
    >>> len(out)
    50
    """
    prm = SPEC.validate(params, aliases={"flip": "flips"})
    gen, seed = seed_record(rng)
    region = as_region(region)
    ctx = check_context(context)
    free = free_region(region, ctx)
    if is_empty(free):
        ex = exemplar.exemplar if isinstance(exemplar, Reference) else exemplar
        arr = empty_result(ex.shapes if isinstance(ex, Arrangement) else {}, region,
                           "the region is empty" if ctx is None else "the context covers the region")
    else:
        src = exemplar.exemplar if isinstance(exemplar, Reference) else exemplar
        if prm["avoid_overlaps"] is None:  # resolved here, and recorded so in meta
            prm["avoid_overlaps"] = not (isinstance(src, Arrangement) and _overlapping_exemplar(src))
        if prm["periodic"] and ctx is not None:
            raise InputError("periodic: a repeat tile cannot grow around context elements (context)")
        arr = _grow(exemplar, free, gen, progress, should_cancel, **prm)
        if free is not region:
            arr = arr.replace(region=region)
        _say_if_short(arr, prm)
    if prm["periodic"]:
        from .._periodic import frame_of_region, mark

        arr = mark(arr, frame_of_region(region))
    src = exemplar.exemplar if isinstance(exemplar, Reference) else exemplar
    return stamp(arr, SPEC, src, prm, seed, region=region, context=ctx)


def _overlapping_exemplar(ex: Arrangement) -> bool:
    """Whether the exemplar's own elements overlap, so that its copies must too.

    Ijiri's growth has no overlap test (§5); strew refuses placements that overlap
    (``avoid_overlaps``). When the exemplar itself overlaps (a tessellation drawn with
    tiles that cover each other's edges, shapes with a stroke), every copy of a
    neighbourhood collides and growth stops at its seed with no word (issue 22 point 3:
    1 element of 100). Then grow as the paper does, without the test, and say so.
    """
    import warnings

    from ..metrics import overlaps
    from .._feedback import ResultWarning

    n = len(ex)
    if n < 2:
        return False
    pairs, areas = overlaps(ex)
    if len(pairs) == 0:
        return False
    geom_area = np.asarray([g.area for g in ex.geometry])
    smaller = np.minimum(geom_area[pairs[:, 0]], geom_area[pairs[:, 1]])
    real = int(np.count_nonzero(areas > 1e-3 * smaller))  # filled shapes that run into each other
    if real < max(1, n // 10):
        return False
    warnings.warn(
        f"grow: the exemplar's own elements overlap ({real} pairs), so every copy of its neighbourhoods would "
        "overlap too; growing without the overlap test, as the paper does (avoid_overlaps=False)",
        ResultWarning,
        stacklevel=4,
    )
    return True


def lattice_periods(ref: Reference, tol: float = 0.02) -> tuple[float, float] | None:
    """The x and y periods of a lattice exemplar, or None when it is not one.

    The exemplar is a lattice when its 1-ring offsets take at most 12 values (each
    within ``tol`` mean edge lengths); the periods are the shortest integer
    combinations of the two shortest independent offsets along x and along y.

    Returns
    -------
    (px, py) float, or None
    """
    r = ref.ring_arrays()
    n = r["n"]
    if len(n) == 0 or int(n.sum()) == 0:
        return None
    vecs = np.concatenate([r["rel"][a, : n[a]] for a in range(len(n))])
    eps = tol * ref.mean_edge
    reps: list[np.ndarray] = []
    for v in vecs:
        if not any(abs(v[0] - c[0]) <= eps and abs(v[1] - c[1]) <= eps for c in reps):
            reps.append(v)
            if len(reps) > 12:
                return None
    reps.sort(key=lambda v: float(np.hypot(*v)))
    b1 = reps[0]
    b2 = next((v for v in reps[1:] if abs(b1[0] * v[1] - b1[1] * v[0]) > 0.1 * np.hypot(*b1) * np.hypot(*v)), None)
    if b2 is None:
        return None
    k = np.arange(-6, 7)
    c = (k[:, None, None] * b1 + k[None, :, None] * b2).reshape(-1, 2)
    along_x = c[(np.abs(c[:, 1]) <= eps) & (c[:, 0] > eps), 0]
    along_y = c[(np.abs(c[:, 0]) <= eps) & (c[:, 1] > eps), 1]
    if len(along_x) == 0 or len(along_y) == 0:
        return None
    return float(along_x.min()), float(along_y.min())


def _lattice_snaps(ref: Reference, tile: Sequence[float]) -> list[tuple[float, float, float, float]]:
    """Tiles that a lattice exemplar's periods divide, to grow it in instead of ``tile``.

    The multiples of the periods just below and just above the tile on each axis, within
    :data:`MAX_STRETCH`, the least moved first (at most three). Empty when the exemplar
    is not a lattice (:func:`lattice_periods`) or its periods divide the tile already.
    """
    per = lattice_periods(ref)
    if per is None:
        return []
    x0, y0, w, h = (float(v) for v in tile)
    if all(abs(v / q - round(v / q)) <= 0.02 for v, q in zip((w, h), per)):
        return []
    # per axis the multiples just below and just above; a stretch of more than
    # MAX_STRETCH would change the pattern more than a seam does
    axes = []
    for v, q in zip((w, h), per):
        m = {q * max(1, math.floor(v / q + 0.02)), q * math.ceil(v / q - 0.02)}
        axes.append([c for c in m if abs(v / c - 1) <= MAX_STRETCH])
    out = [(x0, y0, nw, nh) for nw in axes[0] for nh in axes[1]]
    # the least moved first; at equal moves, spreading (no new contacts) before squeezing
    out.sort(key=lambda t: (round(max(abs(w / t[2] - 1), abs(h / t[3] - 1)), 9), t[2] + t[3]))
    return out[:3]


def _grow_snapped(ref: Reference, params: GrowParams, snap: tuple[float, float, float, float], per: tuple[float, float], **kw: Any) -> Arrangement | None:
    """Grow a lattice in ``snap`` (a multiple of its periods) and stretch the positions
    to the asked tile; None when that made an overlap (then grow in the tile as asked).

    Not in the paper (issue 18). A lattice repeats exactly only in a multiple of its
    periods; grown in another tile its rows meet at the tile's edges with a gap or a
    dislocation (scales_hex in 200 x 150: a visible stripe one third of a row high).
    The lattice is grown in a multiple of its periods and its centres are moved by the
    ratio of the sizes (scales_hex in 200 x 150: grown in 200 x 155.9, rows 3.8% closer),
    if that leaves no overlap, and a ResultWarning says so with the sizes that need no
    stretch.
    """
    import dataclasses
    import warnings

    from .._feedback import ResultWarning
    from .._periodic import mark
    from ..metrics import wrap_overlaps

    x0, y0, w, h = params.tile  # type: ignore[misc]
    _, _, nw, nh = snap
    if params.start is not None and not (x0 < params.start[0] < x0 + nw and y0 < params.start[1] < y0 + nh):
        return None
    sub = dataclasses.replace(params, tile=snap, region=Region.rectangle(nw, nh, x0, y0))
    try:
        arr = grow_reference(ref, sub, **kw)
    except InputError:
        return None  # the snapped tile is too small for the exemplar's neighbourhoods
    fx, fy = w / nw, h / nh
    arr = arr.replace(x=x0 + (arr.x - x0) * fx, y=y0 + (arr.y - y0) * fy, region=params.region)
    if params.avoid_overlaps:
        wo = wrap_overlaps(mark(arr, params.tile))
        if wo["inside"] or wo["across"]:
            return None
    lo = [max(1, math.floor(v / q + 0.02)) * q for v, q in zip((w, h), per)]
    up = [math.ceil(v / q - 0.02) * q for v, q in zip((w, h), per)]
    warnings.warn(
        f"grow: the exemplar is a lattice with periods {per[0]:.4g} x {per[1]:.4g}, which do not divide a {w:g} x {h:g} "
        f"tile: grew it in {nw:.6g} x {nh:.6g} and moved its centres by a factor {fx:.4g} x {fy:.4g} to fill the tile; "
        f"a tile of {lo[0]:.6g} x {lo[1]:.6g} or {up[0]:.6g} x {up[1]:.6g} would repeat it unstretched",
        ResultWarning,
        stacklevel=4,
    )
    return arr


def _warn_lattice_misfit(ref: Reference, tile: Sequence[float]) -> None:
    """Say when a lattice exemplar's periods do not divide the repeat tile and it could
    not be grown in a multiple (:func:`_grow_snapped`): its rows meet at the tile's edges
    with a gap or dislocations; the warning names the nearest tile that fits."""
    import warnings

    from .._feedback import ResultWarning

    per = lattice_periods(ref)
    if per is None:
        return
    w, h = float(tile[2]), float(tile[3])
    if all(abs(v / p - round(v / p)) <= 0.02 for v, p in zip((w, h), per)):
        return
    near = [max(1, round(v / p)) * p for v, p in zip((w, h), per)]
    warnings.warn(
        f"grow: the exemplar is a lattice with periods {per[0]:.4g} x {per[1]:.4g}; a {w:g} x {h:g} tile is not a "
        f"multiple of them, so its rows meet at the tile's edges with a gap or dislocations; a tile of {near[0]:.6g} x {near[1]:.6g} "
        "would repeat it exactly",
        ResultWarning,
        stacklevel=4,
    )


def _say_if_short(arr: Arrangement, prm: Mapping[str, Any]) -> None:
    """Warn when growth stopped well short of ``count`` (issue 22 point 3)."""
    from .._feedback import warn_shortfall

    if prm.get("count") is None:
        return
    where = []
    if prm.get("boundary"):
        where.append("boundary strokes")
    if prm.get("spray") is not None:
        where.append(f"the spray path (spray_radius {prm.get('spray_radius')})")
    if where:
        reason = f"the growth front found no more room inside {' and '.join(where)}; widen them or ask for fewer"
    elif len(arr) <= 1:
        reason = ("no neighbour of the seed could be placed: the exemplar needs elements with Delaunay neighbours "
                  "(see its connectivity with strew grow --connectivity), at least two of them"
                  + (", whose copies do not overlap each other (avoid_overlaps=False lets them)" if prm.get("avoid_overlaps") else ""))
    else:
        reason = ("the growth front ran out of places where a copy of an exemplar neighbourhood fits "
                  "(a region too small, or an exemplar whose copies collide); give a larger region or ask for fewer")
    warn_shortfall("grow", len(arr), int(prm["count"]), reason, stacklevel=4)


def _grow(
    exemplar: Arrangement | Reference,
    region: Region | None,
    rng: np.random.Generator,
    progress: Callable[[int, int | None, str], None] | None,
    should_cancel: Callable[[], bool] | None,
    *,
    count: int | None,
    start: tuple[float, float] | None,
    start_kind: str | None,
    mode: str,
    flow: Callable[[np.ndarray], np.ndarray] | None,
    boundary: Iterable[np.ndarray] | None,
    spray: Any,
    spray_radius: float | None,
    priority: Mapping[str, float] | None,
    jitter_scale: float,
    jitter_rotation: float,
    jitter_color: float,
    relax: bool,
    flips: Iterable[tuple[int, int]],
    connectivity: bool,
    avoid_overlaps: bool,
    relax_every: int,
    periodic: bool = False,
) -> Arrangement:
    """The growth itself (§5) on checked arguments; see :func:`grow`."""
    if mode not in MODES:
        raise InputError(f"mode: unknown mode {mode!r}; use one of {', '.join(MODES)}")
    if isinstance(exemplar, Reference):
        ref = exemplar
        for i, j in flips:
            ref = flip_edge(ref, int(i), int(j))
    elif isinstance(exemplar, Arrangement):
        from .._limits import check_kinds

        check_kinds(len(exemplar.kinds), "exemplar")  # the grower's closeness tables are per kind pair
        ref = analyze(exemplar, flips=flips, lattice_repairs=mode != "flow")
    else:
        raise InputError(f"exemplar: must be an Arrangement or a Reference, got {type(exemplar).__name__}")
    if count is not None:
        if isinstance(count, bool) or int(count) != count or count < 1:
            raise InputError(f"count: must be a positive integer, got {count!r}")
        count = int(count)
    if region is not None and not isinstance(region, Region):
        raise InputError(f"region: must be a Region, got {type(region).__name__}")
    if mode == "flow" and flow is None:
        raise InputError("mode: 'flow' needs a flow field (flow=..., the CLI's --flow STROKES)")
    if flow is not None and not callable(flow):
        raise InputError("flow: must be callable, e.g. strew.fields.flow_field(strokes)")
    spray_arr = None
    if spray is not None:
        spray_arr = _polyline(spray, "spray")
        if spray_radius is None or not (np.isfinite(spray_radius) and spray_radius > 0):
            raise InputError(f"spray_radius: must be a positive number with spray, got {spray_radius!r}")
    elif spray_radius is not None:
        raise InputError("spray_radius: given without spray")
    bounds = [_polyline(b, f"boundary[{i}]") for i, b in enumerate(boundary or [])]
    tile = None
    if periodic:
        from .._periodic import frame_of_region

        if region is None:
            raise InputError("periodic: a repeat tile needs a rectangular region (Region.rectangle, --size WxH on the CLI)")
        if spray_arr is not None:
            raise InputError("periodic: the spray tool paints a path, not a repeat tile; leave out spray or periodic")
        tile = frame_of_region(region)
    if count is None and region is None and spray_arr is None:
        raise InputError("region: give count, or a region to fill (or a spray path)")
    from .._limits import check_work, element_area  # refuse work beyond the limits (issue 17)

    check_work("count" if count is not None else "region", count=count, region=region, per_element=element_area(ref.exemplar))
    kinds = ref.exemplar.kinds
    # hubs first, then their satellites, for clustered exemplars (:mod:`._clusters`), unless
    # the user sets priorities or edits the connectivity
    # (not on a torus: :mod:`._clusters` places whole clusters in the plane)
    clusters = priority is None and not isinstance(exemplar, Reference) and not list(flips) and tile is None
    if priority is None:
        # larger kinds first (§5.1), unless the kinds lie apart in bands or patches
        # (:func:`default_priority`; flow mode keeps size_priority as it was)
        priority = size_priority(ref.exemplar) if mode == "flow" else default_priority(ref, several=mode == "fixed")
    prio: dict[str, float] = {}
    for name, v in dict(priority or {}).items():
        if name not in kinds:
            raise InputError(f"priority: unknown kind {name!r} (exemplar kinds: {', '.join(kinds)})")
        try:
            fv = float(v)
        except (TypeError, ValueError):
            raise InputError(f"priority {name}: must be a number, got {v!r}") from None
        if not np.isfinite(fv):
            raise InputError(f"priority {name}: must be finite")
        prio[name] = fv
    for name, v in (("jitter_scale", jitter_scale), ("jitter_rotation", jitter_rotation), ("jitter_color", jitter_color)):
        if not (np.isfinite(v) and v >= 0):
            raise InputError(f"{name}: must be a non-negative number, got {v!r}")
    if jitter_scale >= 1:
        raise InputError(f"jitter_scale: must be below 1 (a scale must stay positive), got {jitter_scale!r}")
    if start is not None:
        start = tuple(float(v) for v in start)  # type: ignore[assignment]
        if len(start) != 2 or not all(np.isfinite(start)):
            raise InputError(f"start: expected a finite point x,y, got {start!r}")
    start_index = -1
    if start_kind is not None:
        if start_kind not in kinds:
            raise InputError(f"start_kind: unknown kind {start_kind!r} (exemplar kinds: {', '.join(kinds)})")
        start_index = kinds.index(start_kind)
    if int(relax_every) < 1:
        raise InputError(f"relax_every: must be at least 1, got {relax_every!r}")
    params = GrowParams(
        count=count,
        region=region,
        start=start,  # type: ignore[arg-type]
        start_kind=start_index,
        mode=mode,
        flow=flow,
        boundary=bounds,
        spray=spray_arr,
        spray_radius=float(spray_radius) if spray_radius is not None else None,
        priority=prio,
        jitter_scale=float(jitter_scale),
        jitter_rotation=float(jitter_rotation),
        jitter_color=float(jitter_color),
        relax=bool(relax),
        relax_every=int(relax_every),
        avoid_overlaps=bool(avoid_overlaps),
        connectivity=bool(connectivity),
        clusters=clusters,
        tile=tile,
    )
    meta = {"method": "grow"}
    if tile is not None and mode == "fixed" and jitter_scale == 0 and jitter_rotation == 0:
        snaps = _lattice_snaps(ref, tile)
        state = rng.bit_generator.state
        for snap in snaps:
            out = _grow_snapped(ref, params, snap, lattice_periods(ref),  # type: ignore[arg-type]
                                rng=rng, progress=progress, should_cancel=should_cancel, meta=meta)
            if out is not None:
                return out
            rng.bit_generator.state = state
        _warn_lattice_misfit(ref, tile)
    return grow_reference(ref, params, rng=rng, progress=progress, should_cancel=should_cancel, meta=meta)
