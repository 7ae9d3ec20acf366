"""Step 2 of the fill-gap method (Sakurai & Miyata §4.2): the engine.

The engine (:class:`FitEngine`) prepares each kind (flat rings, inscribed disks, anchor
points), places Step 1's points (:func:`_place_sparse`) and drives the compiled draw
loop (``_draw._rounds``), whose poses pass the exact tests of ``_predicates`` (issue 15
point 7 split the former single module in these three; shared loops come from
``strew._kernels``).

Each round draws candidate points Q from the normalised distance field with probability
``alpha = d**n`` (n = 16), chooses P = 100 of them and tries to place an exclusive region
at each, in order; the run stops after ``max_failures`` (200) consecutive cancellations.
The paper's steps are all here; three extensions of §4.2 make each cancellation count:

* **Fit** (``fits`` poses per candidate): a candidate point is tried with up to ``fits``
  random rotations and scales of its kind before it counts as one cancellation. The
  paper draws one pose (``fits=1``); a narrow gap usually admits an elongated or concave
  element in a few orientations only. The first pose puts the exclusive region's
  bounding-box centre on the point (T of Eq. 1, as the paper); later ones alternate
  between the centre of the widest of the kind's inscribed disks that the gap can hold
  (its radius at most the field at the point) and one of the kind's anchor points (the
  centre of its widest disk, or an interior point): a concave element's box centre may
  lie outside it, where a neighbour's arm can sit, and the field never proposes such a
  point.
* **Suppression** (``suppress``): after a cancellation the field's weight is multiplied by
  ``suppress`` in a small disk about the failed point, so that the next candidates explore
  other gaps (like the exclude list of Wong et al.'s framework) instead of spending the
  200-cancellation budget on one gap that nothing fits. ``suppress=1`` turns it off.
* **Fresh candidates**: the field is updated after every placement, not once per round,
  and a candidate whose pixel lost weight since it was drawn is kept with probability
  ``(e_now / e_drawn)**n`` (a thinning that gives the law of the updated field); dropped
  candidates are not trials. The paper's fixed list of 100 points would otherwise spend
  most of a round in the gap that its first placement just filled.

Collision tests stay exact on the polygons: closed-segment intersection and even-odd
point-in-polygon tests against the neighbours found in a uniform grid, and against the
domain's boundary. Before them, a pose is rejected for certain when one of a few disks
inscribed in the kind is wider than the field at its centre allows: the field at a pixel
centre is never below the true distance to the nearest obstacle (exact polygon distances
after each placement; the initial raster distance is measured to obstacle pixel centres,
which lie inside obstacles), so such a disk must meet an obstacle. The field only ever
rejects; it never accepts. The exact tests are robust: an orientation or a ray crossing
too close to call at relative tolerance :data:`TOL` counts as touching, and touching is a
collision, so an accepted element is certainly disjoint from its neighbours and inside
the domain, and needs no shapely re-check (``tests/pack`` checks results with shapely).
"""

from __future__ import annotations

import numba
import numpy as np
import shapely

from .._kernels.geometry import inside as _inside
from .._kernels.grid import hash_segments as _hash_segments
from .._kernels.prng import seed_state as rand_state
from ._draw import DONE, NEED_ROOM, NO_FIELD, RUNNING, _rounds
from ._exclusive import ExclusiveRegion
from ._predicates import _S_CONSEC, _S_NEXT, _S_NP, _S_NR, _S_NV, _S_NE, _S_POSES, _S_QID, _S_ROUNDS, _S_TRIALS, TOL, _in_region, _insert, _pose, ring_layout

__all__ = ["FitEngine", "ring_layout", "TOL", "RUNNING", "DONE", "NEED_ROOM", "NO_FIELD", "rand_state"]


