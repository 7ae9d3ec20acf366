"""Example-based growth from one seed (Ijiri, Měch, Igarashi, Miller, Eurographics 2008).

:func:`analyze` builds the connectivity of a reference arrangement (§4);
:func:`grow` synthesises a larger arrangement from it by local growth (§5) with three
rotation modes, the spray, flow-field and boundary tools, per-element variation and a
least-squares relaxation. :func:`flip_edge` edits the connectivity (Fig. 3) and
:func:`relax_positions` is the relaxation of Eq. 5 / Eq. 6 on its own.
:class:`SprayGrowth` is the spray tool as one growth that follows a stroke (§3, §5.1).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping, Sequence
from typing import Any

import numpy as np

from .._errors import InputError
from ..arrangement import Arrangement
from ..region import Region
from ._analysis import Reference, analyze, delaunay_edges, flip_edge, size_priority
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
    "MODES",
]

MODES = ("fixed", "rotate", "flow")


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
    *,
    count: int | None = None,
    region: Region | None = None,
    start: tuple[float, float] | None = None,
    start_kind: str | None = None,
    mode: str = "fixed",
    flow: Callable[[np.ndarray], np.ndarray] | None = None,
    boundary: Iterable[np.ndarray] | None = None,
    spray: np.ndarray | Sequence[Sequence[float]] | None = None,
    spray_radius: float | None = None,
    priority: Mapping[str, float] | None = None,
    jitter_scale: float = 0.0,
    jitter_rotation: float = 0.0,
    jitter_color: float = 0.0,
    relax: bool = True,
    flips: Iterable[tuple[int, int]] = (),
    connectivity: bool = False,
    avoid_overlaps: bool = True,
    relax_every: int = 16,
    rng: int | np.random.Generator | None = None,
    progress: Callable[[int, int | None, str], None] | None = None,
    should_cancel: Callable[[], bool] | None = None,
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
        Elements lie wholly inside it.
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
        ranked larger first (:func:`size_priority`); ``{}`` turns that off.
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
    avoid_overlaps : bool
        Refuse placements and relaxation steps that would make elements overlap.
    relax_every : int
        Growth steps between two windowed relaxations.
    rng : int, Generator or None
        Ties between equally good references and the jitter draw from it.
    progress, should_cancel
        See :mod:`strew._progress`.

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
    if mode not in MODES:
        raise InputError(f"--mode: unknown mode {mode!r}; use one of {', '.join(MODES)}")
    if isinstance(exemplar, Reference):
        ref = exemplar
        for i, j in flips:
            ref = flip_edge(ref, int(i), int(j))
    elif isinstance(exemplar, Arrangement):
        ref = analyze(exemplar, flips=flips)
    else:
        raise InputError(f"exemplar: must be an Arrangement or a Reference, got {type(exemplar).__name__}")
    if count is not None:
        if isinstance(count, bool) or int(count) != count or count < 1:
            raise InputError(f"--count: must be a positive integer, got {count!r}")
        count = int(count)
    if region is not None and not isinstance(region, Region):
        raise InputError(f"region: must be a Region, got {type(region).__name__}")
    if mode == "flow" and flow is None:
        raise InputError("--mode flow: needs a flow field (--flow STROKES)")
    if flow is not None and not callable(flow):
        raise InputError("flow: must be callable, e.g. strew.fields.flow_field(strokes)")
    spray_arr = None
    if spray is not None:
        spray_arr = _polyline(spray, "spray")
        if spray_radius is None or not (np.isfinite(spray_radius) and spray_radius > 0):
            raise InputError(f"--spray-radius: must be a positive number with --spray, got {spray_radius!r}")
    elif spray_radius is not None:
        raise InputError("--spray-radius: given without --spray")
    bounds = [_polyline(b, f"boundary[{i}]") for i, b in enumerate(boundary or [])]
    if count is None and region is None and spray_arr is None:
        raise InputError("grow: give --count, or a --region / --size (or a spray path) to fill")
    from .._limits import check_work, element_area  # refuse work beyond the limits (issue 17)

    check_work("--count" if count is not None else "--size/--region", count=count, region=region, per_element=element_area(ref.exemplar))
    kinds = ref.exemplar.kinds
    if priority is None:
        priority = size_priority(ref.exemplar)
    prio: dict[str, float] = {}
    for name, v in dict(priority or {}).items():
        if name not in kinds:
            raise InputError(f"--priority: unknown kind {name!r} (exemplar kinds: {', '.join(kinds)})")
        try:
            fv = float(v)
        except (TypeError, ValueError):
            raise InputError(f"--priority {name}: must be a number, got {v!r}") from None
        if not np.isfinite(fv):
            raise InputError(f"--priority {name}: must be finite")
        prio[name] = fv
    for name, v in (("--jitter-scale", jitter_scale), ("--jitter-rotation", jitter_rotation), ("--jitter-color", jitter_color)):
        if not (np.isfinite(v) and v >= 0):
            raise InputError(f"{name}: must be a non-negative number, got {v!r}")
    if jitter_scale >= 1:
        raise InputError(f"--jitter-scale: must be below 1 (a scale must stay positive), got {jitter_scale!r}")
    if start is not None:
        start = tuple(float(v) for v in start)  # type: ignore[assignment]
        if len(start) != 2 or not all(np.isfinite(start)):
            raise InputError(f"--start: expected a finite point x,y, got {start!r}")
    start_index = -1
    if start_kind is not None:
        if start_kind not in kinds:
            raise InputError(f"--start-kind: unknown kind {start_kind!r} (exemplar kinds: {', '.join(kinds)})")
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
    )
    meta = {"method": "grow"}
    return grow_reference(ref, params, rng=rng, progress=progress, should_cancel=should_cancel, meta=meta)
