"""The spray tool as one growth that follows the cursor (Ijiri et al. 2008, §3, §5.1).

§5.1: "In the spray tool mode, we generate an initial seed at the cursor position when
the user starts painting and grow all the seeds which are in the user-specified distance
from the cursor during painting." :class:`SprayGrowth` keeps that one growth (its seeds,
horizon, connectivity and relaxation state) between the cursor moves of a stroke, so
each move only grows the seeds the cursor newly reaches.
"""

from __future__ import annotations

import heapq
import math
from collections.abc import Callable, Iterable, Mapping, Sequence
from typing import Any

import numpy as np
import shapely

from .._errors import InputError
from .._progress import Reporter
from .._rng import as_rng
from ..arrangement import Arrangement
from ..region import Region
from ._analysis import Reference, analyze, size_priority
from ._growth import ELEMENT, SEED, GrowParams, _Grower
from ._match import MODES

__all__ = ["SprayGrowth"]


def _points(a: Any, name: str) -> np.ndarray:
    try:
        p = np.asarray(a, dtype=float).reshape(-1, 2)
    except (TypeError, ValueError):
        raise InputError(f"{name}: must be (x, y) points") from None
    if not np.all(np.isfinite(p)):
        raise InputError(f"{name}: NaN or inf coordinate")
    return p