@numba.njit(cache=True)
def _place_sparse(xy, u_rot, u_sc, kinds, kv, kr, kk, hv, hr, hk, same_hull, rot_lo, rot_hi, sc_lo, sc_hi,
                  rv, rr, rsegs, rhead, rent, rext, rstamp, cv, ch, cbb, hbb,
                  pv, pr, pp, pbb, pose, pkind, g, head, tail, ent, ext, st, per):  # pragma: no cover - numba
    """Step 1 (§4.1): place an element at each Poisson-disk point, in order, when it lies
    inside the domain (exact test; on a repeat tile's torus, ``per`` not None, every
    point does); the points' circles already keep elements apart, so no collision test
    runs. ``u_rot``, ``u_sc``: uniform numbers mapped into each kind's
    ranges; ``kinds``: drawn by weight, or empty for cyclic kinds (advanced on each
    placement). Returns the number placed."""
    nk = len(kk) - 1
    placed = 0
    for i in range(len(xy)):
        k = kinds[i] if len(kinds) else st[_S_NEXT]
        rot = rot_lo[k] + u_rot[i] * (rot_hi[k] - rot_lo[k])
        s = sc_lo[k] + u_sc[i] * (sc_hi[k] - sc_lo[k])
        c = np.cos(rot) * s
        sn = np.sin(rot) * s
        x = xy[i, 0]
        y = xy[i, 1]
        _pose(kv, kr, kk[k], kk[k + 1], x, y, c, sn, cv, cbb)
        st[_S_QID] += 1
        if per is not None:
            inside = True
        elif same_hull[k]:
            inside = _in_region(cv, kr, kk[k], kk[k + 1], cbb, rv, rr, rsegs, g, rhead, rent, rext, rstamp, st[_S_QID])
        else:
            _pose(hv, hr, hk[k], hk[k + 1], x, y, c, sn, ch, hbb)
            inside = _in_region(ch, hr, hk[k], hk[k + 1], hbb, rv, rr, rsegs, g, rhead, rent, rext, rstamp, st[_S_QID])
        if not inside:
            continue
        _insert(k, x, y, rot, s, cv, kr, kk, cbb, pv, pr, pp, pbb, pose, pkind, g, head, tail, ent, ext, st)
        placed += 1
        if len(kinds) == 0:
            st[_S_NEXT] = (st[_S_NEXT] + 1) % nk
    return placed


@numba.njit(cache=True)
def _clearance(v, rings, pts):  # pragma: no cover - numba
    """Even-odd inside flags of points (m, 2) in all rings of a flat layout, and their
    distances to the rings' edges."""
    m = len(pts)
    inside = np.zeros(m, dtype=np.bool_)
    dist = np.zeros(m)
    for j in range(m):
        px, py = pts[j, 0], pts[j, 1]
        inside[j] = _inside(px, py, v, rings, 0, len(rings) - 1)
        best = np.inf
        for r in range(len(rings) - 1):
            for i in range(rings[r], rings[r + 1] - 1):
                ax, ay = v[i, 0], v[i, 1]
                ex, ey = v[i + 1, 0] - ax, v[i + 1, 1] - ay
                l2 = ex * ex + ey * ey
                t = 0.0
                if l2 > 0.0:
                    t = min(max(((px - ax) * ex + (py - ay) * ey) / l2, 0.0), 1.0)
                qx, qy = ax + t * ex - px, ay + t * ey - py
                best = min(best, qx * qx + qy * qy)
        dist[j] = np.sqrt(best)
    return inside, dist


def _interior_grid(body: shapely.Geometry, n: int = 24) -> tuple[np.ndarray, np.ndarray]:
    """Points of an n x n grid over the body's box that lie inside it (not on its
    boundary), and their distances to its boundary."""
    x0, y0, x1, y1 = body.bounds
    gx, gy = np.meshgrid(np.linspace(x0, x1, n), np.linspace(y0, y1, n))
    pts = np.c_[gx.ravel(), gy.ravel()]
    v, rings, _ = ring_layout([body])
    inside, dist = _clearance(v, rings, pts)
    # not on the boundary (the even-odd test is half-open; distances carry rounding)
    keep = inside & (dist > 1e-9 * max(x1 - x0, y1 - y0))
    return pts[keep], dist[keep]


def _anchors(grids: list, disks: np.ndarray, offsets: np.ndarray, more: int = 16) -> tuple[np.ndarray, np.ndarray]:
    """Anchor points inside each kind's exclusive region: the centre of its widest disk
    (about its pole of inaccessibility) and ``more`` interior points of a 24 x 24 grid.

    Parameters
    ----------
    grids : list of ((m, 2) float, (m,) float)
        Each kind's interior grid points and clearances (:func:`_interior_grid`).
    disks, offsets : the kinds' disks (:func:`_disks`)

    Returns
    -------
    anchors : (n, 3) float
        Point in local, centred coordinates, and the radius of a disk about it inside
        the region (its distance to the boundary, less a rounding margin).
    offsets : (K + 1,) int64
    """
    pts, off = [], [0]
    for j in range(len(grids)):
        own = [disks[offsets[j]]] if offsets[j + 1] > offsets[j] else []
        grid, clear = grids[j]
        if len(grid):
            pick = np.unique(np.linspace(0, len(grid) - 1, more).astype(int))
            own.extend(np.c_[grid[pick], clear[pick] * (1 - 1e-9)])
        pts.extend(own)
        off.append(off[-1] + len(own))
    return np.asarray(pts, dtype=float).reshape(-1, 3), np.asarray(off, dtype=np.int64)


