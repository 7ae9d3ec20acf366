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
from .._rng import as_rng
from ..arrangement import Arrangement
from ..region import Region
from . import _kernels as K
from ._prepare import Prepared

__all__ = ["SynthParams", "SynthState", "map_offsets"]

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
        a larger size class (an extension for several sizes, see ``grow``; 2).
    noise_floor : float
        Optimisation moves are shortened by the spread of the element's predictions,
        by at most this fraction of its collision radius (0.1; 0 turns it off): the
        texture's own jitter is kept, not averaged away (an extension of §5.2-5.3, see
        ``_optimize._soft_threshold``).
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
    yield_window: int = 2
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
    """

    def __init__(self, prep: Prepared, region: Region | None = None, params: SynthParams | None = None, rng: Any = None) -> None:
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
        self.grow_start = 0  # first iteration of the running grow() call
        self._flags_n = 0
        self._alive = np.zeros(1024, bool)
        self._fails = np.zeros(1024, np.int16)
        self.brush_points = np.zeros((0, 2))
        self.brush_radii = np.zeros(0)
        self.trace: list[tuple[float, int, float]] | None = None
        self.iterations = 0

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
        for name in ("_pos", "_src", "_origin", "_horizon", "_free_base", "_born", "_fixed"):
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
        k = int(keep.sum())
        removed = self.n - k
        for name in ("_pos", "_src", "_origin", "_horizon", "_free_base", "_born", "_fixed"):
            arr = getattr(self, name)
            arr[:k] = arr[: self.n][keep]
        self.n = k
        return removed

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
            Leave out elements whose geometry is not wholly inside the region.
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