class SprayGrowth:
    """One growth painted along a stroke with the spray tool (§3, §5.1).

    Parameters
    ----------
    exemplar : Arrangement or Reference
        The reference arrangement, or its analysis from :func:`strew.grow.analyze`.
    radius : float
        Spray radius: only seeds within it of the stroke's points grow.
    region : Region, optional
        Element centres stay inside it.
    mode, flow, boundary, priority, jitter_scale, jitter_rotation, jitter_color, relax, relax_every
        As for :func:`strew.grow.grow`.
    rng : int, Generator or None
        Ties and jitter draw from it; the same points in the same calls give the same
        elements.
    tile : (4,) float, optional
        ``x0, y0, W, H``: spray on the torus of this repeat tile (issue 18, not in the
        paper; ``GrowParams.tile``). The growth sees across the tile's edges through
        ghost images, the stroke and the obstacles wrap (a stroke past an edge
        continues at the opposite one), and the elements handed out keep their centres
        in the tile (:func:`strew._periodic.canonical`) with ``meta["periodic"]`` set:
        copies of them laid side by side neither overlap nor show a seam. The region,
        if given, is not tested (the tile is the domain); boundary strokes are.

    Notes
    -----
    Departures from the paper, for painting in a scene:

    - Elements handed out by :meth:`grow` are held fixed from then on (Eq. 6), so that
      what is on screen does not move under later relaxation windows (§5.5). Elements
      are relaxed in the window after their placement only, then held, so that handing
      out at any window gives the same growth.
    - :meth:`add_obstacles` registers elements the growth does not own (the scene);
      seeds that would overlap them die like seeds that would overlap the growth.
    - When the cursor reaches a place with no element or seed within the radius (the
      growth died out, or the stroke started on the scene), a new initial seed is put at
      the cursor, as at the stroke's start (§5.1).

    Examples
    --------
    >>> from strew.grow._exemplars import hex_exemplar
    >>> g = SprayGrowth(hex_exemplar(), radius=30.0, rng=1)
    >>> g.add_points([[0.0, 0.0]])
    >>> first = g.grow()
    >>> g.add_points([[40.0, 0.0], [80.0, 0.0]])
    >>> more = g.grow()
    >>> len(first) > 0 and len(more) > 0
    True
    """

    def __init__(
        self,
        exemplar: Arrangement | Reference,
        *,
        radius: float,
        region: Region | None = None,
        mode: str = "fixed",
        flow: Callable[[np.ndarray], np.ndarray] | None = None,
        boundary: Iterable[np.ndarray] | None = None,
        priority: Mapping[str, float] | None = None,
        jitter_scale: float = 0.0,
        jitter_rotation: float = 0.0,
        jitter_color: float = 0.0,
        relax: bool = True,
        relax_every: int = 16,
        rng: int | np.random.Generator | None = None,
        tile: Sequence[float] | None = None,
    ) -> None:
        if tile is not None:
            from .._periodic import _as_frame

            tile = _as_frame(tile, "tile")
        if isinstance(exemplar, Reference):
            ref = exemplar
        elif isinstance(exemplar, Arrangement):
            ref = analyze(exemplar, lattice_repairs=mode != "flow")
        else:
            raise InputError(f"exemplar: must be an Arrangement or a Reference, got {type(exemplar).__name__}")
        if not (isinstance(radius, (int, float)) and math.isfinite(radius) and radius > 0):
            raise InputError(f"radius: must be a positive number, got {radius!r}")
        if mode not in MODES:
            raise InputError(f"mode: unknown mode {mode!r}; use one of {', '.join(MODES)}")
        if mode == "flow" and flow is None:
            raise InputError("mode flow: needs a flow field")
        if region is not None and not isinstance(region, Region):
            raise InputError(f"region: must be a Region, got {type(region).__name__}")
        for name, v in (("jitter_scale", jitter_scale), ("jitter_rotation", jitter_rotation), ("jitter_color", jitter_color)):
            if not (np.isfinite(v) and v >= 0):
                raise InputError(f"{name}: must be a non-negative number, got {v!r}")
        if jitter_scale >= 1:
            raise InputError(f"jitter_scale: must be below 1, got {jitter_scale!r}")
        if int(relax_every) < 1:
            raise InputError(f"relax_every: must be at least 1, got {relax_every!r}")
        kinds = ref.exemplar.kinds
        if priority is None:
            priority = size_priority(ref.exemplar)  # the default: larger kinds first
        for name in priority or {}:
            if name not in kinds:
                raise InputError(f"priority: unknown kind {name!r}")
        params = GrowParams(
            region=region,
            mode=mode,
            flow=flow,
            boundary=[_points(b, "boundary") for b in (boundary or [])],
            spray_radius=float(radius),
            priority={k: float(v) for k, v in (priority or {}).items()},
            jitter_scale=float(jitter_scale),
            jitter_rotation=float(jitter_rotation),
            jitter_color=float(jitter_color),
            relax=bool(relax),
            relax_every=int(relax_every),
            tile=tile,
        )
        self.radius = float(radius)
        self.tile = tile
        self._g = _Grower(ref, params, as_rng(rng))
        self._g.waiting = []
        self._g.freeze_relaxed = True
        self._stroke = np.zeros((0, 2))
        self._given = 0  # elements of the growth handed out so far
        self._started = False
        if tile is not None:  # the ghost margin now, for obstacles handed in before the first point
            g = self._g
            g.max_scale = float(g.ex_scale.max()) * (1.0 + g.p.jitter_scale)
            g.other_rmax = max(g.other_rmax, float(g.kind_radius.max()) * g.max_scale)
            g._torus_margin()

    # ------------------------------------------------------------------ input
    def add_obstacles(self, arr: Arrangement) -> None:
        """Elements (of any shapes) that the growth must not overlap.

        Parameters
        ----------
        arr : Arrangement
            Elements already in the scene near the stroke.
        """
        if len(arr) == 0:
            return
        geoms = arr.geometry
        areal = shapely.area(geoms) > 0
        per_kind = np.array([arr.shapes[k].radius for k in arr.kinds])
        radii = per_kind[arr.kind] * np.abs(arr.scale)
        if self.tile is not None:
            # on the torus: each obstacle at its canonical place and its images within the
            # ghost margin of the tile (the margin is under a tile: one tile away at most)
            from .._periodic import canonical, translations

            x0, y0, w, h = self.tile
            cx, cy = canonical(arr.x, arr.y, self.tile)
            reach = self._g.margin + radii
            for i, j in translations(3, 3):
                px, py = cx + i * w, cy + j * h
                hit = (px + reach > x0) & (px - reach < x0 + w) & (py + reach > y0) & (py - reach < y0 + h)
                for q in np.flatnonzero(hit):
                    dx, dy = px[q] - arr.x[q], py[q] - arr.y[q]
                    gq = shapely.transform(geoms[q], lambda c, dx=dx, dy=dy: c + (dx, dy))
                    self._g.add_obstacle(float(px[q]), float(py[q]), gq, bool(areal[q]), float(radii[q]))
            return
        for i in range(len(arr)):
            self._g.add_obstacle(float(arr.x[i]), float(arr.y[i]), geoms[i], bool(areal[i]), float(radii[i]))

    def add_points(self, points: np.ndarray | Sequence[Sequence[float]]) -> None:
        """The cursor moved through ``points`` (k, 2): seeds within the radius may grow.

        The first point of a stroke gets the initial seed (§5.1). With a ``tile`` the
        points may lie anywhere: each continues the stroke by the shortest step on the
        torus.
        """
        pts = _points(points, "points")
        if len(pts) == 0:
            return
        g = self._g
        if self.tile is not None:
            pts = self._unwrapped(pts)
        self._stroke = np.concatenate([self._stroke, pts])
        line = shapely.LineString(self._stroke) if len(self._stroke) >= 2 else shapely.Point(self._stroke[0])
        g.spray_area = line.buffer(self.radius)
        if self.tile is not None:
            g.spray_area = self._images(g.spray_area)
        shapely.prepare(g.spray_area)
        if not self._started:
            for p in pts:
                if g.in_domain(float(p[0]), float(p[1])):
                    g.begin((float(p[0]), float(p[1])))
                    self._started = True
                    break
        else:
            # not in the paper: a new initial seed where the growth cannot reach (see Notes)
            for p in pts[::-1]:
                x, y = float(p[0]), float(p[1])
                if self.tile is not None:
                    from .._periodic import canonical

                    cx, cy = canonical(np.array([x]), np.array([y]), self.tile)
                    x, y = float(cx[0]), float(cy[0])
                if g.in_domain(x, y) and not self._any_near(x, y):
                    g.new_object(x, y, g.p.start_kind)
                    break
        # seeds that waited outside the spray area and are now inside it
        wait = [s for s in g.waiting if g.state[s] == SEED] if g.waiting else []
        if wait:
            inside = shapely.contains_xy(g.spray_area, g.pos[wait, 0], g.pos[wait, 1])
            g.waiting = [s for s, ok in zip(wait, inside) if not ok]
            ox, oy = g.origin
            for s, ok in zip(wait, inside):
                if ok:
                    g.heap.append((math.hypot(g.pos[s, 0] - ox, g.pos[s, 1] - oy), s))
            heapq.heapify(g.heap)

    def _unwrapped(self, pts: np.ndarray) -> np.ndarray:
        """Torus: the points as a continuous stroke, each the shortest step from the one
        before (the first of a stroke wrapped into the tile)."""
        from .._periodic import canonical, wrap_delta

        _, _, w, h = self.tile  # type: ignore[misc]
        out = np.empty_like(pts)
        if len(self._stroke):
            prev = self._stroke[-1]
            first = 0
        else:
            cx, cy = canonical(pts[:1, 0], pts[:1, 1], self.tile)  # type: ignore[arg-type]
            prev = out[0] = (cx[0], cy[0])
            first = 1
        for k in range(first, len(pts)):
            prev = out[k] = (prev[0] + wrap_delta(pts[k, 0] - prev[0], w), prev[1] + wrap_delta(pts[k, 1] - prev[1], h))
        return out

    def _images(self, area: Any) -> Any:
        """Torus: the spray area with its copies whole tiles away that come within a tile
        of the tile (where originals and ghosts can be)."""
        x0, y0, w, h = self.tile  # type: ignore[misc]
        bx0, by0, bx1, by1 = area.bounds
        parts = []
        for i in range(math.ceil((x0 - w - bx1) / w), math.floor((x0 + 2 * w - bx0) / w) + 1):
            for j in range(math.ceil((y0 - h - by1) / h), math.floor((y0 + 2 * h - by0) / h) + 1):
                parts.append(shapely.transform(area, lambda c, i=i, j=j: c + (i * w, j * h)))
        return shapely.union_all(parts) if parts else area

    def _any_near(self, x: float, y: float) -> bool:
        """Is a seed or element within the radius of (x, y)?"""
        return bool(self._g.index.near(x, y, self.radius, (1 << SEED) | (1 << ELEMENT), limit=1))

    # ------------------------------------------------------------------ growth
    @property
    def reach(self) -> float:
        """Bounding radius of the widest element this growth can place.

        Its widest kind at the exemplar's largest scale, with the scale jitter on top
        (§3), and never less than the kind's own radius: the bound the growth itself
        tests overlaps with (obstacles from :meth:`add_obstacles` are not counted). A
        caller that hands in obstacles near the stroke needs those within ``radius +
        reach`` of it, plus their own radii.
        """
        g = self._g
        widest = float(g.kind_radius.max()) if len(g.kind_radius) else 0.0
        top = float(np.max(np.abs(g.ex_scale))) if len(g.ex_scale) else 1.0
        return widest * max(1.0, top * (1.0 + g.p.jitter_scale))

    @property
    def pending(self) -> bool:
        """True when seeds within the spray area may still grow."""
        return bool(self._g.heap)

    def grow(
        self,
        max_new: int | None = None,
        *,
        progress: Callable[[int, int | None, str], None] | None = None,
        should_cancel: Callable[[], bool] | None = None,
    ) -> Arrangement:
        """Grow the seeds within the spray area; return the new elements.

        Parameters
        ----------
        max_new : int, optional
            Stop after about this many new elements (at the next relaxation window, so
            that stopping and going on gives the same growth); :attr:`pending` then says
            whether more can grow. All by default; 0 grows nothing and hands out what a
            cancelled call left.
        progress, should_cancel
            See :mod:`strew._progress`; a cancelled call raises
            :class:`strew.Cancelled` and keeps what it placed for the next call.

        Returns
        -------
        Arrangement
            The elements placed since the last call, in placement order, with column
            ``sub_id`` (and ``color`` when colours vary). They stay where they are.
        """
        g = self._g
        if self._started and max_new == 0:
            g.settle()  # no growth: hand out what an interrupted call placed
        elif self._started:
            rep = Reporter(progress, should_cancel, message="spraying")
            pause = None if max_new is None else self._given + max(1, int(max_new))
            if not g.advance(rep, g.p.max_elements, pause=pause):
                g.settle()
        order = g.order[self._given :]
        idx = np.asarray(order, dtype=np.intp)
        idx = idx[g.state[idx] == ELEMENT] if len(idx) else idx
        g.fixed[idx] = True  # Eq. 6: handed-out elements hold their positions (see Notes)
        self._given = len(g.order)
        return self._result(idx)

    def _result(self, idx: np.ndarray) -> Arrangement:
        g = self._g
        ex = g.ref.exemplar
        columns: dict[str, Any] = {"sub_id": g.sub[idx].copy()}
        if g.want_color:
            columns["color"] = [g.color[i] for i in idx]
        columns.update(g.copied_columns(g.sub[idx]))
        arr = Arrangement(ex.shapes, g.kind[idx], g.pos[idx, 0].copy(), g.pos[idx, 1].copy(), g.rot[idx].copy(), g.scl[idx].copy(), columns=columns, meta={"method": "grow", "tool": "spray"})
        if self.tile is not None:
            from .._periodic import mark

            arr = mark(arr, self.tile)
        return arr

    def arrangement(self) -> Arrangement:
        """All elements handed out so far, in the order :meth:`grow` gave them."""
        return self._result(np.asarray(self._g.order[: self._given], dtype=np.intp))