def _disks(grids: list, most: int = 16) -> tuple[np.ndarray, np.ndarray]:
    """Disks inside each kind's exclusive region, for the field's certain rejections.

    Greedy: among interior sample points, take the one farthest from the boundary, drop
    the points its disk covers, repeat (at most ``most`` disks, each at least 0.15 of
    the widest: more and thinner disks reject more poses before the exact tests, with
    the same results, since the disks only ever reject poses that collide).

    Parameters
    ----------
    grids : list of ((m, 2) float, (m,) float)
        Each kind's interior grid points and their distances to its boundary
        (:func:`_interior_grid`).

    Returns
    -------
    disks : (n, 3) float
        Centre (local, centred coordinates) and radius.
    offsets : (K + 1,) int64
    """
    out, off = [], [0]
    for pts, clear in grids:
        own = _greedy_disks(np.ascontiguousarray(pts, dtype=float), np.asarray(clear, dtype=float), most)
        out.append(own)
        off.append(off[-1] + len(own))
    return np.concatenate(out).reshape(-1, 3), np.asarray(off, dtype=np.int64)


@numba.njit(cache=True)
def _greedy_disks(pts, clear, most):  # pragma: no cover - numba
    """The greedy choice of :func:`_disks` for one kind: (m, 3) centres and radii."""
    n = len(pts)
    alive = np.empty(n, dtype=np.bool_)
    for j in range(n):
        alive[j] = True
    out = np.zeros((most, 3))
    m = 0
    while m < most:
        i = -1
        best = -1.0
        for j in range(n):  # the first of the widest left
            if alive[j] and clear[j] > best:
                best = clear[j]
                i = j
        if i < 0 or (m > 0 and clear[i] < 0.15 * out[0, 2]):
            break
        out[m, 0] = pts[i, 0]
        out[m, 1] = pts[i, 1]
        out[m, 2] = clear[i] * (1 - 1e-9)
        m += 1
        for j in range(n):  # drop the points this disk covers
            if alive[j] and np.hypot(pts[j, 0] - pts[i, 0], pts[j, 1] - pts[i, 1]) <= clear[i]:
                alive[j] = False
    return out[:m]


