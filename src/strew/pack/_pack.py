"""``strew.pack.pack``: dense non-periodic aggregates (Sakurai & Miyata).

Two methods over the same exclusive regions (§3.1) and exact placement tests:

``"naive"`` (§3.2)
    Dart throwing: random position, rotation and scale; cancel on collision; stop after
    ``max_failures`` consecutive cancellations (10,000 in the paper's §3.3).
``"fill-gap"`` (§4)
    Step 1 (§4.1): sparse placement at Poisson-disk points whose circles circumscribe
    the exclusive regions, so that no collision test is needed (only containment).
    Step 2 (§4.2): rounds of P = 100 candidates drawn from the distance field to the
    placed regions and the boundary with probability ``d**16``; stop after 200
    consecutive cancellations. Both steps run in the compiled engine of :mod:`._fit`
    (exact, robust polygon tests; no shapely in the loop), Step 2 with extensions of
    §4.2: several poses per candidate, suppression of failed spots, candidates kept
    fresh within a round, the kinds tried in order of their lag behind the requested
    proportions (``kind_choice="fit"``, default; the paper cycles), and optionally the
    largest scale that fits the gap first (``scale_choice="fit"``).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from typing import Any

import numpy as np
import shapely

from .._errors import InputError
from .._progress import Reporter
from .._method import MethodSpec, Param, as_region, as_shapes, check_context, empty_result, free_region, is_empty, seed_record, stamp
from ..arrangement import Arrangement
from ..region import Region
from ..shape import Shape
from ._exclusive import ExclusiveRegion, build_exclusive_regions, element_origin
from ._field import DistanceField
from ._fit import NO_FIELD, RUNNING, FitEngine
from ._placer import Placer
from ._poisson import poisson_disk

__all__ = ["pack", "METHODS", "DEFAULTS", "SPEC"]

METHODS = ("fill-gap", "naive")

# Every constant of the method, with the paper's values.
DEFAULTS: dict[str, Any] = {
    "max_failures": {"fill-gap": 200, "naive": 10_000},  # §4.2 / §3.3
    "candidates": 100,  # P per round, §4
    "power": 16.0,  # alpha = d**n, §4.2
    "poisson_candidates": 30,  # Bridson's k for Step 1
    "naive_batch": 256,  # darts tested per bulk query (does not change the result's law)
    # extensions of §4.2 (see _fit): poses tried per candidate point, and the factor that
    # damps the field about a cancelled candidate (fits=1, suppress=1: the paper's rounds)
    "fits": 48,
    "suppress": 0.9,
    # extension of §4.2 (see _fit._kind_order): each candidate tries the kinds most behind
    # their requested shares first, keeping every share within this of its target
    "kind_choice": "fit",
    "tolerance": 0.05,
    # extension of §4.2: "random" draws scales uniformly in the range (§4.1); "fit" tries
    # the largest first at each candidate, so that big elements take big gaps and small
    # ones fill what is left
    "scale_choice": "random",
}

KIND_CHOICES = ("fit", "cycle")
SCALE_CHOICES = ("random", "fit")

# old keyword names -> current ones (none renamed so far)
_ALIASES: dict[str, str] = {}

SPEC = MethodSpec(
    name="pack",
    command="pack",
    entry="strew.pack:pack",
    paper="Sakurai & Miyata, Generating a Layout of Nonperiodic Aggregates",
    summary="Pack shapes densely and non-periodically into a region (fill-gap).",
    progress_message="pack",
    input=Param("shapes", "any", help="Element kinds: a Shape, a list or a mapping name -> Shape.", section="§3.1",
                parse="shape-files", metavar="SHAPE..."),
    params=(
        Param("method", "str", "fill-gap", choices=METHODS, help="Fill-gap (§4) or naive dart throwing (§3.2).", section="§3.2, §4"),
        Param("max_failures", "int", None, low=1, help="Stop after this many consecutive cancellations [default: 200 fill-gap, 10000 naive].",
              section="§3.3, §4.2", metavar="N"),
        Param("rotation", "any", (0.0, 2 * np.pi), unit="radians", help="Rotation range (lo, hi), or a mapping kind -> range ('*' for the rest).",
              flag="--rotate", cli="multiple", parse="per-kind-range-deg", metavar="[KIND=]A:B",
              cli_help="Rotation range in degrees [default: 0:360]; repeat with KIND= for one kind.", section="§3.2"),
        Param("scale", "any", (1.0, 1.0), help="Scale range (lo, hi), or a mapping kind -> range.", cli="multiple", parse="per-kind-range",
              metavar="[KIND=]A:B", cli_help="Scale range [default: 1:1]; KIND= for one kind.", section="§4.1"),
        Param("margin", "any", 0.0, unit="document units", help="Grow each exclusive region by this buffer (a number or kind -> number).",
              cli="multiple", parse="per-kind-number", metavar="[KIND=]M",
              cli_help="Grow each exclusive region by M (a buffer) [default: 0]; KIND= for one kind.", section="§3.1"),
        Param("exclusive", "any", None, help="Exclusive shapes in each element's local frame, matched to kinds by name.", parse="shapes-file",
              metavar="FILE", cli_help="SVG or JSON file of exclusive shapes, matched to kinds by name.", section="§3.1"),
        Param("weights", "any", None, help="Requested proportions of kinds (a list, or kind -> weight; '*' for the rest) [default: equal].",
              flag="--weight", cli="multiple", parse="kind-weights", metavar="KIND=W", section="§3.2"),
        Param("kind_choice", "str", DEFAULTS["kind_choice"], choices=KIND_CHOICES,
              help="Fill-gap: try the kinds most behind their proportions until one fits the gap, or cycle.", section="extension of §4.2 (cycle: §3.2)"),
        Param("scale_choice", "str", DEFAULTS["scale_choice"], choices=SCALE_CHOICES,
              help="Fill-gap: uniform scales in the range, or the largest that fits each gap first.", section="extension of §4.2"),
        Param("candidates", "int", DEFAULTS["candidates"], low=1, help="Fill-gap: candidates P per round.", section="§4"),
        Param("power", "float", DEFAULTS["power"], low=0, low_open=True, help="Fill-gap: exponent n of alpha = d**n.", section="§4.2"),
        Param("resolution", "float", None, low=0, low_open=True, unit="document units",
              help="Fill-gap: pixel side of the distance field [default: a sixth of the smallest element].", section="§4.2"),
        Param("sparse_candidates", "int", DEFAULTS["poisson_candidates"], low=1, help="Fill-gap Step 1: Bridson's trial points per active sample.",
              section="§4.1"),
        Param("fits", "int", None, low=1, help="Fill-gap Step 2: poses tried per candidate point [default: 48, 96 with scale_choice fit].",
              section="extension of §4.2"),
        Param("suppress", "float", DEFAULTS["suppress"], low=0, low_open=True, high=1,
              help="Fill-gap Step 2: field damping about a cancelled candidate (1: off).", section="extension of §4.2"),
        Param("tolerance", "float", DEFAULTS["tolerance"], low=0, high=1, low_open=True, high_open=True,
              help="Fill-gap with kind_choice fit: how far each kind's share may stray from its target.", section="extension of §4.2"),
        Param("periodic", "bool", False, cli="flag",
              help="Make a seamless repeat tile of a rectangular region (--size WxH): distances, free space and "
                   "overlap tests wrap around its edges.", section="extension (issue 18)"),
    ),
)

# Step 2 rounds per call of the compiled loop (between progress reports)
_ROUNDS_PER_TICK = 25


def _weights(weights: Any, kinds: list[str]) -> np.ndarray | None:
    if weights is None:
        return None
    if isinstance(weights, Mapping):
        unknown = [k for k in weights if k not in kinds and k != "*"]
        if unknown:
            raise InputError(f"weights: unknown kind {unknown[0]!r} (kinds: {', '.join(kinds)})")
        rest = weights.get("*", 0.0)  # '*': the weight of every kind not named
        w = [weights.get(k, rest) for k in kinds]
    else:
        w = list(weights)
        if len(w) != len(kinds):
            raise InputError(f"weights: {len(w)} given for {len(kinds)} kinds")
    try:
        arr = np.asarray(w, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"weights: must be numbers, got {weights!r}") from None
    if not np.all(np.isfinite(arr)) or np.any(arr < 0) or arr.sum() <= 0:
        raise InputError(f"weights: must be non-negative, finite and not all zero, got {arr.tolist()}")
    return arr / arr.sum()


def _positive_int(value: Any, name: str) -> int:
    try:
        v = int(value)
    except (TypeError, ValueError):
        raise InputError(f"{name}: must be an integer, got {value!r}") from None
    if v < 1 or v != value:
        raise InputError(f"{name}: must be a positive integer, got {value!r}")
    return v


# pixels of a distance field that runs Step 2's rounds as the paper's (see _fill_gap)
REF_PIXELS = 400_000
# the default field is coarsened above this many pixels (issue 19.6: was REF_PIXELS; a
# coarser field prunes fewer poses, so the cost per element grew with the region:
# exponent 1.24-1.39 from 10^4 to 10^5 elements, benchmarks/pack_scaling.py)
MAX_PIXELS = 4_000_000


def _default_cell(kinds: list[ExclusiveRegion], region: Region) -> float:
    """Pixel side of the distance field: a sixth of the smallest kind's size at its mean
    scale, coarsened so that the raster stays under about MAX_PIXELS pixels."""
    size = min(np.sqrt(k.area) * 0.5 * (k.scale[0] + k.scale[1]) for k in kinds)
    return float(max(size / 6.0, np.sqrt(region.area / MAX_PIXELS)))


def pack(
    shapes: Mapping[str, Shape] | Sequence[Shape] | Shape,
    region: Region | Any = None,
    *,
    context: Arrangement | None = None,
    rng: int | np.random.Generator | None = None,
    progress: Callable[[int, int | None, str], None] | None = None,
    should_cancel: Callable[[], bool] | None = None,
    **params: Any,
) -> Arrangement:
    """Pack elements densely and non-periodically into a region.

    Parameters
    ----------
    shapes : Shape, sequence of Shape or mapping of kind name -> Shape
        Element kinds: any polygons, concave, elongated or with holes.
    region : Region, shapely polygon, ``"WxH"`` or (W, H)
        The domain; elements lie wholly inside it (holes included). Required.
    context : Arrangement, optional
        Fixed elements to pack around (issue 15): they are obstacles, never
        overlapped, kept ``margin`` away like the boundary; they are not part of the
        result.
    method : {"fill-gap", "naive"}
        Fill-gap (§4) or naive dart throwing (§3.2).
    rotation : (lo, hi) or mapping of kind -> (lo, hi)
        Rotation range in radians (default the full turn). A mapping may use the key
        ``"*"`` for the kinds it does not name.
    scale : (lo, hi) or mapping of kind -> (lo, hi)
        Uniform scale range (positive; default 1).
    margin : float or mapping of kind -> float
        The exclusive region is the element (or its ``exclusive`` shape) grown by this
        buffer distance: gaps between elements are at least twice the margin, and
        elements keep the margin from the boundary. Negative values shrink it.
    exclusive : mapping of kind -> Shape, optional
        Exclusive shapes in each element's local coordinates (§3.1). An exclusive shape
        smaller than its element lets elements overlap.
    weights : sequence or mapping of kind -> float, optional
        The kinds' requested proportions (default equal). How they are met follows
        ``kind_choice``; naive dart throwing chooses kinds at random with these weights,
        or cyclically without them (§3.2).
    max_failures : int, optional
        Stop after this many consecutive cancellations; default 200 for fill-gap
        (§4.2) and 10,000 for naive (§3.3).
    candidates : int
        Fill-gap: points P tried per round (100, §4).
    power : float
        Fill-gap: exponent n of ``alpha = d**n`` (16, §4.2).
    resolution : float, optional
        Fill-gap: pixel side of the distance field; default a sixth of the smallest
        element's size (the raster only proposes candidates).
    sparse_candidates : int
        Fill-gap Step 1: Bridson's trial points per active Poisson-disk sample (30).
    fits : int, optional
        Fill-gap Step 2: random rotations and scales tried at each candidate point before
        it counts as a cancellation (an extension of §4.2; 1 draws one pose as the
        paper). Default 48, and 96 with ``scale_choice="fit"``, whose poses sweep the
        scale range from the top and so try fewer rotations at each scale.
    suppress : float in (0, 1]
        Fill-gap Step 2: factor applied to the distance field about a cancelled candidate,
        so that later rounds explore other gaps (0.9; an extension of §4.2; 1 turns it off).
    kind_choice : {"fit", "cycle"}
        Fill-gap Step 2: ``"fit"`` (default; an extension of §4.2) tries at each
        candidate point the kinds most behind their requested proportions first and
        moves on to the next kind when one does not fit the gap, so that a gap too small
        for one kind is filled by another; the proportions stay within ``tolerance`` of
        the requested ones (once there are more than about ``K / tolerance`` elements).
        ``"cycle"``: one kind per candidate, cyclically or drawn by ``weights`` (§3.2).
    scale_choice : {"random", "fit"}
        Fill-gap Step 2: ``"random"`` (default) draws each pose's scale uniformly in its
        kind's range (§4.1); ``"fit"`` (an extension of §4.2) tries the poses at each
        candidate from the largest scale down, so that the largest element that fits
        takes the gap and smaller ones fill what is left: denser, with scales skewed
        towards the top of the range.
    tolerance : float in (0, 1)
        Fill-gap with ``kind_choice="fit"``: how far each kind's proportion may stray
        from the requested one (0.05).
    periodic : bool
        Fill the torus of a rectangular region, a seamless repeat tile (issue 18; an
        extension: the paper's aggregates are non-periodic). Every method wraps around
        the tile's edges: Poisson-disk points, the distance field, candidate points and
        the collision tests, so that copies of the result laid side by side never
        overlap. The result keeps each element once, at its canonical position
        (:mod:`strew._periodic`, ``meta["periodic"] = [x0, y0, W, H]``). The tile must
        be at least two elements across (twice the largest circumscribed diameter of
        an exclusive region at its largest scale) on each side; ``context`` is refused.
    rng : int, Generator or None
        Recorded in ``meta`` (``seed``, or the Generator's ``rng_state`` before the run).
    progress, should_cancel : callables, optional
        See :mod:`strew._progress`.
    **params
        The parameters above from ``method`` on, keyword only; :data:`SPEC` declares
        them (type, default, range, paper section) and checks them first.

    Returns
    -------
    Arrangement
        The placed elements, with the domain as its region. ``meta`` holds the
        provenance (:func:`strew._method.stamp`: method, version, seed, every parameter
        resolved, input hash); ``meta["pack"]`` records the algorithm, the number of
        trials and why it stopped. It is empty when nothing
        fits (``meta["pack"]["stopped"]`` says so).

    Raises
    ------
    InputError
        Zero-area exclusive regions, inverted ranges, unknown methods or kinds; with
        ``periodic``, a region that is not a rectangle, a tile smaller than two
        elements, or a context.

    Examples
    --------
    >>> from strew import Shape, Region
    >>> arr = pack(Shape.rectangle(4, 1), Region.rectangle(20, 20), rng=1)
    >>> from strew.metrics import overlaps, outside
    >>> len(arr) > 20, len(overlaps(arr)[0]), len(outside(arr))
    (True, 0, 0)
    """
    prm = SPEC.validate(params, aliases=_ALIASES)
    # defaults that depend on other parameters, resolved here so that meta records them
    if prm["max_failures"] is None:
        prm["max_failures"] = DEFAULTS["max_failures"][prm["method"]]
    if prm["fits"] is None:
        prm["fits"] = DEFAULTS["fits"] * (2 if prm["scale_choice"] == "fit" else 1)
    gen, seed = seed_record(rng)
    lib = as_shapes(shapes)
    dom = as_region(region)
    if dom is None:
        raise InputError("region: give the region to fill (a Region, a polygon, 'WxH' or (W, H))")
    ctx = check_context(context)
    tile = None
    if prm["periodic"]:
        from .._periodic import frame_of_region

        tile = frame_of_region(dom)
        if ctx is not None and len(ctx):
            raise InputError("periodic: a repeat tile cannot be packed around a context (--around); give one or the other")
    free = free_region(dom, ctx)
    if is_empty(free):
        arr = empty_result(lib, dom, "the region is empty" if ctx is None else "the context covers the region")
        arr = arr.with_meta(pack={"algorithm": prm["method"], "stopped": arr.meta["stopped"], "trials": 0})
    else:
        arr = _pack_into(lib, free, gen=gen, progress=progress, should_cancel=should_cancel, **prm).replace(region=dom)
        arr = _say_if_large(arr, lib, prm["scale"], free)
    if tile is not None:
        from .._periodic import mark

        arr = mark(arr, tile)
    return stamp(arr, SPEC, lib, prm, seed, region=dom, context=ctx)


def _say_if_large(arr: Arrangement, lib: Mapping[str, Shape], scale: Any, region: Region) -> Arrangement:
    """Say so when few or no elements fit because the shapes are large (issue 22 point 3).

    A few elements: a :class:`~strew._feedback.ResultWarning`. None: the advice joins
    ``meta["pack"]["stopped"]``, which the CLI's error gives.
    """
    from .._feedback import large_shapes_advice, warn_large_shapes

    def hi(kind: str) -> float:
        rng = scale.get(kind, scale.get("*", (1.0, 1.0))) if isinstance(scale, Mapping) else scale
        try:
            return float(np.max(np.atleast_1d(np.asarray(rng, dtype=float))))
        except (TypeError, ValueError):
            return 1.0

    areas = {k: float(s.area) * hi(k) ** 2 for k, s in lib.items()}
    if len(arr) == 0:
        advice = large_shapes_advice(areas, region)
        info = dict(arr.meta.get("pack") or {})
        if advice and info.get("stopped"):
            return arr.with_meta(pack={**info, "stopped": f"{info['stopped']}; {advice}"})
        return arr
    warn_large_shapes("pack", len(arr), areas, region, stacklevel=4)
    return arr


def _pack_into(
    shapes: dict[str, Shape],
    dom: Region,
    *,
    method: str,
    rotation: Any,
    scale: Any,
    margin: Any,
    exclusive: Mapping[str, Shape] | None,
    weights: Sequence[float] | Mapping[str, float] | None,
    max_failures: int | None,
    candidates: int,
    power: float,
    resolution: float | None,
    sparse_candidates: int,
    fits: int | None,
    suppress: float,
    kind_choice: str,
    scale_choice: str,
    tolerance: float,
    gen: np.random.Generator,
    progress: Callable[[int, int | None, str], None] | None,
    should_cancel: Callable[[], bool] | None,
    periodic: bool = False,
) -> Arrangement:
    """The packing itself (§3, §4), on checked arguments; see :func:`pack`."""
    lib = shapes
    if method not in METHODS:
        raise InputError(f"method: unknown method {method!r}; use one of {', '.join(METHODS)}")
    kinds = build_exclusive_regions(lib, rotation=rotation, scale=scale, margin=margin, exclusive=exclusive)
    w = _weights(weights, list(lib))
    limit = _positive_int(DEFAULTS["max_failures"][method] if max_failures is None else max_failures, "max_failures")
    p_count = _positive_int(candidates, "candidates")
    from .._limits import check_work  # refuse work beyond the limits (issue 17)

    check_work("candidates", extra_bytes=256.0 * p_count)  # each round's candidate arrays
    check_work("max_failures", trials=limit)
    check_work("region (with these shapes and scale)", region=dom, per_element=min(k.area * k.scale[0] ** 2 for k in kinds))
    k_sparse = _positive_int(sparse_candidates, "sparse_candidates")
    try:
        power = float(power)
    except (TypeError, ValueError):
        raise InputError(f"power: must be a number, got {power!r}") from None
    if not (np.isfinite(power) and power > 0):
        raise InputError(f"power: must be positive, got {power}")
    if resolution is not None:
        try:
            resolution = float(resolution)
        except (TypeError, ValueError):
            raise InputError(f"resolution: must be a number, got {resolution!r}") from None
        if not (np.isfinite(resolution) and resolution > 0):
            raise InputError(f"resolution: must be positive, got {resolution}")
    if fits is None:
        fits = DEFAULTS["fits"] * (2 if scale_choice == "fit" else 1)
    n_fits = _positive_int(fits, "fits")
    try:
        suppress = float(suppress)
    except (TypeError, ValueError):
        raise InputError(f"suppress: must be a number, got {suppress!r}") from None
    if not (0 < suppress <= 1):
        raise InputError(f"suppress: must be in (0, 1], got {suppress}")
    if kind_choice not in KIND_CHOICES:
        raise InputError(f"kind_choice: unknown choice {kind_choice!r}; use one of {', '.join(KIND_CHOICES)}")
    if scale_choice not in SCALE_CHOICES:
        raise InputError(f"scale_choice: unknown choice {scale_choice!r}; use one of {', '.join(SCALE_CHOICES)}")
    try:
        tolerance = float(tolerance)
    except (TypeError, ValueError):
        raise InputError(f"tolerance: must be a number, got {tolerance!r}") from None
    if not (0 < tolerance < 1):
        raise InputError(f"tolerance: must be in (0, 1), got {tolerance}")
    tile = _tile(dom, kinds) if periodic else None
    rep = Reporter(progress, should_cancel, message=f"pack ({method})")
    placer = Placer(kinds, dom, w, limit, periodic=tile)
    info: dict[str, Any] = {"algorithm": method, "max_failures": limit}
    if all(k.area * k.scale[0] ** 2 > dom.area for k in kinds):
        info["stopped"] = "no shape fits: the region is smaller than every shape"
    elif method == "naive":
        info["stopped"] = _naive(placer, dom, gen, rep)
    else:
        cell = _default_cell(kinds, dom) if resolution is None else resolution
        x0, y0, x1, y1 = dom.bounds
        if (x1 - x0) * (y1 - y0) / cell**2 > 2e7:
            raise InputError(f"resolution: {cell:g} is too fine for a region of {x1 - x0:g} x {y1 - y0:g} (over 20 million pixels)")
        info.update(candidates=p_count, power=power, resolution=cell, fits=n_fits, suppress=suppress, kind_choice=kind_choice,
                    scale_choice=scale_choice)
        target = None
        if kind_choice == "fit":
            target = np.full(len(kinds), 1.0 / len(kinds)) if w is None else w
            info["tolerance"] = tolerance
        info["stopped"] = _fill_gap(placer, dom, gen, rep, p_count, power, cell, k_sparse, n_fits, suppress, info, target, tolerance,
                                    scale_choice == "fit", tile)
    if len(placer) == 0 and "no shape fits" not in info["stopped"]:
        info["stopped"] = f"no shape fits in the region ({info['stopped']})"
    info["trials"] = placer.trials
    rep.done(len(placer))
    return _arrangement(lib, kinds, placer, dom, info)


def _tile(dom: Region, kinds: list[ExclusiveRegion]) -> tuple[float, float, float, float]:
    """The repeat tile of a periodic pack (issue 18): the region's rectangle, at least two
    elements across on each side.

    "Two elements" is twice the largest circumscribed diameter (§4.1's circle O) of an
    exclusive region at its largest scale: then no element meets its own wrapped image,
    and every element meets the images of the others through the 3 x 3 block of tiles
    around it only.
    """
    from .._periodic import frame_of_region

    tile = frame_of_region(dom)
    big = max(kinds, key=lambda k: k.radius * k.scale[1])
    diameter = 2 * big.radius * big.scale[1]
    if min(tile[2], tile[3]) < 2 * diameter:
        raise InputError(
            f"periodic: the tile {tile[2]:g} x {tile[3]:g} is smaller than two elements across: kind {big.name!r} "
            f"spans {diameter:g} (its exclusive region's circumscribed diameter at scale {big.scale[1]:g}); "
            f"make each side at least {2 * diameter:g}, or the shapes smaller")
    return tile


def _arrangement(lib: dict[str, Shape], kinds: list[ExclusiveRegion], placer: Placer, dom: Region, info: dict) -> Arrangement:
    n = len(placer)
    kind = np.asarray(placer.kind, dtype=np.int32)
    xy = np.asarray(placer.xy, dtype=float).reshape(n, 2)
    rot = np.asarray(placer.rotation, dtype=float)
    sc = np.asarray(placer.scale, dtype=float)
    origin = np.zeros((n, 2))
    for k, ex in enumerate(kinds):
        idx = np.flatnonzero(kind == k)
        if len(idx):
            origin[idx] = element_origin(ex.centre, xy[idx], rot[idx], sc[idx])
    return Arrangement(lib, kind, origin[:, 0], origin[:, 1], rot, sc, region=dom, meta={"method": "pack", "pack": info})


def _uniform_in_region(dom: Region, gen: np.random.Generator, m: int) -> np.ndarray:
    """(m', 2) points uniform in the domain (darts from its bounding box that land inside)."""
    x0, y0, x1, y1 = dom.bounds
    pts = np.c_[x0 + gen.random(m) * (x1 - x0), y0 + gen.random(m) * (y1 - y0)]
    return pts[dom.contains(pts)]


def _naive(placer: Placer, dom: Region, gen: np.random.Generator, rep: Reporter) -> str:
    """Naive dart throwing (§3.2): (1) random placement, (2) exact collision test,
    (3) cancel on overlap; stop after ``max_failures`` consecutive cancellations."""
    batch = DEFAULTS["naive_batch"]
    while not placer.done:
        xy = _uniform_in_region(dom, gen, batch)
        m = len(xy)
        u_rot, u_sc = gen.random(m), gen.random(m)
        placer.try_batch(xy, u_rot, u_sc, placer.draw_kinds(gen, m))
        rep.tick(len(placer), message=f"{len(placer)} placed, {placer.consecutive} consecutive cancellations")
    return f"{placer.max_failures} consecutive cancellations"


def _fill_gap(
    placer: Placer,
    dom: Region,
    gen: np.random.Generator,
    rep: Reporter,
    p_count: int,
    power: float,
    cell: float,
    k_sparse: int,
    fits: int,
    suppress: float,
    info: dict,
    target: np.ndarray | None = None,
    tolerance: float = 0.05,
    scale_fit: bool = False,
    tile: tuple[float, float, float, float] | None = None,
) -> str:
    kinds = placer.kinds
    # Step 1 (§4.1): Poisson-disk points with the circumscribed circle O of the largest
    # exclusive region at its largest scale, in the domain shrunk by that radius, so that
    # regions neither overlap nor leave the domain. On a repeat tile (issue 18) the
    # points are sampled on its torus and nothing is shrunk: the torus has no boundary.
    radius = max(k.radius * k.scale[1] for k in kinds)
    inner = dom.geometry if tile is not None else shapely.buffer(dom.geometry, -radius)
    engine = FitEngine(kinds, dom.geometry, placer.weights, placer.next_kind, periodic=tile)
    sparse = 0
    if not inner.is_empty and inner.area > 0:
        pts = poisson_disk(inner, 2 * radius, candidates=k_sparse, rng=gen, periodic=tile is not None)
        m = len(pts)
        # compiled: exact containment tests, no collision test (§4.1); Step 1 places no
        # cancellations on purpose, only Step 2 counts them
        sparse = engine.place_sparse(pts, gen.random(m), gen.random(m), placer.draw_kinds(gen, m))
        placer.trials += m
    info["sparse"] = sparse
    rep.tick(len(engine), message=f"step 1: {sparse} placed", force=True)
    field = DistanceField(dom, cell, segments=engine.segments(), periodic=tile)
    # Step 2 (§4.2): rounds of P candidates from the normalised distance field, in a
    # compiled loop (see _fit for the fit, suppression and fresh-candidate extensions).
    # suppression disk: a quarter of the smallest element's circumscribed radius, at least a pixel
    sup_r = max(0.25 * min(k.radius * k.scale[0] for k in kinds), cell)
    # gap-fitting kind choice: no share may run ahead of its target by more than
    # tolerance / (K - 1), so that none falls behind by more than the tolerance
    k_tol = tolerance / max(int(np.count_nonzero(target)) - 1, 1) if target is not None else 0.0
    # Departure from §4.2 (issue 19.6): every round draws Q from the whole field, a cost
    # that grows with its area, while it tries P candidates; with a fixed P the number
    # of rounds grows with the area too, so the cost went as area**2. A field of k x
    # REF_PIXELS pixels tries k P candidates per round, as k fields of REF_PIXELS side by
    # side would, so that the rounds follow n / area and the cost n (10^4 to 10^5
    # elements: exponent 0.99 at a fixed cell). The stop stays at max_failures
    # consecutive cancellations (scaled by k, the trials per element doubled at 3x the
    # area; unscaled, the density stays within 1% of a small field's). Fields up to
    # REF_PIXELS are unchanged bit for bit.
    k_area = max(1.0, field.d.size / REF_PIXELS)
    p_round = int(round(p_count * k_area))
    status = RUNNING
    while status == RUNNING:
        status = engine.run(gen, field, _ROUNDS_PER_TICK, placer.max_failures, p_round, power, fits, suppress, sup_r,
                            target, k_tol, scale_fit)
        rep.tick(len(engine), message=f"{len(engine)} placed, {engine.consecutive} consecutive cancellations")
    placer.trials += engine.trials
    placer.consecutive = engine.consecutive
    info["poses"] = engine.poses
    info["rounds"] = engine.rounds
    _add_placed(placer, engine)
    if status == NO_FIELD:
        return "the distance field has no free pixel left"
    return f"{placer.max_failures} consecutive cancellations"


def _add_placed(placer: Placer, engine: FitEngine) -> None:
    """Copy the compiled engine's elements (kind and pose) into ``placer``.

    The compiled tests are exact and cancel every case too close to call (see
    :data:`._fit.TOL`), so no shapely re-check follows; the tests in ``tests/pack``
    check the results against shapely.
    """
    n = len(engine)
    pose = engine.pose[:n]
    placer.kind.extend(int(k) for k in engine.pkind[:n])
    placer.xy.extend(map(tuple, pose[:, :2].tolist()))
    placer.rotation.extend(pose[:, 2].tolist())
    placer.scale.extend(pose[:, 3].tolist())
