"""Synthesis state: the output O, its horizon, free space and brush points.

The state is what the tools of §5.4 (generative brush, filler, eraser) work on, one call
per stroke segment; :func:`strew.synth.synthesize` drives it for a whole region.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numba
import numpy as np
from scipy.spatial import cKDTree

from .._errors import InputError
from .._periodic import canonical, translations
from .._rng import as_rng
from ..arrangement import Arrangement
from ..region import Region
from . import _kernels as K
from ._prepare import Prepared

__all__ = ["SynthParams", "SynthState", "map_offsets"]

#: ``born`` of a ghost image (see :meth:`SynthState.wrap`): older than any growth
#: iteration, so that a ghost never yields to a new element (it cannot be removed)
GHOST_BORN = -(1 << 40)

OPTIMIZE = ("horizon", "global", "none")


@dataclass(frozen=True)
class SynthParams:
    """Parameters of region growing and optimisation (defaults from §5 and §6.1).

    Attributes
    ----------
    k : int
        Size of the k-coherence sets (§5.1; 5).
    c : float
        Ratio constant rejecting poor candidate neighbourhoods (§5.1; 2, > 1).
    kind_cost : float
        Attribute (kind) mismatch cost omega of Eq. 1, in units of the pair's squared
        threshold ``d^2``.
    seed_separation : float
        Seeds are at least this fraction of their neighbourhood radius apart (§5.1; 0.75).
    optimize : {"horizon", "global", "none"}
        Optimise the expanded horizon (§5.2), every element (§6.4), or nothing.
    relaxation : float
        Fraction of the least-squares step taken per optimisation (0.8).
    frozen_weight : float
        Weight of a frozen element's old position (§5.3: high).
    frozen_prediction_weight : float
        Factor on predictions for frozen elements (§5.3: low).
    horizon_anchor : float
        Small weight keeping horizon elements near their old positions (regularisation).
    max_failures : int
        A free-space point is dropped after this many seeds near it failed to use it.
    check_energy : bool
        Keep an optimisation step only when it lowers the energy of the expanded horizon
        (Eq. 2), else half of it, else none.
    yield_window : int
        Horizon elements made in the last this many iterations yield to new elements of
        a larger size class (an extension for several sizes, see ``grow``; 3).
    noise_floor : float
        Optimisation moves are shortened by the spread of the element's predictions,
        by at most this fraction of its collision radius (0.1; 0 turns it off): the
        texture's own jitter is kept, not averaged away (an extension of §5.2-5.3, see
        ``_optimize._soft_threshold``). It applies to near-regular exemplars that are
        not jittered lattices; those keep their jitter through ``_optimize._own_jitter``.
    """

    k: int = 5
    c: float = 2.0
    kind_cost: float = 1.0
    seed_separation: float = 0.75
    optimize: str = "horizon"
    relaxation: float = 0.8
    frozen_weight: float = 10.0
    frozen_prediction_weight: float = 0.1
    horizon_anchor: float = 0.01
    max_failures: int = 3
    check_energy: bool = False
    yield_window: int = 3
    noise_floor: float = 0.1

    def __post_init__(self) -> None:
        if int(self.k) < 1:
            raise InputError(f"k: must be at least 1, got {self.k}")
        if not self.c > 1:
            raise InputError(f"c: the ratio constant must be greater than 1, got {self.c}")
        if self.optimize not in OPTIMIZE:
            raise InputError(f"optimize: expected one of {', '.join(OPTIMIZE)}, got {self.optimize!r}")
        if not (0 < self.relaxation <= 1):
            raise InputError(f"relaxation: must be in (0, 1], got {self.relaxation}")
        if not self.seed_separation > 0:
            raise InputError(f"seed_separation: must be positive, got {self.seed_separation}")
        if not self.noise_floor >= 0:
            raise InputError(f"noise_floor: must be non-negative, got {self.noise_floor}")
        if not self.kind_cost >= 0:
            raise InputError(f"kind_cost: must be non-negative, got {self.kind_cost}")


def map_offsets(p: np.ndarray, off: np.ndarray) -> np.ndarray:
    """Vectorised m_p (§5.1): offsets ``off`` (n, 2) from example space at points ``p`` (n, 2)."""
    return _map_offsets(np.ascontiguousarray(p, dtype=float), np.ascontiguousarray(off, dtype=float))



@numba.njit(cache=True)
def _map_offsets(p, off):
    out = np.empty_like(off)
    for i in range(off.shape[0]):
        mx, my = K.map_offset(p[i, 0], p[i, 1], off[i, 0], off[i, 1])
        out[i, 0] = mx
        out[i, 1] = my
    return out


_STORAGE = ("_pos", "_src", "_origin", "_horizon", "_free_base", "_born", "_fixed", "_ghost")


class SynthState:
    """The output domain during synthesis.

    Parameters
    ----------
    prep : Prepared
        The analysed selection.
    region : Region, optional
        New elements keep their centres inside it.
    params : SynthParams
    rng : int or Generator or None
    tile : (4,) float, optional
        ``x0, y0, W, H``: synthesize on the torus of this repeat tile (issue 18; see
        :meth:`set_tile`).

    Attributes
    ----------
    n : int
        Number of output elements (voids included).
    pos : (n, 2) float
    src : (n,) int
        Exemplar element each output element was copied from (its attributes and its
        per-element parameters r, r-bar, §4.1).
    origin : (n,) int
        Exemplar element used for k-coherence search (o_e, §5.1); optimisation
        re-assigns it to the best match.
    horizon : (n,) bool
    fixed : (n,) bool
        Context elements.
    born : (n,) int
        The iteration each element was added in.
    iterations : int
        Growth iterations so far (Algorithm 1's loop, over all calls).
    tile : (x0, y0, W, H) or None
        The repeat tile of a periodic state (:meth:`set_tile`), else None.
    """

    def __init__(self, prep: Prepared, region: Region | None = None, params: SynthParams | None = None, rng: Any = None,
                 tile: Any = None) -> None:
        self.prep = prep
        self.region = region
        self.params = params or SynthParams()
        self.rng = as_rng(rng)
        cap = 256
        self.n = 0
        self._pos = np.zeros((cap, 2))
        self._src = np.zeros(cap, np.int64)
        self._origin = np.zeros(cap, np.int64)
        self._horizon = np.zeros(cap, bool)
        self._free_base = np.zeros(cap, np.int64)
        self._born = np.zeros(cap, np.int64)  # state.iterations when added
        self._fixed = np.zeros(cap, bool)  # context elements: neighbours that never move nor leave
        self._ghost = np.zeros(cap, bool)  # periodic: wrapped images of elements near the tile's edges
        self.tile: tuple[float, float, float, float] | None = None
        self.grow_start = 0  # first iteration of the running grow() call
        # first iteration of a grow() call left unfinished (horizon open) whose rooms
        # _grow.fill_room has not seen on finished growth yet (None: none; ROOM_ONE_CLASS)
        self.room_since: int | None = None
        self._flags_n = 0
        self._alive = np.zeros(1024, bool)
        self._fails = np.zeros(1024, np.int16)
        self.brush_points = np.zeros((0, 2))
        self.brush_radii = np.zeros(0)
        self.trace: list[tuple[float, int, float]] | None = None
        self.iterations = 0
        # a tile of strew.tiles: the part of the region whose elements the tile drops
        # (later tiles redo it; a shapely geometry), read by _grow._prefer_balanced
        self._balance_drop: Any = None
        if tile is not None:
            self.set_tile(tile)

    # -- element storage ---------------------------------------------------------------
    @property
    def pos(self) -> np.ndarray:
        return self._pos[: self.n]

    @property
    def src(self) -> np.ndarray:
        return self._src[: self.n]

    @property
    def origin(self) -> np.ndarray:
        return self._origin[: self.n]

    @property
    def horizon(self) -> np.ndarray:
        return self._horizon[: self.n]

    @property
    def fixed(self) -> np.ndarray:
        """(n,) bool: context elements (see ``_context``): seen as neighbours, never
        moved, removed or output."""
        return self._fixed[: self.n]

    @property
    def born(self) -> np.ndarray:
        """(n,) int: the growth iteration (:attr:`iterations`) in which each element was
        added (Algorithm 1's loop counter; context elements: when the context was set)."""
        return self._born[: self.n]

    def element_keys(self, idx: np.ndarray | None = None) -> np.ndarray:
        """Keys that name elements across removals and re-assignments.

        An element's index shifts when an earlier element is removed; its key does not.
        The key combines the element's free-space block (§5.1; allocated afresh for every
        added or re-assigned element, so never shared by two elements of one state) and its
        exemplar element.

        Parameters
        ----------
        idx : (m,) int, optional
            Elements (default: all ``n``).

        Returns
        -------
        (m,) int64
            Distinct for distinct live elements; an element keeps its key until it is
            removed or re-assigned (:meth:`reassign`).
        """
        idx = np.arange(self.n) if idx is None else np.asarray(idx, np.int64)
        return (self._free_base[idx].astype(np.int64) << 20) | self._src[idx].astype(np.int64)

    def elements(self, idx: np.ndarray | None = None) -> Arrangement:
        """Elements ``idx`` as a bare arrangement: shapes, kinds and poses only.

        Unlike :meth:`to_arrangement` nothing is left out (voids, context elements and
        overlapping elements included), no columns are built and no region is attached,
        so indices into the result are indices into the state.

        Parameters
        ----------
        idx : (m,) int, optional
            Elements (default: all ``n``).

        Returns
        -------
        Arrangement
            ``m`` elements, in the order of ``idx``.
        """
        prep = self.prep
        idx = np.arange(self.n) if idx is None else np.asarray(idx, np.int64)
        src = self._src[idx]
        pos = self._pos[idx]
        return Arrangement(prep.shapes, prep.kind[src].astype(np.int64), pos[:, 0], pos[:, 1], prep.rotation[src], prep.scale[src])

    @property
    def r(self) -> np.ndarray:
        return self.prep.r[self.src]

    @property
    def rbar(self) -> np.ndarray:
        return self.prep.rbar[self.src]

    @property
    def kind(self) -> np.ndarray:
        return self.prep.kind[self.src]

    def _grow_to(self, n: int) -> None:
        cap = len(self._src)
        if n <= cap:
            return
        new = max(n, 2 * cap)
        for name in _STORAGE:
            old = getattr(self, name)
            arr = np.zeros((new, *old.shape[1:]), dtype=old.dtype)
            arr[: self.n] = old[: self.n]
            setattr(self, name, arr)

    def _alloc_flags(self, src: np.ndarray) -> np.ndarray:
        """Fresh (alive) free-space flags for elements copied from ``src``; returns bases."""
        counts = np.diff(self.prep.free_ptr)[src]
        base = self._flags_n + np.concatenate([[0], np.cumsum(counts)[:-1]]) if len(src) else np.zeros(0, np.int64)
        need = self._flags_n + int(counts.sum())
        if need > len(self._alive):
            new = max(need, 2 * len(self._alive))
            a = np.zeros(new, bool)
            a[: self._flags_n] = self._alive[: self._flags_n]
            f = np.zeros(new, np.int16)
            f[: self._flags_n] = self._fails[: self._flags_n]
            self._alive, self._fails = a, f
        self._alive[self._flags_n : need] = True
        self._fails[self._flags_n : need] = 0
        self._flags_n = need
        return base.astype(np.int64)

    def add(self, src: np.ndarray, pos: np.ndarray, *, horizon: bool = True, fixed: bool = False) -> np.ndarray:
        """Append elements copied from exemplar elements ``src`` at ``pos``; returns their indices."""
        src = np.asarray(src, np.int64)
        m = len(src)
        self._grow_to(self.n + m)
        idx = np.arange(self.n, self.n + m)
        self._pos[idx] = pos
        self._src[idx] = src
        self._origin[idx] = src
        self._horizon[idx] = horizon
        self._free_base[idx] = self._alloc_flags(src)
        self._born[idx] = self.iterations
        self._fixed[idx] = fixed
        self._ghost[idx] = False
        self.n += m
        return idx

    def reassign(self, idx: np.ndarray, src: np.ndarray) -> None:
        """Give elements new attributes (copied from ``src``) and fresh free space."""
        idx = np.asarray(idx, np.int64)
        src = np.asarray(src, np.int64)
        self._src[idx] = src
        self._origin[idx] = src
        self._free_base[idx] = self._alloc_flags(src)

    def remove(self, mask: np.ndarray) -> int:
        """Delete elements where ``mask`` is True (context elements stay); returns how many."""
        keep = ~(np.asarray(mask, bool) & ~self.fixed)
        return self._compact(keep)

    def _compact(self, keep: np.ndarray) -> int:
        """Keep the elements where ``keep`` (n,) is True, in order; returns how many went."""
        k = int(keep.sum())
        removed = self.n - k
        if removed:
            for name in _STORAGE:
                arr = getattr(self, name)
                arr[:k] = arr[: self.n][keep]
            self.n = k
        return removed

    # -- periodic output (issue 18; not in the paper) -------------------------------------
    def set_tile(self, tile: Any) -> None:
        """Synthesize on the torus of a repeat tile from now on (None: in the plane again).

        Not in the paper (issue 18). The output then fills ``[x0, x0 + W) x [y0, y0 + H)``
        as a torus: during growth (:meth:`wrap`) every element within :attr:`margin` of
        the tile's edges has ghost images one tile away, frozen context like
        ``_context``'s neighbours (§5.2), so that neighbourhood matching, seeding,
        collisions, free space and optimisation see across the edges; elements keep
        their centres in the tile (:func:`strew._periodic.canonical`), and
        :meth:`to_arrangement` marks the output periodic. The tools (``brush``,
        ``fill``, ``erase``) take strokes anywhere and wrap them.

        Parameters
        ----------
        tile : (4,) float or None
            ``x0, y0, W, H``. The region, when set, must lie in it (it is the tile by
            default); the tile must be at least :attr:`margin` wide and high.
        """
        self.unwrap()
        if tile is None:
            self.tile = None
            return
        from .._periodic import _as_frame

        x0, y0, w, h = _as_frame(tile, "tile")
        m = self.margin
        if min(w, h) < m:
            raise InputError(
                f"periodic: the tile {w:g} x {h:g} is too small for this selection: its neighbourhoods reach {m:.4g} "
                f"(twice the largest neighbourhood and element radius); give a tile at least {m:.4g} wide and high"
            )
        self.tile = (x0, y0, w, h)
        if self.region is None:
            self.region = Region.rectangle(w, h, x0, y0)

    @property
    def margin(self) -> float:
        """How far beyond a periodic tile's edges ghost images are kept: twice the
        largest neighbourhood radius plus twice the largest element radius of the
        prepared exemplars (a seed's neighbourhood, its candidates' and their
        collisions all lie within it)."""
        prep = self.prep
        return 2.0 * float(np.max(prep.rbar)) + 2.0 * float(np.max(prep.r)) if len(prep.r) else 0.0

    @property
    def ghost(self) -> np.ndarray:
        """(n,) bool: ghost images of a periodic state (only while :meth:`wrap` holds them)."""
        return self._ghost[: self.n]

    def unwrap(self) -> None:
        """Drop the ghost images and wrap the elements' centres into the tile (periodic
        states; nothing in the plane). The state then holds its own elements only, in
        the order they were made."""
        if self.tile is None:
            return
        if self._ghost[: self.n].any():
            self._compact(~self._ghost[: self.n])
        own = np.flatnonzero(~self._fixed[: self.n])
        if len(own):
            x, y = canonical(self._pos[own, 0], self._pos[own, 1], self.tile)
            self._pos[own, 0] = x
            self._pos[own, 1] = y

    def wrap_discs(self, points: np.ndarray, radii: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Brush discs on the torus of a periodic state (unchanged in the plane).

        Each disc's centre is wrapped into the tile (:func:`strew._periodic.canonical`),
        and its images one tile away follow wherever the disc, widened by the largest
        neighbourhood radius (the brush wakes elements that far, §5.4), reaches into
        the tile: the generative brush then grows on both sides of an edge it crosses.

        Parameters
        ----------
        points : (m, 2) float
        radii : (m,) float

        Returns
        -------
        points, radii : (k, 2) float, (k,) float
            The wrapped discs, in order, then their images.
        """
        if self.tile is None or len(points) == 0:
            return points, radii
        x0, y0, w, h = self.tile
        cx, cy = canonical(points[:, 0], points[:, 1], self.tile)
        c = np.c_[cx, cy]
        reach = radii + float(np.max(self.prep.rbar))
        pts, rad = [c], [radii]
        for i, j in translations(3, 3):
            if i == 0 and j == 0:
                continue
            p = c + (i * w, j * h)
            hit = (p[:, 0] + reach > x0) & (p[:, 0] - reach < x0 + w) & (p[:, 1] + reach > y0) & (p[:, 1] - reach < y0 + h)
            pts.append(p[hit])
            rad.append(radii[hit])
        return np.concatenate(pts), np.concatenate(rad)

    def stroke_path(self, points: np.ndarray, reach: float = 0.0) -> Any:
        """A tool's path as a shapely geometry: the polyline (a point for one point) in
        the plane; on a periodic state the stroke wrapped into the tile, as runs and
        the copies of runs that come within ``reach`` of it
        (:func:`strew.editing.wrap_stroke`).

        Parameters
        ----------
        points : (m, 2) float
            At least one point.
        reach : float
            How far from the path the tool acts (its radius and what it wakes around).
        """
        import shapely

        def line(p: np.ndarray) -> Any:
            return shapely.LineString(p) if len(p) > 1 else shapely.Point(p[0])

        if self.tile is None:
            return line(points)
        from ..editing import wrap_stroke

        return shapely.union_all([line(r) for r in wrap_stroke(points, self.tile, reach) if len(r)])

    def wrap(self) -> int:
        """Periodic states: renew the ghost images (§5.2's frozen neighbours, one tile away).

        Drops the old ghosts, wraps the centres into the tile, leaves out elements that
        collide with another across the edges (two elements placed in one iteration on
        either side of an edge see each other only from the next one: the later goes,
        or the void of a void and a visible element), and appends a ghost for each
        image within :attr:`margin` of the tile: same exemplar element, origin and free
        space (shared flags: an image's free-space point is the same point of the
        torus), on the horizon (:func:`~strew.synth._grow.update_free_space` then
        prunes it), frozen (``fixed``) and never yielding. A ghost seeds growth into
        the tile from across the edge. Context elements (``fixed``) are not wrapped.
        :func:`~strew.synth.grow` calls this before every update of the free space and
        :meth:`unwrap` when it returns. Nothing happens in the plane.

        Returns
        -------
        int
            Elements left out for colliding across the edges.
        """
        if self.tile is None:
            return 0
        self.unwrap()
        n = self.n
        own = np.flatnonzero(~self._fixed[:n])
        if len(own) == 0:
            return 0
        prep = self.prep
        x0, y0, w, h = self.tile
        m = self.margin
        pos = self._pos[own]
        gorig, gpos = [], []
        for i, j in translations(3, 3):
            if i == 0 and j == 0:
                continue
            p = pos + (i * w, j * h)
            hit = (p[:, 0] >= x0 - m) & (p[:, 0] <= x0 + w + m) & (p[:, 1] >= y0 - m) & (p[:, 1] <= y0 + h + m)
            gorig.append(own[hit])
            gpos.append(p[hit])
        g_of = np.concatenate(gorig)
        g_pos = np.concatenate(gpos)
        dropped = 0
        if len(g_of):
            # collisions across the edges: a ghost of a within the collision bound of b
            # (Prepared.rc and min_dist, as SynthState.conflicts tests them)
            rc, sk = prep.rc[self._src[:n]], prep.skind[self._src[:n]]
            reach = max(2.0 * float(rc[own].max()), float(prep.min_dist.max()))
            lists = cKDTree(pos).query_ball_point(g_pos, r=reach)
            cnt = np.fromiter((len(v) for v in lists), np.int64, len(lists))
            if cnt.any():
                a = np.repeat(g_of, cnt)
                b = own[np.fromiter((q for v in lists for q in v), np.int64, int(cnt.sum()))]
                d = np.hypot(*(np.repeat(g_pos, cnt, axis=0) - self._pos[b]).T)
                hit = (a != b) & (d < np.maximum(rc[a] + rc[b], prep.min_dist[sk[a], sk[b]]))
                if hit.any():
                    pairs = np.unique(np.sort(np.c_[a[hit], b[hit]], axis=1), axis=0)
                    gone = np.zeros(n, bool)
                    void = prep.void[self._src[:n]]
                    for i, j in pairs.tolist():  # i < j: j is the later
                        if gone[i] or gone[j]:
                            continue
                        gone[i if void[i] and not void[j] else j] = True
                    dropped = self._compact(~gone)
                    new = np.cumsum(~gone) - 1
                    keep = ~gone[g_of]
                    g_of, g_pos = new[g_of[keep]], g_pos[keep]
        k = len(g_of)
        if k:
            self._grow_to(self.n + k)
            idx = np.arange(self.n, self.n + k)
            self._pos[idx] = g_pos
            for name in ("_src", "_origin", "_free_base"):
                arr = getattr(self, name)
                arr[idx] = arr[g_of]
            self._horizon[idx] = True
            self._born[idx] = GHOST_BORN
            self._fixed[idx] = True
            self._ghost[idx] = True
            self.n += k
        return dropped

    # -- free space (§5.1, Eq. 3) ------------------------------------------------------------
    def free_points(self, elems: np.ndarray, alive_only: bool = True) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Free-space points of ``elems``: ``F = {m_p(v) + p_o | v in free(o_e)}``.

        Returns
        -------
        pos : (f, 2) float
        r : (f,) float
            Bounding radius r_v.
        cover : (f,) float
            Cover radius.
        flag : (f,) int
            Index into the alive/failure flags.
        owner : (f,) int
            Output element.
        """
        prep = self.prep
        elems = np.asarray(elems, np.int64)
        src = self._src[elems]
        counts = prep.free_ptr[src + 1] - prep.free_ptr[src]
        owner = np.repeat(elems, counts)
        total = int(counts.sum())
        local = np.arange(total) - np.repeat(np.cumsum(counts) - counts, counts)
        rows = np.repeat(prep.free_ptr[src], counts) + local
        flag = np.repeat(self._free_base[elems], counts) + local
        if alive_only:
            keep = self._alive[flag]
            owner, rows, flag = owner[keep], rows[keep], flag[keep]
        p = self._pos[owner]
        fpos = p + map_offsets(p, prep.free_off[rows])
        return fpos, prep.free_r[rows], prep.free_cover[rows], flag, owner

    def in_domain(self, pts: np.ndarray) -> np.ndarray:
        """(n,) bool: inside the region and, while brushing, inside a brush disc."""
        ok = np.ones(len(pts), bool)
        if len(self.brush_radii) and len(pts):
            ok = K.in_discs(np.ascontiguousarray(pts, dtype=float), np.ascontiguousarray(self.brush_points, dtype=float), np.ascontiguousarray(self.brush_radii, dtype=float))
        if self.region is not None and ok.any():
            ok[ok] = self.region.contains(pts[ok])
        return ok

    def conflicts(self, pts: np.ndarray, src: np.ndarray | None, tree: cKDTree | None = None, cover: np.ndarray | None = None, r: np.ndarray | None = None, visible_only: bool = False) -> np.ndarray:
        """(m,) bool: would copies of exemplar elements ``src`` at ``pts`` intersect O?

        Two elements intersect when ``|p - q| < max(rc_p + rc_q, min_dist)`` (see
        :class:`Prepared`). With ``cover`` (m,), an output element closer than ``cover``
        also counts (free-space points, §5.1); ``r`` overrides the radii of ``src``.
        ``tree`` is accepted for symmetry and unused (a uniform grid is faster here).
        Without ``src`` (free-space points) only the discs and ``cover`` count. With
        ``visible_only``, void elements of O are ignored (§5.6 extension, see ``grow``).
        """
        if self.n == 0 or len(pts) == 0:
            return np.zeros(len(pts), bool)
        prep = self.prep
        opos, osrc = self.pos, self.src
        if visible_only:
            vis = ~prep.void[osrc]
            opos, osrc = opos[vis], osrc[vis]
            if len(osrc) == 0:
                return np.zeros(len(pts), bool)
        f = 1.0  # collision radii rc (Prepared.rc)
        rq = prep.rc[np.asarray(src, np.int64)] if r is None else np.asarray(r, float)
        rr = prep.rc[osrc]
        use_sk = src is not None
        qsk = prep.skind[np.asarray(src, np.int64)] if use_sk else np.zeros(len(pts), np.int64)
        qcover = np.zeros(len(pts)) if cover is None else np.asarray(cover, float)
        cell = f * (float(np.max(rq)) + float(rr.max()))
        if use_sk:
            cell = max(cell, float(prep.min_dist.max()))
        ext = float(np.ptp(opos, axis=0).max())
        cell = max(cell, float(qcover.max()), ext / 2000.0, 1e-9)  # bounded grid size
        return K.conflict_check(
            np.ascontiguousarray(pts, dtype=float), rq.astype(float), qsk.astype(np.int64), qcover, np.ascontiguousarray(opos), rr, prep.skind[osrc], prep.min_dist, f, use_sk, cell
        )

    # -- output ------------------------------------------------------------------------
    def to_arrangement(self, *, keep_voids: bool = False, clip: bool = True, drop_overlaps: bool = True, meta: dict | None = None) -> Arrangement:
        """The output as an arrangement.

        Parameters
        ----------
        keep_voids : bool
            Keep void elements (§5.6), flagged in the ``void`` column; by default they
            are hidden (left out).
        clip : bool
            Leave out elements whose geometry is not wholly inside the region (on a
            periodic state, see :meth:`set_tile`: whose centre is not in the region;
            positions are wrapped into the tile and ``meta["periodic"]`` is set).
        drop_overlaps : bool
            When no exemplar has overlapping shapes, leave out the later of any two
            output elements whose shapes overlap (the bounding discs of §4 do not rule
            that out for elongated shapes at new angles).
        """
        prep = self.prep
        src = self.src
        keep = np.ones(self.n, bool) if keep_voids else ~prep.void[src]
        keep &= ~self.fixed  # context elements are the caller's, not output
        cols: dict[str, Any] = {
            "radius": prep.r[src],
            "neighborhood_radius": prep.rbar[src],
            "exemplar": np.asarray(prep.names, dtype=object)[prep.source[src]],
        }
        if keep_voids:
            cols["void"] = prep.void[src]
        for name, col in prep.columns.items():
            cols[name] = col[src]
        arr = Arrangement(
            prep.shapes,
            prep.kind[src].astype(np.int64),
            self.pos[:, 0],
            self.pos[:, 1],
            prep.rotation[src],
            prep.scale[src],
            columns=cols,
            region=self.region,
            meta=meta or {},
        )
        arr = arr.select(keep)
        if self.tile is not None:
            # a repeat tile (see set_tile): centres in the tile, elements may cross its
            # edges (they wrap in at the opposite ones), overlaps count across the wrap
            from .._periodic import mark

            arr = mark(arr, self.tile)
            if clip and self.region is not None and len(arr):
                arr = arr.select(self.region.contains(arr.xy))
            if drop_overlaps and self.prep.overlap_free and len(arr) > 1:
                from ..editing import overlap_drops
                from ..metrics import wrap_overlaps

                pairs = wrap_overlaps(arr)["pairs"][:, :2]
                pairs = pairs[pairs[:, 0] != pairs[:, 1]]
                if len(pairs):
                    arr = arr.select(~overlap_drops(pairs, 0, np.ones(len(arr), bool)))
            return arr
        if clip and self.region is not None and len(arr):
            inside = self.region.contains_geometry(arr.geometry, tolerance=1e-9 * max(1.0, *map(abs, self.region.bounds)))
            arr = arr.select(inside)
        if drop_overlaps and self.prep.overlap_free and len(arr) > 1:
            from ..editing import overlap_drops
            from ..metrics import overlaps

            pairs, _ = overlaps(arr)
            if len(pairs):  # the later of two overlapping elements goes, unless the earlier went
                arr = arr.select(~overlap_drops(pairs, 0, np.ones(len(arr), bool)))
        return arr