class FitEngine:
    """Placed exclusive regions in a grid, and the compiled Step 2 loop over them.

    Parameters
    ----------
    kinds : list of ExclusiveRegion
    domain : shapely Polygon or MultiPolygon
        The region to fill.
    weights : (K,) float or None
        Kind probabilities; None: cyclic (§3.2).
    next_kind : int
        The kind to place next in cyclic mode (after Step 1).
    periodic : (x0, y0, W, H), optional
        Fill the torus of this repeat tile (issue 18; ``domain`` is its rectangle).
    """

    def __init__(self, kinds: list[ExclusiveRegion], domain: shapely.Geometry, weights: np.ndarray | None, next_kind: int,
                 periodic: tuple | None = None) -> None:
        self.kv, self.kr, self.kk = ring_layout([k.body for k in kinds])
        self.hv, self.hr, self.hk = ring_layout([k.hull for k in kinds])
        self.same_hull = np.array([k.hull is k.body for k in kinds])
        self.kbb = np.array([shapely.bounds(k.body) for k in kinds], dtype=float).reshape(-1, 4)  # local boxes
        self.rot_lo = np.array([k.rotation[0] for k in kinds], dtype=float)
        self.rot_hi = np.array([k.rotation[1] for k in kinds], dtype=float)
        self.sc_lo = np.array([k.scale[0] for k in kinds], dtype=float)
        self.sc_hi = np.array([k.scale[1] for k in kinds], dtype=float)
        self.cumw = np.zeros(0) if weights is None else np.cumsum(weights)
        grids = [_interior_grid(k.body) for k in kinds]
        self.kdisk, self.kdo = _disks(grids)
        self.kanch, self.ka = _anchors(grids, self.kdisk, self.kdo)
        # grid: cells about the largest element's circumscribed radius
        self.rv, self.rr, _ = ring_layout([domain])
        x0, y0, x1, y1 = domain.bounds
        gc = max(max(k.radius * k.scale[1] for k in kinds), (x1 - x0 + y1 - y0) / 2000.0)
        if periodic is not None:
            # on a repeat tile's torus, placed regions reach up to their circumscribed
            # radius beyond the tile, and so do the translated poses tested against them:
            # the grid covers the tile grown by that much (a cell more for rounding)
            grow = max(k.radius * k.scale[1] for k in kinds) + gc
            x0, y0, x1, y1 = x0 - grow, y0 - grow, x1 + grow, y1 + grow
        cols = int(np.floor((x1 - x0) / gc)) + 1
        rows = int(np.floor((y1 - y0) / gc)) + 1
        # the hashed grids (strew._kernels.grid, issue 15 point 5) of the placed regions
        # and of the domain's edges: cells of side gc, a chain per cell of the extent
        # (rounded up to a power of two); g = (gc, a box around the domain)
        self.g = np.array([gc, x0, y0, x0 + cols * gc, y0 + rows * gc], dtype=float)
        table = 1 << max(int(cols * rows - 1).bit_length(), 10)
        same = np.flatnonzero(self.rr[1:] - self.rr[:-1] > 0)
        starts = np.concatenate([np.arange(self.rr[r], self.rr[r + 1] - 1) for r in same]) if len(same) else np.zeros(0, int)
        self.rsegs = np.ascontiguousarray(np.c_[self.rv[starts], self.rv[starts + 1]]) if len(starts) else np.zeros((0, 4))
        self.rhead, self.rent, self.rext = _hash_segments(self.rsegs, gc, table)
        self.rstamp = np.full(len(self.rsegs), -1, dtype=np.int64)
        nv = max(len(self.kv), len(self.hv))
        self.cv = np.zeros((len(self.kv), 2))
        self.ch = np.zeros((len(self.hv), 2))
        self.cbb = np.zeros(4)
        self.hbb = np.zeros(4)
        maxseg = max(int((self.kr[self.kk[1:]] - self.kr[self.kk[:-1]]).max()), 1)
        self.buf = np.zeros(max(nv, maxseg) + 1, dtype=np.int64)
        self.segs = np.zeros((maxseg + 1, 4))
        self.st = np.zeros(10, dtype=np.int64)
        self.st[_S_NEXT] = next_kind
        self.head = np.full(table, -1, dtype=np.int64)
        self.tail = np.full(table, -1, dtype=np.int64)
        self.ext = np.array([0, 0, -1, -1], dtype=np.int64)
        reach = max(k.radius * k.scale[1] for k in kinds)
        self.per = None if periodic is None else np.array([*(float(v) for v in periodic), reach], dtype=float)
        self.ct = np.zeros((len(self.kv), 2))
        self.tbb = np.zeros(4)
        self._alloc(256, 256 * nv, 256 * 4, 256 * 8)

    def _alloc(self, np_: int, nv: int, nr: int, ne: int) -> None:
        def grow(a: np.ndarray | None, n: int, shape: tuple, dtype, fill=0) -> np.ndarray:
            out = np.full((n, *shape), fill, dtype=dtype)
            if a is not None:
                out[: len(a)] = a
            return out

        old = getattr(self, "pv", None) is not None
        self.pv = grow(self.pv if old else None, nv, (2,), float)
        self.pr = grow(self.pr if old else None, nr + 1, (), np.int64)
        self.pp = grow(self.pp if old else None, np_ + 1, (), np.int64)
        self.pbb = grow(self.pbb if old else None, np_, (4,), float)
        self.pose = grow(self.pose if old else None, np_, (4,), float)
        self.pkind = grow(self.pkind if old else None, np_, (), np.int64)
        self.stamp = grow(self.stamp if old else None, np_, (), np.int64, -1)
        self.ent = grow(self.ent if old else None, ne, (4,), np.int64, -1)
        self.caps = np.array([np_, nv, nr, ne], dtype=np.int64)

    def _room(self, polys: int) -> None:
        """Grow the store (doubling) until ``polys`` more elements fit in the worst case."""
        maxv = int((self.kr[self.kk[1:]] - self.kr[self.kk[:-1]]).max())
        maxr = int((self.kk[1:] - self.kk[:-1]).max())
        need = np.array([self.st[_S_NP] + polys, self.st[_S_NV] + polys * maxv, self.st[_S_NR] + polys * maxr,
                         self.st[_S_NE] + polys * 9])  # a body's box spans at most 3 x 3 cells
        if np.all(need <= self.caps):
            return
        self._alloc(*(int(c) for c in np.maximum(self.caps * 2, need)))

    def __len__(self) -> int:
        return int(self.st[_S_NP])

    def place_sparse(self, xy: np.ndarray, u_rot: np.ndarray, u_scale: np.ndarray, kinds: np.ndarray | None) -> int:
        """Step 1 (§4.1): an element at each point of (m, 2) ``xy`` that lies inside the
        domain, with no collision test (the points are far enough apart).

        Parameters
        ----------
        xy : (m, 2) float
            Where the bounding-box centres of the exclusive regions go (T of Eq. 1).
        u_rot, u_scale : (m,) float in [0, 1)
            Uniform numbers mapped into each kind's rotation and scale range.
        kinds : (m,) int or None
            Kinds drawn by weight; None: cyclic.

        Returns
        -------
        int
            The number placed.
        """
        self._room(len(xy))
        ks = np.zeros(0, dtype=np.int64) if kinds is None else np.asarray(kinds, dtype=np.int64)
        return int(_place_sparse(np.ascontiguousarray(xy, dtype=float), np.asarray(u_rot, dtype=float),
                                 np.asarray(u_scale, dtype=float), ks, self.kv, self.kr, self.kk, self.hv, self.hr,
                                 self.hk, self.same_hull, self.rot_lo, self.rot_hi, self.sc_lo, self.sc_hi, self.rv,
                                 self.rr, self.rsegs, self.rhead, self.rent, self.rext, self.rstamp, self.cv, self.ch,
                                 self.cbb, self.hbb, self.pv, self.pr, self.pp, self.pbb, self.pose, self.pkind, self.g,
                                 self.head, self.tail, self.ent, self.ext, self.st, self.per))

    def segments(self) -> tuple[np.ndarray, np.ndarray]:
        """Ring edges of the placed exclusive regions: (s, 4) ``x0, y0, x1, y1`` and
        (n + 1,) offsets (element ``i`` owns edges ``offsets[i]:offsets[i + 1]``)."""
        n = len(self)
        nr = int(self.pp[n])
        sizes = np.diff(self.pr[: nr + 1])
        ring_of = np.repeat(np.arange(nr), sizes)  # the ring of each stored vertex
        starts = np.flatnonzero(ring_of[:-1] == ring_of[1:])
        segs = np.ascontiguousarray(np.c_[self.pv[starts], self.pv[starts + 1]])
        owner = np.repeat(np.arange(n), np.diff(self.pp[: n + 1]))[ring_of[starts]]
        return segs, np.searchsorted(owner, np.arange(n + 1)).astype(np.int64)

    def run(self, gen: np.random.Generator, field, rounds: int, limit: int, p_count: int, power: float, fits: int,
            suppress: float, sup_r: float, target: np.ndarray | None = None, tol: float = 0.05,
            scale_fit: bool = False) -> int:
        """Up to ``rounds`` rounds of Step 2 against ``field`` (updated in place).

        ``target`` (K,) float: requested kind shares for the gap-fitting kind choice
        (:func:`_kind_order`, ``tol`` the share a kind may run ahead); None: one kind per
        candidate, cyclic or by weight (§3.2). ``scale_fit``: each candidate's poses run
        from the largest scale down, so that the largest element that fits takes the gap.
        """
        ktarget = np.zeros(0) if target is None else np.ascontiguousarray(target, dtype=float)
        if not hasattr(self, "w") or self.w.shape != field.d.shape:
            self.w = np.ones_like(field.d)
            self.qbuf = np.zeros(field.d.size, dtype=np.int64)
            self.cand = np.zeros(p_count, dtype=np.int64)
            self.cdraw = np.zeros(p_count)
        while True:
            state = rand_state(gen)
            status = _rounds(
                state, rounds, limit, p_count, float(power), fits, float(suppress), float(sup_r), ktarget, float(tol), bool(scale_fit), self.kanch, self.ka, self.kdisk, self.kdo,
                self.kbb,
                field.d, self.w, field.x0, field.y0, field.cell, self.qbuf, self.cand, self.cdraw,
                self.kv, self.kr, self.kk, self.hv, self.hr, self.hk, self.same_hull, self.rot_lo, self.rot_hi,
                self.sc_lo, self.sc_hi, self.cumw,
                self.rv, self.rr, self.rsegs, self.rhead, self.rent, self.rext, self.rstamp,
                self.pv, self.pr, self.pp, self.pbb, self.pose, self.pkind, self.g, self.head, self.tail, self.ent, self.ext,
                self.stamp, self.cv, self.ch, self.cbb, self.hbb, self.buf, self.segs, self.caps, self.st,
                float(getattr(field, "cell_y", field.cell)), self.per, self.ct, self.tbb,
            )
            if status != NEED_ROOM:
                return status
            self._room(p_count)

    @property
    def consecutive(self) -> int:
        return int(self.st[_S_CONSEC])

    @property
    def trials(self) -> int:
        return int(self.st[_S_TRIALS])

    @property
    def rounds(self) -> int:
        return int(self.st[_S_ROUNDS])

    @property
    def poses(self) -> int:
        return int(self.st[_S_POSES])

    @property
    def next_kind(self) -> int:
        return int(self.st[_S_NEXT])
