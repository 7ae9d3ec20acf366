"""Synthesis by local growth (Ijiri et al. 2008, §5).

One seed is placed; then, repeatedly, the seed nearest the initial seed is replaced by
the best matching reference element (§5.2, §5.3) and the unpaired elements of that
reference's 1-ring become new seeds (§5.4), subject to the heuristics of Fig. 6. A
windowed least-squares relaxation (§5.5) keeps ring shapes close to the reference.

Departures from the paper (each explained where it is made):

- a seed moves to where the chosen ring fits its placed neighbours best before it is
  replaced (the least-squares step of Eq. 5 for that element), so that the noise of
  near-regular rings does not add up along the growth (``_fit_position``);
- rotation mode fits centred point sets ([MHTG05]) and keeps the neighbours' frame
  within ``max_turn``; flow mode fits the rotation the same way, held within
  ``flow_max_turn`` of the field (``choose``; :func:`strew.grow.match_references`);
- the relaxation keeps each edge's reference offset, and takes the current offset only
  for edges the element's ring did not make (``ring_target``);
- Fig. 6 (b) also drops a seed or element closer to an object than the reference ever
  has their two kinds (``too_close_in_kind``), Fig. 6 (e) compares a pair the ring does
  not give with the ring's longest edge, and a small kind that leans on larger ones is
  placed only where its larger neighbour can be (``lean_ok``); an element is not placed
  nearer one of another size than the reference's smallest distance between the two
  less that distance's spread below its median (``pair_close``: pebbles crowded stones);
  in fixed mode the same holds for two elements of one kind;
- clustered exemplars (hubs ringed by satellites) grow their hubs alone and copy a
  whole reference cluster around each (:mod:`strew.grow._clusters`, §5.1 after Wong);
- elements lie wholly inside the region and off boundary strokes, and never overlap;
- grid cells come from both the spacing and the element size;
- ``tile`` (issue 18, not in the paper) grows on a torus: each object near the tile's
  edges has ghost images, translated by the tile's periods, that mirror its state, so
  that merging (Fig. 6b), matching (§5.2), the edge-collision and overlap tests and
  the relaxation see across the edges; a seed beyond the edge is made at its wrapped
  position and an edge to an image is kept at both of its ends.
"""

from __future__ import annotations

import heapq
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import shapely

from .._errors import InputError
from .._progress import Reporter
from .._rng import as_rng
from ..arrangement import Arrangement
from ..region import Region
from ._analysis import Reference, size_priority
from ._clusters import grow_clusters, satellite_structure
from ._index import GrowIndex
from ._match import MODES, W1, W2, W3, match_references, order_target
from ._relax import relax_positions

__all__ = ["GrowParams", "grow_reference"]

DEAD, SEED, ELEMENT = 0, 1, 2
#: A smaller kind leans on larger ones (see ``_Grower.lean_ok``) when 90% of its elements
#: have their nearest larger element within this factor of the median distance to it.
LEAN_SPREAD = 1.15
#: Elements the growth must not overlap but does not own (a scene the spray paints over).
OBSTACLE = 3
#: bit masks of the state tuples :meth:`_Grower.near` is asked for
_STATE_MASKS: dict[tuple[int, ...], int] = {}
_ELEMENT_OR_OBSTACLE = (1 << ELEMENT) | (1 << OBSTACLE)


@dataclass
class GrowParams:
    """Parameters of :func:`grow_reference` (validated by :func:`strew.grow.grow`)."""

    count: int | None = None
    region: Region | None = None
    start: tuple[float, float] | None = None
    start_kind: int = -1
    mode: str = "fixed"
    flow: Callable[[np.ndarray], np.ndarray] | None = None
    boundary: Sequence[np.ndarray] = ()
    spray: np.ndarray | None = None
    spray_radius: float | None = None
    priority: dict[str, float] | None = None
    jitter_scale: float = 0.0
    jitter_rotation: float = 0.0
    jitter_color: float = 0.0
    relax: bool = True
    relax_every: int = 16
    relax_hops: int = 1
    weights: tuple[float, float, float] = (W1, W2, W3)
    avoid_overlaps: bool = True
    connectivity: bool = False
    max_elements: int = 2_000_000
    #: rotation mode: weight of the neighbours' frame, per mean edge length (see
    #: :func:`strew.grow.match_references`); 0 is the paper's Eq. 4 alone
    frame_weight: float = 3.0
    #: rotation mode: the largest turn of an element's frame from its neighbours' (§5.3)
    max_turn: float = math.pi / 18
    #: flow mode: fit the rotation to the neighbours near the flow direction (see
    #: ``_Grower.choose``); False turns each reference to the flow exactly (§5.3)
    flow_fit: bool = True
    #: rotation and flow modes: a seed with fewer placed neighbours than this may also
    #: keep the neighbours' frame (or the flow direction) unturned, when that fits
    #: better than the turn (see :func:`strew.grow.match_references`); 0: never
    keep_frame: int = 3
    #: a seed moves to its fitted position only within this many l_short
    fit_reach: float = 0.5
    #: flow mode: the largest turn of an element's frame from the flow direction
    flow_max_turn: float = math.pi / 18
    #: flow mode: each ring offset of a placed element is turned further by this share
    #: of the field's turn between the element and the offset's end (``_bent_ring``)
    flow_bend: float = 0.5
    #: flow mode: carry the fitted frame on by the field's turn from the neighbours
    flow_carry: bool = True
    #: an element that would overlap may move up to this share of l_short (``_nudge``)
    nudge: float = 0.25
    #: fixed mode: ... only when at most this many slots of its ring are left without a
    #: placed neighbour (an enclosed slot; see ``place``); None: always
    nudge_open: int | None = 1
    #: clustered exemplars grow their hubs first, then each hub's satellites
    #: (:mod:`strew.grow._clusters`); off with a user's priorities or edge flips
    clusters: bool = False
    #: keep elements of one kind as far apart as the reference's smallest distance
    #: between two of them, less its spread (see ``_Grower.pair_close``); None: in
    #: fixed mode only
    own_kind_close: bool | None = None
    #: kinds of different sizes: the share of the spread of the reference's distances
    #: below their median that a placement may come nearer than their smallest (see
    #: ``_Grower.pair_close``)
    close_spread: float = 0.5
    #: a seed whose nearest element or seed of a larger kind lies farther than this
    #: quantile of the reference's distances between the two kinds first tries to become
    #: one of that kind (see ``_Grower.missing_larger``); None turns it off
    canopy_quantile: float | None = 1.0
    #: the reach of that try's fitted position, in mean edge lengths
    canopy_reach: float = 1.0
    #: torus: rounds of :meth:`_Grower.refill` after the growth stops (0: none)
    refill_rounds: int = 2
    #: a repeat tile ``(x0, y0, W, H)``: grow on the torus (issue 18; see the module
    #: docstring); None grows in the plane
    tile: tuple[float, float, float, float] | None = None


def _segments_cross(p: tuple[float, float], q: tuple[float, float], a: tuple[float, float], b: tuple[float, float]) -> bool:
    """True when segments pq and ab cross at a point interior to both."""
    ex, ey = b[0] - a[0], b[1] - a[1]
    d1 = ex * (p[1] - a[1]) - ey * (p[0] - a[0])
    d2 = ex * (q[1] - a[1]) - ey * (q[0] - a[0])
    if not ((d1 > 0 and d2 < 0) or (d1 < 0 and d2 > 0)):
        return False
    fx, fy = q[0] - p[0], q[1] - p[1]
    d3 = fx * (a[1] - p[1]) - fy * (a[0] - p[0])
    d4 = fx * (b[1] - p[1]) - fy * (b[0] - p[0])
    return (d3 > 0 and d4 < 0) or (d3 < 0 and d4 > 0)


def _skewed(p: Sequence[float], q: Sequence[float], r: Sequence[float]) -> bool:
    """True when triangle pqr has an angle of 2π/3 or more (§4's skewed triangles)."""
    a2 = (q[0] - r[0]) ** 2 + (q[1] - r[1]) ** 2
    b2 = (p[0] - r[0]) ** 2 + (p[1] - r[1]) ** 2
    c2 = (p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2
    a, b, c = math.sqrt(a2), math.sqrt(b2), math.sqrt(c2)
    # cos(angle) <= -1/2 at any vertex
    return b2 + c2 - a2 <= -b * c + 1e-12 or a2 + c2 - b2 <= -a * c + 1e-12 or a2 + b2 - c2 <= -a * b + 1e-12


def _parse_hex(c: Any) -> tuple[float, float, float] | None:
    if not isinstance(c, str) or not c.startswith("#") or len(c) not in (4, 7):
        return None
    try:
        if len(c) == 4:
            return tuple(int(ch * 2, 16) / 255 for ch in c[1:])  # type: ignore[return-value]
        return tuple(int(c[i : i + 2], 16) / 255 for i in (1, 3, 5))  # type: ignore[return-value]
    except ValueError:
        return None


class _Grower:
    def __init__(self, ref: Reference, p: GrowParams, rng: np.random.Generator) -> None:
        self.ref = ref
        self.p = p
        self.rng = rng
        ex = ref.exemplar
        self.rings = ref.ring_arrays()
        self.ref_ids = self.rings["ids"]
        self.ex_kind = ex.kind.astype(np.int64)
        self.ex_rot = ex.rotation
        self.ex_scale = ex.scale
        self.n_kinds = len(ex.kinds)
        self.l = ref.mean_edge
        self.l_short = 0.5 * ref.shortest_edge  # §5.4: half of the shortest reference edge
        self.mode_code = MODES[p.mode]
        # half the smallest centre distance between elements of two kinds in the
        # reference (see too_close_in_kind), at least l_short
        self.pair_short = np.full((self.n_kinds, self.n_kinds), self.l_short)
        from scipy.spatial import cKDTree

        dist_to: list[dict[int, np.ndarray]] = [{} for _ in range(self.n_kinds)]
        nearest_to: dict[int, np.ndarray] = {}
        for k2 in range(self.n_kinds):
            sel = np.flatnonzero(self.ex_kind == k2)
            if len(sel) == 0:
                continue
            d, q = cKDTree(ex.xy[sel]).query(ex.xy, k=2)
            nearest = np.where(sel[q[:, 0]] == np.arange(len(ex)), d[:, 1], d[:, 0])
            dist_to[k2] = {}
            nearest_to[k2] = nearest
            for k1 in range(self.n_kinds):
                m = nearest[(self.ex_kind == k1) & np.isfinite(nearest)]
                dist_to[k2][k1] = m
                if len(m):
                    self.pair_short[k1, k2] = max(self.l_short, 0.5 * float(m.min()))
        self.pair_short = np.minimum(self.pair_short, self.pair_short.T)
        self.pair_short_max = self.pair_short.max(axis=1)
        # size levels of the kinds (see lean_ok); none when all are of about one size
        lv = size_priority(ex)
        self.size_level = np.array([lv.get(k, 0.0) for k in ex.kinds])
        # the closest an element may be placed to one of a kind of another size, or of
        # its own kind (see place): the reference's smallest distance between the two,
        # less its spread below the median, at least pair_short. The rule for one kind
        # applies to the hubs of clustered exemplars
        # (``own_kind_close``) and, in fixed mode, to kinds whose nearest distances spread
        # by 5% of their median or more or exceed 1.2 l: in rotation mode each element's turn moves its
        # ring, and near-perfect lattices gain nothing from it (bricks in rotation mode
        # and scales grew less regular rows: regularity 0.044 -> 0.054, 0.046 -> 0.055).
        # (§5.4 (b) merges only within l_short, half the shortest edge: sparse kinds such
        # as cluster hubs then came to half the distance the reference ever has them,
        # and stones and stripes crowded their own kind: nn failed by a few percent.)
        self.pair_close = self.pair_short.copy()
        for k1, k2 in np.ndindex(self.n_kinds, self.n_kinds):
            if (k1 != k2 and self.size_level[k1] == self.size_level[k2]) or not dist_to[k2]:
                continue
            m = dist_to[k2][k1]
            if len(m) >= 3:
                lo, med = float(m.min()), float(np.median(m))
                # one kind: in fixed mode, where its distances spread (not a lattice) or
                # its elements lie farther apart than the rings' edges (sparse apples
                # among voids, drawn as saturated discs, came to half their distance)
                own = p.own_kind_close if p.own_kind_close is not None else (p.mode == "fixed" and (med - lo >= 0.05 * med or lo >= 1.2 * self.l))
                if k1 == k2 and not own:
                    continue
                spread = med - lo
                if k1 != k2:
                    spread *= p.close_spread
                if k1 == k2 and p.own_kind_close is None:
                    spread = max(spread, 0.05 * lo)  # saturated discs have almost none
                self.pair_close[k1, k2] = max(self.pair_short[k1, k2], lo - spread)
        self.pair_close = np.maximum(self.pair_close, self.pair_close.T)
        self.pair_close_max = self.pair_close.max(axis=1)
        # a kind "leans" on larger ones when every element of it in the reference has a
        # larger element at about one distance (dots ringed around hubs), not at any
        # distance (pebbles scattered among stones)
        self.leans = np.zeros(self.n_kinds, dtype=bool)
        for k1 in range(self.n_kinds):
            mine = np.flatnonzero(self.ex_kind == k1)
            big = np.flatnonzero(self.size_level[self.ex_kind] > self.size_level[k1])
            if len(mine) >= 3 and len(big):
                d = cKDTree(ex.xy[big]).query(ex.xy[mine])[0]
                # (the 90th percentile: an element whose larger one the frame cut off
                # must not decide it)
                self.leans[k1] = bool(np.percentile(d, 90) <= LEAN_SPREAD * np.median(d))
        self.several_sizes = bool(self.leans.any())
        # the farthest an element of one kind lies from its nearest element of a larger
        # kind in the reference (Hanisch border correction: only elements nearer to that
        # one than to the frame), per pair of kinds; inf where the reference does not say
        # (see missing_larger)
        self.reach_larger = np.full((self.n_kinds, self.n_kinds), np.inf)
        if p.canopy_quantile is not None:
            to_frame = shapely.distance(ex.region.geometry.boundary, shapely.points(ex.xy)) if ex.region is not None else np.full(len(ex), np.inf)
            for k2, nearest in nearest_to.items():
                for k1 in range(self.n_kinds):
                    if self.size_level[k2] <= self.size_level[k1]:
                        continue
                    sel = self.ex_kind == k1
                    d = nearest[sel]
                    d = d[np.isfinite(d) & (d <= to_frame[sel])]
                    if len(d) >= 5:
                        self.reach_larger[k1, k2] = float(np.quantile(d, p.canopy_quantile))
        self.canopy = bool(np.isfinite(self.reach_larger).any())
        # per-reference: angular gaps of the ring, mean ring edge length
        n_ref = len(self.ref_ids)
        self.ring_gap_min = []  # (k,) smallest of the two gaps beside each ring slot
        self.ring_edge_mean = np.zeros(n_ref)
        self.ring_edge_max = np.zeros(n_ref)
        all_gaps = []
        for a in range(n_ref):
            k = int(self.rings["n"][a])
            rel = self.rings["rel"][a, :k]
            ang = np.arctan2(rel[:, 1], rel[:, 0])
            gaps = np.mod(np.diff(np.r_[ang, ang[0]]), 2 * np.pi)  # gap after slot j
            self.ring_gap_min.append(np.minimum(gaps, np.roll(gaps, 1)).tolist())
            all_gaps.append(gaps)
            ring_edges = np.linalg.norm(rel - np.roll(rel, -1, axis=0), axis=1)
            self.ring_edge_mean[a] = float(ring_edges.mean())
            self.ring_edge_max[a] = float(ring_edges.max())
        # torus: an angular gap between placed neighbours wider than this splits them
        # into arcs (see choose)
        self.arc_gap = 1.5 * float(np.median(np.concatenate(all_gaps))) if all_gaps else math.pi
        ref_kind = self.ex_kind[self.ref_ids]
        self.kind_candidates = [ref_kind == k for k in range(self.n_kinds)]
        self.kind_has_candidates = [bool(c.any()) for c in self.kind_candidates]
        self.all_candidates = np.ones(n_ref, dtype=bool)
        # priorities (§5.1)
        prio = np.zeros(self.n_kinds)
        for name, v in (p.priority or {}).items():
            prio[ex.kinds.index(name)] = v
        self.kind_prio = prio
        self.use_prio = bool(prio.max() > prio.min())
        # seeds above the lowest priority, on a grid of cells 5 l wide (see outranked);
        # placed and dead ones are dropped as they go
        self.hcell = max(5 * self.l, 1e-9)
        self.hgrid: dict[tuple[int, int], set[int]] = {}
        self.none_prio = float(prio.min())
        self.kind_prio_list = [float(v) for v in prio]
        # geometry for the overlap guard
        self.local_geom = [ex.shapes[k].geometry for k in ex.kinds]
        self.local_coords = [None] * self.n_kinds
        # exterior rings of kinds that are simple polygons (fast path of element_geometry)
        self.local_ring = [
            shapely.get_coordinates(g.exterior) if g.geom_type == "Polygon" and len(g.interiors) == 0 and not g.has_z else None for g in self.local_geom
        ]
        self.kind_radius = np.array([max(ex.shapes[k].radius, 0.0) for k in ex.kinds])
        self.areal = [not g.is_empty and g.area > 0 for g in self.local_geom]
        # colours (§3: per-element colour variation)
        base = ex.columns.get("color")
        self.ex_color: list[Any] = []
        for i in range(len(ex)):
            c = base[i] if base is not None and base.ndim == 1 else None
            if c is None:
                c = ex.shapes[ex.kinds[ex.kind[i]]].style.get("fill")
            self.ex_color.append(c)
        self.want_color = p.jitter_color > 0 or base is not None
        # state
        cap = 1024
        self.pos = np.zeros((cap, 2))
        self.state = np.zeros(cap, dtype=np.int8)
        self.kind = np.full(cap, -1, dtype=np.int64)
        self.sub = np.full(cap, -1, dtype=np.int64)
        self.rot = np.zeros(cap)
        self.scl = np.ones(cap)
        self.fixed = np.zeros(cap, dtype=bool)
        self.refslot = np.full(cap, -1, dtype=np.int64)  # reference row of each element
        self.frame = np.zeros(cap)  # rotation of the reference ring each element copies (§5.3)
        self.n = 0
        # periodic tiles: the original of each object (itself but for ghost images), the
        # image's tile offset, and the ghosts of each original by offset
        self.tile = p.tile
        self.orig_of: list[int] = []
        self.off_of: list[tuple[int, int]] = []
        self.ghosts: dict[int, dict[tuple[int, int], int]] = {}
        self.margin = 0.0
        self.target: list[dict[int, tuple[float, float]] | None] = []  # ring offsets r_ji
        self.geom: list[Any] = []
        self.color: list[Any] = []
        self.order: list[int] = []  # elements in placement order
        # Grid cells from both the spacing and the element size: the overlap guard looks
        # up a disc of about twice the largest element radius, the growth one of l_short
        # to 5 l. (Cells from the spacing alone make each lookup walk (r / l)^2 cells:
        # 10^8 for elements of radius 89 spaced 0.01 apart.)
        self.cell = max(self.l, 0.5 * float(self.kind_radius.max()), 1e-9)
        self.rep: Reporter | None = None  # polled for cancellation in the inner loops
        self.xy: list[tuple[float, float]] = []  # pos as Python floats, for the scalar hot paths
        # the point and edge grids and the connectivity (adj, edges): :mod:`._index`
        self.index = GrowIndex(self.cell, self.pos, self.state, self.xy)
        self.adj: list[set[int]] = self.index.adj
        self.edges: set[tuple[int, int]] = self.index.edges
        self.heap: list[tuple[float, int]] = []
        self.deferred: set[int] = set()
        self._out_of_domain = False  # the last place() refused an element across the domain's edge
        #: the largest reference ring a seed of each kind (-1: any) can be matched to
        self._ring_max: dict[int, int] = {}
        #: flow mode: the field's angle at each element where it was placed
        self._flow_at: dict[int, float] = {}
        self.origin = (0.0, 0.0)
        # tools
        self.region = p.region
        self.region_box: tuple[float, float, float, float] | None = None
        if p.region is not None:
            rg = p.region.geometry
            if rg.geom_type == "Polygon" and len(rg.interiors) == 0 and bool(shapely.equals(rg, rg.envelope)):
                self.region_box = tuple(float(v) for v in rg.bounds)  # type: ignore[assignment]
        self.boundary = None
        if p.boundary:
            lines = [shapely.LineString(b) for b in p.boundary if len(b) >= 2]
            if lines:
                self.boundary = shapely.MultiLineString(lines)
                shapely.prepare(self.boundary)
        self.spray_area = None
        if p.spray is not None:
            sp = np.asarray(p.spray, dtype=float)
            g = shapely.LineString(sp) if len(sp) >= 2 else shapely.Point(sp[0])
            self.spray_area = g.buffer(float(p.spray_radius))
            shapely.prepare(self.spray_area)
        self.dirty: set[int] = set()
        self.steps_since_relax = 0
        self.ring_n: dict[int, int] = {}
        self.max_scale = 1.0
        self.other_rmax = float(self.kind_radius.max())  # bounding radius of any element or obstacle
        self._last_nb = np.zeros(0, dtype=np.int64)
        # incremental spray (see :class:`strew.grow.SprayGrowth`): seeds outside the spray
        # area wait here instead of being dropped, and grow once the cursor reaches them
        self.waiting: list[int] | None = None
        self.s0 = -1
        self.first = True
        # incremental spray: elements are held (Eq. 6) after the relaxation window that
        # follows their placement, so pausing at a window changes nothing
        self.freeze_relaxed = False

    # -- storage ------------------------------------------------------------------------
    def _grow_capacity(self) -> None:
        cap = 2 * len(self.state)
        for name in ("pos", "state", "kind", "sub", "rot", "scl", "fixed", "refslot", "frame"):
            old = getattr(self, name)
            new = np.zeros((cap, *old.shape[1:]), dtype=old.dtype)
            if name in ("kind", "sub", "refslot"):
                new[:] = -1
            if name == "scl":
                new[:] = 1.0
            new[: len(old)] = old
            setattr(self, name, new)
        self.index.rebind(self.pos, self.state)

    def _cell(self, x: float, y: float) -> tuple[int, int]:
        return self.index.cell_of(x, y)

    def new_object(self, x: float, y: float, kind: int) -> int:
        """A new seed at (x, y); on a torus, the image at (x, y) of a seed made at its wrapped place."""
        if self.tile is not None:
            x0, y0, w, h = self.tile
            ki, kj = math.floor((x - x0) / w), math.floor((y - y0) / h)
            i = self._new_object(x - ki * w, y - kj * h, kind)
            self._ensure_ghosts(i)
            return self.image(i, (ki, kj))
        return self._new_object(x, y, kind)

    def _new_object(self, x: float, y: float, kind: int) -> int:
        if self.n == len(self.state):
            self._grow_capacity()
        i = self.n
        self.n += 1
        self.pos[i] = (x, y)
        self.xy.append((float(x), float(y)))
        self.state[i] = SEED
        self.kind[i] = kind
        self.adj.append(set())
        self.target.append(None)
        self.geom.append(None)
        self.color.append(None)
        self.orig_of.append(i)
        self.off_of.append((0, 0))
        self.index.insert(i, x, y)
        heapq.heappush(self.heap, (math.hypot(x - self.origin[0], y - self.origin[1]), i))
        self.dirty.add(i)
        if self.use_prio and self.seed_priority(i) > self.none_prio:
            self.hgrid.setdefault((math.floor(x / self.hcell), math.floor(y / self.hcell)), set()).add(i)
        return i

    # -- torus (issue 18) ------------------------------------------------------------------
    def image(self, i: int, off: tuple[int, int]) -> int:
        """The ghost of original ``i`` translated by ``off`` tile periods (made on demand).

        A ghost mirrors its original's state (:meth:`_sync`), is held fixed by the
        relaxation and never grows itself: only originals are on the heap.
        """
        if off == (0, 0):
            return i
        own = self.ghosts.setdefault(i, {})
        g = own.get(off)
        if g is not None:
            return g
        assert self.tile is not None
        _, _, w, h = self.tile
        if self.n == len(self.state):
            self._grow_capacity()
        g = self.n
        self.n += 1
        x, y = self.xy[i]
        gx, gy = x + off[0] * w, y + off[1] * h
        self.pos[g] = (gx, gy)
        self.xy.append((gx, gy))
        self.fixed[g] = True
        self.adj.append(set())
        self.target.append(None)
        self.geom.append(None)
        self.color.append(None)
        self.orig_of.append(i)
        self.off_of.append(off)
        own[off] = g
        self._copy_state(i, g)
        if self.state[g] != DEAD:
            self.index.insert(g, gx, gy)
        # a seed of a higher priority holds back the seeds around its images too (§5.1)
        if self.state[g] == SEED and self.use_prio and self.seed_priority(g) > self.none_prio:
            self.hgrid.setdefault((math.floor(gx / self.hcell), math.floor(gy / self.hcell)), set()).add(g)
        return g

    def _copy_state(self, i: int, g: int) -> None:
        for a in (self.state, self.kind, self.sub, self.rot, self.scl, self.refslot, self.frame):
            a[g] = a[i]
        self.color[g] = self.color[i]
        gi = self.geom[i]
        if gi is None:
            self.geom[g] = None
        else:
            dx, dy = self.xy[g][0] - self.xy[i][0], self.xy[g][1] - self.xy[i][1]
            self.geom[g] = shapely.transform(gi, lambda q: q + (dx, dy))

    def _sync(self, i: int) -> None:
        """Ghosts of ``i`` take its state (placed, died, new outline)."""
        for g in self.ghosts.get(i, {}).values():
            was = self.state[g]
            self._copy_state(i, g)
            if self.state[g] == DEAD and was != DEAD:
                self.index.remove(g)

    def _ensure_ghosts(self, i: int) -> None:
        """Ghosts of original ``i`` wherever one lies within the margin of the tile."""
        x0, y0, w, h = self.tile  # type: ignore[misc]
        m = self.margin
        x, y = self.xy[i]
        for ki in (-1, 0, 1):
            px = x + ki * w
            if px < x0 - m or px > x0 + w + m:
                continue
            for kj in (-1, 0, 1):
                py = y + kj * h
                if (ki or kj) and y0 - m <= py <= y0 + h + m:
                    self.image(i, (ki, kj))

    def has_edge(self, a: int, b: int) -> bool:
        if self.tile is None:
            return b in self.adj[a]
        ia, ib = self.orig_of[a], self.orig_of[b]
        oa, ob = self.off_of[a], self.off_of[b]
        g = self.ghosts.get(ib, {}).get((ob[0] - oa[0], ob[1] - oa[1])) if ob != oa else ib
        return g is not None and g in self.adj[ia]

    def near(self, x: float, y: float, r: float, states: tuple[int, ...] = (SEED, ELEMENT)) -> list[int]:
        """Objects within ``r`` of (x, y) in one of ``states`` (:meth:`GrowIndex.near`)."""
        m = _STATE_MASKS.get(states)
        if m is None:
            m = _STATE_MASKS[states] = sum(1 << s for s in set(states))
        return self.index.near(x, y, r, m)

    def _unhigh(self, i: int) -> None:
        """Take seed ``i`` off the priority grid (it was placed, died or moves)."""
        if self.hgrid:
            x, y = self.xy[i]
            cell = self.hgrid.get((math.floor(x / self.hcell), math.floor(y / self.hcell)))
            if cell is not None:
                cell.discard(i)
            for g in self.ghosts.get(i, {}).values():
                self._unhigh(g)

    def _move(self, i: int, x: float, y: float) -> None:
        if self.hgrid and self.state[i] == SEED:
            h = self.hcell
            ox, oy = self.xy[i]
            a, b = (math.floor(ox / h), math.floor(oy / h)), (math.floor(x / h), math.floor(y / h))
            if a != b and i in self.hgrid.get(a, ()):
                self.hgrid[a].discard(i)
                self.hgrid.setdefault(b, set()).add(i)
        ox, oy = self.xy[i]
        self.pos[i] = (x, y)
        self.xy[i] = (float(x), float(y))
        self.index.move(i, ox, oy, x, y)  # a new cell: its edges are listed there too
        if self.tile is not None and self.orig_of[i] == i:
            _, _, w, h = self.tile
            for (ki, kj), g in list(self.ghosts.get(i, {}).items()):
                self._move(g, x + ki * w, y + kj * h)
            self._ensure_ghosts(i)

    # -- edges --------------------------------------------------------------------------
    def add_edge(self, a: int, b: int) -> None:
        if self.tile is not None:
            # on the torus an edge is kept at both ends: from each original to the image
            # of the other
            ia, ib = self.orig_of[a], self.orig_of[b]
            if ia == ib:
                return
            oa, ob = self.off_of[a], self.off_of[b]
            rel = (ob[0] - oa[0], ob[1] - oa[1])
            self._add_edge(ia, self.image(ib, rel))
            if rel != (0, 0):
                self._add_edge(self.image(ia, (-rel[0], -rel[1])), ib)
            return
        self._add_edge(a, b)

    def _add_edge(self, a: int, b: int) -> None:
        self.index.add_edge(a, b, self.orig_of[a], self.orig_of[b])

    def remove_edge(self, a: int, b: int) -> None:
        if self.tile is not None:
            ia, ib = self.orig_of[a], self.orig_of[b]
            oa, ob = self.off_of[a], self.off_of[b]
            rel = (ob[0] - oa[0], ob[1] - oa[1])
            pairs = [(ia, self.ghosts.get(ib, {}).get(rel) if rel != (0, 0) else ib)]
            if rel != (0, 0):
                pairs.append((self.ghosts.get(ia, {}).get((-rel[0], -rel[1])), ib))
            for u, v in pairs:
                if u is not None and v is not None:
                    self._remove_edge(u, v)
            return
        self._remove_edge(a, b)

    def _remove_edge(self, a: int, b: int) -> None:
        self.index.remove_edge(a, b)

    def crosses_edges(self, a: int | None, pa: tuple[float, float], b: int | None, pb: tuple[float, float]) -> bool:
        """Edge collision (§5.4, Fig. 6d): does segment pa-pb cross an existing edge?

        Edges at ``a`` or ``b`` (on the torus: at any of their images) do not count.
        """
        oo = self.orig_of
        return self.index.crosses(-2 if a is None else oo[a], pa, -2 if b is None else oo[b], pb, self.tile, self.margin)

    def crosses_boundary(self, pa: Sequence[float], pb: Sequence[float]) -> bool:
        if self.boundary is None:
            return False
        return bool(shapely.intersects(self.boundary, shapely.LineString([pa, pb])))

    def kill(self, i: int) -> None:
        self._unhigh(i)
        for j in list(self.adj[i]):
            self.remove_edge(i, j)
        self.state[i] = DEAD
        self.deferred.discard(i)
        # the dead take no part in any query: off the grid, so that queries stay short
        self.index.remove(i)
        if self.tile is not None:
            self._sync(i)

    # -- geometry guard -----------------------------------------------------------------
    def element_geometry(self, kind: int, x: float, y: float, rot: float, scale: float) -> Any:
        local = self.local_geom[kind]
        m = np.array([[math.cos(rot) * scale, -math.sin(rot) * scale], [math.sin(rot) * scale, math.cos(rot) * scale]])
        t = np.array([x, y])
        ring = self.local_ring[kind]
        if ring is not None:  # a simple polygon: the same coordinates, built directly
            return shapely.polygons(ring @ m.T + t)
        return shapely.transform(local, lambda q: q @ m.T + t)

    def element_geometries(self, idx: Sequence[int], xy: np.ndarray) -> list[Any]:
        """Outlines of elements ``idx`` moved to ``xy`` (m, 2), batched by kind."""
        out: list[Any] = [None] * len(idx)
        idx_a = np.asarray(idx, dtype=np.intp)
        kinds = self.kind[idx_a]
        for kind in np.unique(kinds).tolist():
            sel = np.flatnonzero(kinds == kind)
            ring = self.local_ring[kind]
            if ring is None:
                for q in sel.tolist():
                    g = int(idx_a[q])
                    out[q] = self.element_geometry(kind, float(xy[q, 0]), float(xy[q, 1]), self.rot[g], self.scl[g])
                continue
            gi = idx_a[sel]
            c = np.cos(self.rot[gi]) * self.scl[gi]
            s = np.sin(self.rot[gi]) * self.scl[gi]
            px = c[:, None] * ring[None, :, 0] - s[:, None] * ring[None, :, 1] + xy[sel, 0][:, None]
            py = s[:, None] * ring[None, :, 0] + c[:, None] * ring[None, :, 1] + xy[sel, 1][:, None]
            polys = shapely.polygons(np.stack([px, py], axis=-1))
            for q, g in zip(sel.tolist(), polys):
                out[q] = g
        return out

    def overlaps_any(self, g: Any, kind: int, x: float, y: float, scale: float, skip: set[int] | None = None) -> bool:
        r = self.kind_radius[kind] * scale + self.other_rmax
        # bounding discs: an element farther than the sum of the two radii cannot touch
        # (obstacles have no kind of ours), so it skips the shapely test
        kr = self.kind_radius
        nk = len(kr)
        rg = float(kr[kind]) * abs(scale)
        xy, kinds, state, scl = self.xy, self.kind, self.state, self.scl
        others = []
        for j in self.near(x, y, r, (ELEMENT, OBSTACLE)):
            if skip and j in skip:
                continue
            if state[j] == ELEMENT:
                kj = kinds[j]
                if kj < nk:
                    reach = (rg + float(kr[kj]) * abs(float(scl[j]))) * (1.0 + 1e-9)
                    px, py = xy[j]
                    if (px - x) ** 2 + (py - y) ** 2 > reach * reach:
                        continue
            others.append(j)
        if not others:
            return False
        gs = np.array([self.geom[j] for j in others], dtype=object)
        hit = shapely.intersects(g, gs)
        if not hit.any():
            return False
        if not self.areal[kind]:
            return True
        for j in np.flatnonzero(hit):
            if not self.areal[self.kind[others[j]]]:
                return True
            if shapely.intersection(g, gs[j]).area > 1e-9 * max(g.area, 1e-300):
                return True
        return False

    def overlapping(self, g: int) -> list[int]:
        """Elements whose geometry overlaps element ``g`` (area overlap, or any contact of strokes)."""
        kind = int(self.kind[g])
        x, y = self.xy[g]
        r = self.kind_radius[kind] * self.scl[g] + self.other_rmax
        others = [j for j in self.near(x, y, r, (ELEMENT, OBSTACLE)) if self.orig_of[j] != g]
        if not others:
            return []
        geom = self.geom[g]
        gs = np.array([self.geom[j] for j in others], dtype=object)
        hit = np.flatnonzero(shapely.intersects(geom, gs))
        out = []
        for q in hit:
            j = others[q]
            if not (self.areal[kind] and self.areal[self.kind[j]]):
                out.append(j)
            elif shapely.intersection(geom, gs[q]).area > 1e-9 * max(geom.area, 1e-300):
                out.append(j)
        return out

    def overlapping_many(self, check: Sequence[int]) -> dict[int, list[int]]:
        """:meth:`overlapping` for several elements, with one vectorised shapely call."""
        out: dict[int, list[int]] = {}
        ca = np.asarray(check, dtype=np.int64)
        if len(ca) == 0:
            return out
        # the candidates of every element in one query of the index
        kr = self.kind_radius
        nk = len(kr)
        rg = kr[self.kind[ca]] * self.scl[ca]
        pos = self.pos
        qi, js = self.index.near_many(pos[ca, 0], pos[ca, 1], rg + self.other_rmax, _ELEMENT_OR_OBSTACLE)
        gs = ca[qi]
        keep = js != gs
        if self.tile is not None:  # not an image of the element itself
            oo = self.orig_of
            keep &= np.fromiter((oo[j] != g for j, g in zip(js.tolist(), gs.tolist())), dtype=bool, count=len(js))
        # bounding radius of each element: pairs farther apart than the sum of theirs
        # cannot touch, and skip the shapely test (obstacles have no kind of ours)
        kj = self.kind[js]
        el = (self.state[js] == ELEMENT) & (kj < nk)
        reach = (rg[qi] + kr[np.where(el, kj, 0)] * self.scl[js]) * (1.0 + 1e-9)
        d2 = (pos[js, 0] - pos[gs, 0]) ** 2 + (pos[js, 1] - pos[gs, 1]) ** 2
        keep &= ~(el & (d2 > reach * reach))
        ga: list[int] = gs[keep].tolist()
        gb: list[int] = js[keep].tolist()
        if not ga:
            return out
        geoms = self.geom
        A = np.array([geoms[g] for g in ga], dtype=object)
        B = np.array([geoms[j] for j in gb], dtype=object)
        hit = np.flatnonzero(shapely.intersects(A, B))
        if len(hit) == 0:
            return out
        areal = self.areal
        both = np.array([areal[self.kind[ga[q]]] and areal[self.kind[gb[q]]] for q in hit], dtype=bool)
        keep = ~both
        if both.any():
            hb = hit[both]
            area = shapely.area(shapely.intersection(A[hb], B[hb]))
            keep[both] = area > 1e-9 * np.maximum(shapely.area(A[hb]), 1e-300)
        for q in hit[keep].tolist():
            out.setdefault(ga[q], []).append(gb[q])
        return out

    # -- growth -------------------------------------------------------------------------
    def seed_priority(self, i: int) -> float:
        # Extra seeds (no symbol id, §5.4e) take the lowest priority: they fill gaps.
        k = self.kind[i]
        return self.none_prio if k < 0 else float(self.kind_prio[k])

    def outranked(self, i: int) -> bool:
        """§5.1: grow only seeds of the highest priority within 5 * l."""
        if not self.use_prio:
            return False
        pi = self.seed_priority(i)
        x, y = self.xy[i]
        r2 = (5 * self.l) ** 2
        xy = self.xy
        # the live seeds above the lowest priority, on a grid of cells 5 l wide: nine
        # cells to look at instead of the hundred of the fine grid
        h = self.hcell
        cx, cy = math.floor(x / h), math.floor(y / h)
        hg = self.hgrid
        kind = self.kind
        state = self.state
        kp = self.kind_prio_list
        none = self.none_prio
        oo = self.orig_of
        for j in [j for dx in (-1, 0, 1) for dy in (-1, 0, 1) for j in hg.get((cx + dx, cy + dy), ())]:
            if j == i or oo[j] == i or state[j] != SEED:
                continue
            kj = kind[j]
            if (none if kj < 0 else kp[kj]) <= pi:  # seed_priority(j), inlined
                continue
            px, py = xy[j]
            if (px - x) ** 2 + (py - y) ** 2 > r2:
                continue
            # a seed outside the spray area cannot grow now: it does not hold others
            # back (they would wait for it, and the spray would stall)
            if self.spray_area is not None and not shapely.contains_xy(self.spray_area, px, py):
                continue
            return True
        return False

    def release_deferred(self, i: int) -> None:
        if not self.deferred:
            return
        x, y = self.xy[i]
        r2 = (5 * self.l) ** 2
        xy = self.xy
        if self.tile is not None:  # on the torus: the nearest images
            _, _, w, h = self.tile
            near = [j for j in self.deferred if self.state[j] == SEED
                    and (d := (xy[j][0] - x - w * round((xy[j][0] - x) / w), xy[j][1] - y - h * round((xy[j][1] - y) / h)))
                    and d[0] ** 2 + d[1] ** 2 <= r2]
        else:
            near = [j for j in self.deferred if (xy[j][0] - x) ** 2 + (xy[j][1] - y) ** 2 <= r2 and self.state[j] == SEED]
        for j in sorted(near):
            if j in self.deferred:
                self.deferred.discard(j)
                heapq.heappush(self.heap, (math.hypot(self.xy[j][0] - self.origin[0], self.xy[j][1] - self.origin[1]), j))

    def in_domain(self, x: float, y: float) -> bool:
        if self.tile is not None:
            return True  # the torus has no edge: a seed beyond the tile is made at its wrapped place
        box = self.region_box
        if box is not None:  # a rectangular region: the same test without shapely
            return box[0] < x < box[2] and box[1] < y < box[3]
        if self.region is not None and not shapely.contains_xy(self.region.prepared, x, y):
            return False
        return True

    def too_close_in_kind(self, x: float, y: float, kind: int, s: int, states: tuple[int, ...] = (SEED, ELEMENT), placing: bool = False) -> bool:
        """Is an object within ``l_short(kind, kind')`` of a new seed of ``kind`` at (x, y)?

        §5.4 (b) takes one ``l_short`` for all kinds: half the shortest reference edge.
        With kinds far apart in the reference (cluster hubs, large stones) a seed that
        lands at twice that from an element of its own kind, where the reference never
        has one, survives, and hubs double up. We also drop a new seed that lies within
        half the reference's smallest distance between its kind and the object's kind
        (:attr:`pair_short`); objects within the global ``l_short`` are merged as before.
        """
        if kind < 0:
            return False
        ps = self.pair_close if placing else self.pair_short
        r = float((self.pair_close_max if placing else self.pair_short_max)[kind])
        if r <= self.l_short:
            return False
        xy = self.xy
        for o in self.near(x, y, r, states):
            if self.orig_of[o] == s:
                continue
            ko = int(self.kind[o])
            if ko < 0:
                continue
            d = ps[kind, ko]
            px, py = xy[o]
            if (px - x) ** 2 + (py - y) ** 2 < d * d:
                return True
        return False

    def lean_ok(self, s: int, a: int, k: int, th: float, x: float, y: float, kind: int) -> bool:
        """Will the element have the larger neighbour its reference ring has beside it?

        Not in the paper. With kinds of several sizes a smaller element may sit where the
        reference has it because of a larger one next to it (dots ringed around a hub:
        a kind that :attr:`leans`). §5.4 places the small element first and the larger
        one as a seed afterwards; where that seed cannot grow the small element is left
        alone, and clusters dissolve into scattered dots. The placement is refused when
        the nearest larger neighbour of reference ``a``'s ring (at distance ``d``) has no
        counterpart: no element or seed of its kind within ``1.25 d`` of the seed, and
        its own place is outside the region, overlaps an element or is too close to one
        (:meth:`too_close_in_kind`).
        """
        if not self.leans[kind]:
            return True
        lv = self.size_level
        n_ring = int(self.rings["n"][a])
        ring_kind = self.rings["kind"][a, :n_ring]
        bigger = np.flatnonzero((ring_kind >= 0) & (lv[np.maximum(ring_kind, 0)] > lv[kind]))
        if len(bigger) == 0:
            return True
        big_slots = set(bigger.tolist())
        if any((k + i) % n_ring in big_slots for i in range(len(self._last_nb))):
            return True  # a target neighbour stands for it
        rel = self.rings["rel"][a]
        dist = np.hypot(rel[bigger, 0], rel[bigger, 1])
        j = int(bigger[int(np.argmin(dist))])
        kj = int(ring_kind[j])
        reach = 1.25 * float(dist.min())
        if any(int(self.kind[o]) == kj for o in self.near(x, y, reach) if self.orig_of[o] != s):
            return True
        c, sn = math.cos(th), math.sin(th)
        px = x + c * rel[j, 0] - sn * rel[j, 1]
        py = y + sn * rel[j, 0] + c * rel[j, 1]
        if not self.in_domain(px, py) or self.too_close_in_kind(px, py, kj, s):
            return False
        r = int(self.rings["sub"][a, j])
        sc = float(self.ex_scale[r])
        g = self.element_geometry(kj, px, py, float(self.ex_rot[r]) + th, sc)
        return self.fits_domain(g) and not (self.p.avoid_overlaps and self.overlaps_any(g, kj, px, py, sc))

    def fits_domain(self, g: Any) -> bool:
        """Does element geometry ``g`` lie inside the region and cross no boundary stroke?"""
        box = self.region_box if self.tile is None else None
        if box is not None:
            b = shapely.bounds(g)
            if not (b[0] >= box[0] and b[1] >= box[1] and b[2] <= box[2] and b[3] <= box[3]):
                return False
        elif self.region is not None and self.tile is None and not shapely.contains(self.region.prepared, g):
            return False
        if self.boundary is not None and shapely.intersects(self.boundary, g):
            return False
        return True

    def fits_domain_many(self, gs: Sequence[Any]) -> np.ndarray:
        """:meth:`fits_domain` of several geometries (m,), with one shapely call each; (m,) bool."""
        arr = np.empty(len(gs), dtype=object)
        arr[:] = gs
        ok = np.ones(len(gs), dtype=bool)
        box = self.region_box
        if self.tile is not None:
            pass  # on the torus an element may cross the tile's edge
        elif box is not None:
            b = shapely.bounds(arr)
            ok &= (b[:, 0] >= box[0]) & (b[:, 1] >= box[1]) & (b[:, 2] <= box[2]) & (b[:, 3] <= box[3])
        elif self.region is not None:
            ok &= shapely.contains(self.region.prepared, arr)
        if self.boundary is not None:
            ok &= ~shapely.intersects(self.boundary, arr)
        return ok

    def missing_larger(self, s: int) -> list[int]:
        """Larger kinds with no element or seed where the reference always has one.

        Not in the paper. With kinds of several sizes (stones ringed by pebbles) the
        larger ones come only from the rings of placed elements (§5.4); where their seeds
        die (overlaps, the priority wait of §5.1) no ring proposes another, and the small
        ones fill a gap in the larger kind that the reference never has: three sizes grew
        small stones up to 30 units from the nearest large one where the reference has at
        most 23. A seed of kind ``a`` that has no element or seed of a larger kind ``b``
        within :attr:`reach_larger` ``[a, b]`` (a quantile of the reference's distances
        from ``a`` to its nearest ``b``) is first tried as a ``b`` (largest kind first).
        """
        k = int(self.kind[s])
        if k < 0:
            return []  # an extra seed of Fig. 6e fills a gap; it has no kind to miss a larger one
        row = self.reach_larger[k]
        want = np.flatnonzero(np.isfinite(row))
        if len(want) == 0:
            return []
        x, y = self.xy[s]
        r = float(row[want].max())
        have = set()
        for o in self.near(x, y, r):
            b = int(self.kind[o])
            if self.orig_of[o] != s and b >= 0 and (self.xy[o][0] - x) ** 2 + (self.xy[o][1] - y) ** 2 <= row[b] ** 2:
                have.add(b)
        out = [int(b) for b in want if int(b) not in have]
        out.sort(key=lambda b: -self.size_level[b])
        return out

    def choose(self, s: int) -> tuple[int, int, float] | None:
        """§5.2: the reference element minimising Eq. 3 for seed ``s``."""
        # §5.2: w(e_tar) are the seed's immediate neighbours. We take the placed elements
        # among them only: seeds have no sub-id yet and their positions are guesses.
        nb = [j for j in self.adj[s] if self.state[j] == ELEMENT]
        ps = self.pos[s]
        if nb:
            rel = self.pos[nb] - ps
            order = order_target(rel)
            nb_arr = np.asarray(nb)[order]
            rel = rel[order]
            if self.tile is not None and len(nb_arr) >= 3:
                nb_arr, rel = self._one_arc(nb_arr, rel)
        else:
            nb_arr = np.zeros(0, dtype=np.int64)
            rel = np.zeros((0, 2))
        k = self.kind[s]
        cand = self.all_candidates
        if k >= 0 and self.kind_has_candidates[k]:
            # §5.2: a seed with a symbol id examines only references of that id. A kind that
            # occurs only on the exemplar's boundary has no reference: any element may go.
            cand = self.kind_candidates[k]
        n_max = self._ring_max.get(int(k))
        if n_max is None:
            n_max = self._ring_max[int(k)] = int(self.rings["n"][cand].max()) if cand.any() else 0
        if 0 < n_max < len(nb_arr):
            # Not in the paper: a seed that waited (§5.1 priority) or sits where fronts
            # meet can be joined to more placed neighbours than any reference ring has,
            # and then matched none and died, leaving a hole (bricks with a priority: one
            # brick missing). Its nearest n_max neighbours are matched.
            near = np.sort(np.argsort(np.hypot(rel[:, 0], rel[:, 1]), kind="stable")[:n_max])
            nb_arr, rel = nb_arr[near], rel[near]
            order = order_target(rel)
            nb_arr, rel = nb_arr[order], rel[order]
        flow_theta = 0.0
        if self.mode_code == 2:
            v = self.p.flow(ps[None, :])[0]
            flow_theta = math.atan2(v[1], v[0])
        frame_theta, frame_w = 0.0, 0.0
        mode = self.p.mode
        if self.mode_code == 1 and len(nb_arr):
            # the neighbours' reference frames (their Eq. 4 rotations), circular mean
            f = self.frame[nb_arr]
            frame_theta = math.atan2(float(np.sin(f).sum()), float(np.cos(f).sum()))
            frame_w = self.p.frame_weight * self.l
        elif self.mode_code == 2 and self.p.flow_fit:
            # §5.3 turns the reference to the flow direction exactly. We fit the rotation
            # to the placed neighbours as in rotation mode, held within max_turn of the
            # flow direction and charged for the turn away from it: where the field bends
            # the neighbours' lattice then bends with it gradually, instead of each
            # element taking the field's angle and leaving holes and overlaps between
            # neighbours that took different ones.
            frame_theta, frame_w, mode = flow_theta, self.p.frame_weight * self.l, "rotate"
            if len(nb_arr) and self.p.flow_carry:
                # Not in the paper: the fit alone keeps the neighbours' frame, so the
                # lattice lags the field by max_turn, ahead of the field where growth
                # runs against its turn and behind it where growth runs with it; the
                # two meet in seams. The fitted frame is carried on by the field's turn
                # from the neighbours to the seed (the target is turned by it before the
                # fit): the lattice turns with the field.
                # the field at each neighbour where it was placed (``_bent_ring``)
                fa = self._flow_at
                va = np.array([fa[j] if j in fa else math.nan for j in nb_arr.tolist()])
                miss = np.isnan(va)
                if miss.any():
                    v = np.asarray(self.p.flow(self.pos[nb_arr[miss]]), dtype=float)
                    va[miss] = np.arctan2(v[:, 1], v[:, 0])
                # a line field: the neighbours' mean direction with the seed's sign
                dd = va - flow_theta
                dd = dd - np.pi * np.round(dd / np.pi)
                carry = -float(np.mean(dd))
                if abs(carry) > 1e-12:
                    cc, ss = math.cos(carry), math.sin(carry)
                    rel = np.c_[cc * rel[:, 0] - ss * rel[:, 1], ss * rel[:, 0] + cc * rel[:, 1]]
        err, shift, theta = match_references(
            self.rings,
            rel,
            self.kind[nb_arr],
            self.sub[nb_arr],
            mode=mode,
            flow_theta=flow_theta,
            candidates=cand,
            weights=self.p.weights,
            frame_theta=frame_theta,
            frame_weight=frame_w,
            max_turn=self.p.flow_max_turn if self.mode_code == 2 else self.p.max_turn,
            keep_frame=self.p.keep_frame if self.mode_code == 1 else 0,
        )
        best = float(err.min()) if len(err) else math.inf
        if not math.isfinite(best):
            return None
        # Equally good references (e.g. every one for the very first seed) are chosen at
        # random from ``rng``; the paper does not say how it breaks ties.
        ties = np.flatnonzero(err <= best + 1e-9 * (1.0 + best))
        a = int(ties[0]) if len(ties) == 1 else int(ties[self.rng.integers(len(ties))])
        self._last_nb = nb_arr
        return a, int(shift[a]), float(theta[a])

    def _one_arc(self, nb: np.ndarray, rel: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The longest run of placed neighbours without a gap wider than :attr:`arc_gap`.

        Not in the paper. §5.2 matches the target's neighbours, in angular order, to
        consecutive ring slots (no skipping). In the plane the placed neighbours of a
        seed lie on one arc of the front; on the torus, where the front meets itself, a
        seed has neighbours from both sides with empty slots between them, and matching
        them to consecutive slots pulls the seed off the lattice (scales_hex in a tile
        that is a multiple of its periods: 32 of 400 elements off by up to a quarter
        spacing). The longest arc is matched; the others are met again as the ring's
        seeds merge with them (Fig. 6b), which pairs them with their own slots.
        """
        ang = np.arctan2(rel[:, 1], rel[:, 0])
        gaps = np.mod(np.diff(ang), 2 * np.pi)
        cut = np.flatnonzero(gaps > self.arc_gap) + 1
        if len(cut) == 0:
            return nb, rel
        bounds = np.r_[0, cut, len(nb)]
        q = int(np.argmax(np.diff(bounds)))
        sel = slice(int(bounds[q]), int(bounds[q + 1]))
        return nb[sel], rel[sel]

    def try_larger(self, s: int) -> bool:
        """Place seed ``s`` as a larger kind it misses (:meth:`missing_larger`); True when placed."""
        kinds = self.missing_larger(s)
        if not kinds:
            return False
        own = int(self.kind[s])
        ox, oy = self.xy[s]
        for b in kinds:
            if not self.kind_has_candidates[b]:
                continue
            self.kind[s] = b
            pick = self.choose(s)
            if pick is not None and self.place(s, *pick, reach=self.p.canopy_reach * self.l):
                return True
            self.kind[s] = own
            if self.xy[s] != (ox, oy):
                self._move(s, ox, oy)
        return False

    def try_smaller(self, s: int) -> bool:
        """Place seed ``s``, whose element crossed a boundary stroke, as a smaller kind; True when placed.

        Not in the paper, whose boundary tool only stops growth. A seed of a large kind
        by the region's edge or a boundary stroke, where its element would reach across,
        died and left a gap the size of that element, which nothing filled: a closed
        stroke around stones with pebbles was filled to 0.83-0.87 of its inside (the
        inside away from the stroke at the exemplar's density). The seed is tried as
        each smaller kind, largest first, as :meth:`try_larger` tries larger ones.
        Only at strokes: at the region's edge, which crops the pattern as the
        exemplar's frame does, the fidelity suite's three sizes lost a seed's worth
        (nn[small>large] failed on seed 3 too).
        """
        own = int(self.kind[s])
        if own < 0:
            return False
        lv = self.size_level
        smaller = [b for b in range(self.n_kinds) if lv[b] < lv[own] and self.kind_has_candidates[b]]
        smaller.sort(key=lambda b: -lv[b])
        ox, oy = self.xy[s]
        for b in smaller:
            self.kind[s] = b
            pick = self.choose(s)
            if pick is not None and self.place(s, *pick):
                return True
            self.kind[s] = own
            if self.xy[s] != (ox, oy):
                self._move(s, ox, oy)
        return False

    def place(self, s: int, a: int, k: int, th: float, reach: float | None = None) -> bool:
        """§5.4: replace seed ``s`` by reference ``a`` and put its unpaired ring out as seeds."""
        p = self.p
        if self.rep is not None and self.order:
            # throttled poll of should_cancel, before this step changes anything (a seed
            # that refuses its placements costs lookups but no growth step)
            self.rep.tick(len(self.order))
        r = int(self.ref_ids[a])
        kind = int(self.ex_kind[r])
        n_ring = int(self.rings["n"][a])
        c, sn = math.cos(th), math.sin(th)
        rel = self.rings["rel"][a, :n_ring]
        nb = self._last_nb
        if len(nb) >= 2 or (reach is not None and len(nb) >= 1):
            self._fit_position(s, nb, rel, k, c, sn, reach)
        x, y = self.xy[s]
        rot = float(self.ex_rot[r]) + th
        scale = float(self.ex_scale[r])
        if p.jitter_rotation > 0:
            rot += float(self.rng.uniform(-p.jitter_rotation, p.jitter_rotation))
        if p.jitter_scale > 0:
            scale *= float(1.0 + self.rng.uniform(-p.jitter_scale, p.jitter_scale))
        # an element as close to one of its own kind (or another) as the reference never
        # has them is refused, like the seeds of too_close_in_kind
        if self.too_close_in_kind(x, y, kind, s, (ELEMENT,), placing=True):
            return False
        if self.several_sizes and not self.lean_ok(s, a, k, th, x, y, kind):
            return False
        g = self.element_geometry(kind, x, y, rot, scale)
        # Not in the paper: an element must lie wholly inside the region and off the
        # boundary strokes (the paper stops growth at them; an element whose centre is
        # inside could still reach across).
        if not self.fits_domain(g):
            # (a boundary stroke, not the region's edge: see try_smaller)
            self._out_of_domain = self.boundary is not None and bool(shapely.intersects(self.boundary, g))
            return False
        # Not in the paper: a placement that would overlap an element is refused (the
        # seed dies), so that an exemplar without overlaps grows a pattern without any.
        if p.avoid_overlaps and self.overlaps_any(g, kind, x, y, scale):
            # Fixed mode without priorities: only where the slot is enclosed (at most
            # ``nudge_open`` of its ring's slots unplaced). The nudge is for slots that
            # closed in (fronts that met; with §5.1's priorities, low-priority seeds
            # among placed ones). In the open front a nudged element is off the lattice,
            # later seeds fit their positions to it (_fit_position) and the offset
            # spreads until two fronts meet out of step: bricks seed 5 grew a seam half
            # a course out of step (regularity 0.060 against 0.05) from 4 nudges with
            # 2-4 of 6 slots placed. In rotation mode each element's turn moves its
            # ring a little and the nudge keeps those overlaps from leaving holes
            # (without it bricks rotate seeds 1, 2, 4 failed).
            if (p.nudge_open is not None and self.mode_code == 0 and not self.use_prio
                    and sum(self.state[o] == ELEMENT for o in self.adj[s]) < n_ring - p.nudge_open):
                return False
            moved = self._nudge(s, kind, x, y, rot, scale)
            if moved is None:
                return False
            x, y, g = moved
        self._unhigh(s)
        self.state[s] = ELEMENT
        self.kind[s] = kind
        self.sub[s] = r
        self.rot[s] = rot
        self.scl[s] = scale
        self.refslot[s] = a
        self.frame[s] = th
        self.geom[s] = g
        self.color[s] = self._color(r) if self.want_color else None
        if self.tile is not None:
            self._sync(s)
        self.order.append(s)
        self.dirty.add(s)

        ring_pos = np.empty((n_ring, 2))
        ring_pos[:, 0] = x + c * rel[:, 0] - sn * rel[:, 1]
        ring_pos[:, 1] = y + sn * rel[:, 0] + c * rel[:, 1]
        if self.mode_code == 2 and p.flow_bend > 0:
            rel = self._bent_ring(s, x, y, rel, ring_pos, c, sn)
            c, sn = 1.0, 0.0
            ring_pos[:, 0] = x + rel[:, 0]
            ring_pos[:, 1] = y + rel[:, 1]
        ring_kind = self.rings["kind"][a, :n_ring].tolist()
        ring_xy = ring_pos.tolist()
        slot_of: dict[int, int] = {}
        for i, j in enumerate(nb.tolist()):
            slot_of[j] = (k + i) % n_ring
        paired = set(slot_of.values())
        gap_min = self.ring_gap_min[a]
        # New seeds (Fig. 2g) with the heuristics of Fig. 6 (b)-(d).
        for j in range(n_ring):
            if j in paired:
                continue
            cx, cy = ring_xy[j]
            if not self.in_domain(cx, cy):
                continue
            if self.crosses_boundary((x, y), (cx, cy)):
                self.fixed[s] = True  # Eq. 6: elements at user boundaries are constrained
                continue
            # (b) merge with an object within l_short
            close = self.near(cx, cy, self.l_short)
            close = [o for o in close if self.orig_of[o] != s]
            if not close and self.too_close_in_kind(cx, cy, ring_kind[j], s):
                continue
            if close:
                o = min(close, key=lambda o: (self.xy[o][0] - cx) ** 2 + (self.xy[o][1] - cy) ** 2)
                if not self.has_edge(s, o):
                    po = self.xy[o]
                    if not self.crosses_edges(s, (x, y), o, po) and not self.crosses_boundary((x, y), po):
                        self.add_edge(s, o)
                        slot_of.setdefault(o, j)
                continue
            # (c) angle check against the neighbours already around s. The "original
            # angle" is taken as the smaller of the two reference ring angles beside slot j.
            ang = math.atan2(cy - y, cx - x)
            too_close = False
            for o in self.adj[s]:
                d = abs(math.atan2(self.xy[o][1] - y, self.xy[o][0] - x) - ang)
                d = min(d, 2 * math.pi - d)
                if d < 0.5 * gap_min[j]:
                    too_close = True
                    break
            if too_close:
                continue
            # (d) edge collision
            if self.crosses_edges(s, (x, y), None, (cx, cy)):
                continue
            t = self.new_object(cx, cy, ring_kind[j])
            self.add_edge(s, t)
            slot_of[t] = j
        # (h) edges between consecutive ring members, and (e) extra seeds on long ones
        self._ring_edges(s, a, slot_of, rel, c, sn)
        # ring targets r_ji for the relaxation (§5.5)
        tgt = {}
        rel_l = rel.tolist()
        for o, j in slot_of.items():
            if o in self.adj[s]:
                rx, ry = rel_l[j]
                tgt[o] = (c * rx - sn * ry, sn * rx + c * ry)
        self.target[s] = tgt
        self.ring_n[s] = n_ring
        return True

    def _bent_ring(self, s: int, x: float, y: float, rel: np.ndarray, ring_pos: np.ndarray, c: float, sn: float) -> np.ndarray:
        """The ring offsets turned with the flow field between the element and each slot.

        Not in the paper: §5.3 turns the whole reference neighbourhood by the field at
        the element being placed, so each of its ring members is predicted in that one
        frame; where the field turns, the members ahead sit off the lattice that will be
        grown there (their own neighbourhoods are turned by the field at them) and the
        mismatch piles up as strain and holes. Each offset is turned further by
        ``flow_bend`` times the field's turn from the element to the predicted slot (a
        half: the chord of a curving row follows the field at its midpoint).

        Returns the offsets in the plane's frame, shape (n_ring, 2).
        """
        pts = np.vstack([[x, y], ring_pos])
        v = np.asarray(self.p.flow(pts), dtype=float)
        a = np.arctan2(v[:, 1], v[:, 0])
        self._flow_at[s] = float(a[0])  # for the frame carried on from s (``choose``)
        d = a[1:] - a[0]
        d = d - np.pi * np.round(d / np.pi)  # a line field: +-pi/2 (direction sign free)
        t = math.atan2(sn, c) + self.p.flow_bend * d
        ct, st = np.cos(t), np.sin(t)
        return np.c_[ct * rel[:, 0] - st * rel[:, 1], st * rel[:, 0] + ct * rel[:, 1]]

    def _nudge(self, s: int, kind: int, x: float, y: float, rot: float, scale: float) -> tuple[float, float, Any] | None:
        """A place near ``(x, y)`` where the element of seed ``s`` overlaps nothing, or None.

        Not in the paper (which does not test overlaps). In a tight tiling the slot a
        seed fills is bounded by elements placed around it, each fitted to its own
        neighbours; where they closed in by a little (a seed that waited for §5.1's
        priority, or fronts that met), the element overlapped one of them, the seed died
        and left a hole of a whole element (bricks with a priority). Up to 16 offsets of
        at most ``nudge * l_short`` are tried, nearest first, with the checks of
        :meth:`_fit_position`; the first that fits is taken.
        """
        reach = self.p.nudge * self.l_short
        if reach <= 0:
            return None
        for f in (0.25, 0.5, 0.75, 1.0):
            for q in range(4):
                t = 0.5 * math.pi * q + 0.25 * math.pi * (f * 4 % 2)
                nx, ny = x + f * reach * math.cos(t), y + f * reach * math.sin(t)
                if not self.in_domain(nx, ny) or self.crosses_boundary((x, y), (nx, ny)):
                    continue
                if self.spray_area is not None and not shapely.contains_xy(self.spray_area, nx, ny):
                    continue
                if any(self.crosses_edges(s, (nx, ny), o, self.xy[o]) or self.crosses_boundary((nx, ny), self.xy[o]) for o in self.adj[s]):
                    continue
                if self.too_close_in_kind(nx, ny, kind, s, (ELEMENT,), placing=True):
                    continue
                g = self.element_geometry(kind, nx, ny, rot, scale)
                if not self.fits_domain(g) or self.overlaps_any(g, kind, nx, ny, scale):
                    continue
                self._move(s, nx, ny)
                return nx, ny, g
        return None

    def _fit_position(self, s: int, nb: np.ndarray, rel: np.ndarray, k: int, c: float, sn: float, reach: float | None = None) -> None:
        """Move seed ``s`` to where the chosen ring fits its placed neighbours best.

        Not in the paper, which keeps the seed where the element that made it put it:
        the seed's position is then one neighbour's noisy ring offset, and the noise of
        near-regular references adds up from element to element along the growth, so
        rows wander and close up (§5.5 relaxes it only afterwards). The least-squares
        position for the chosen ring, ``mean_i (x_i - R r_{f(i)})``, is the minimiser of
        Eq. 5 for the new element alone with its neighbours held (Eq. 6). The move is
        kept within ``fit_reach * l_short`` and within the region, boundaries and
        connectivity.
        """
        n_ring = len(rel)
        rel_l = rel.tolist()
        xy = self.xy
        fx = fy = 0.0
        for i, o in enumerate(nb.tolist()):
            rx, ry = rel_l[(k + i) % n_ring]
            px, py = xy[o]
            fx += px - (c * rx - sn * ry)
            fy += py - (sn * rx + c * ry)
        fx /= len(nb)
        fy /= len(nb)
        ox, oy = self.xy[s]
        d2 = (fx - ox) ** 2 + (fy - oy) ** 2
        if d2 <= (1e-9 * self.l) ** 2:
            return  # already there (a perfect lattice): nothing to check
        if reach is None:
            reach = self.p.fit_reach * self.l_short
        if d2 > reach**2 or not self.in_domain(fx, fy):
            return
        if self.crosses_boundary((ox, oy), (fx, fy)):
            return
        if self.spray_area is not None and not shapely.contains_xy(self.spray_area, fx, fy):
            return
        for o in self.adj[s]:
            if self.crosses_edges(s, (fx, fy), o, self.xy[o]) or self.crosses_boundary((fx, fy), self.xy[o]):
                return
        self._move(s, fx, fy)

    def _ring_edges(self, s: int, a: int, slot_of: dict[int, int], rel: np.ndarray, c: float, sn: float) -> None:
        x, y = self.xy[s]
        nbrs = list(self.adj[s])
        if len(nbrs) < 2:
            return
        angs = [math.atan2(self.xy[o][1] - y, self.xy[o][0] - x) for o in nbrs]
        order = sorted(range(len(nbrs)), key=lambda q: angs[q])
        m = len(order)
        for q in range(m):
            ia, ib = order[q], order[(q + 1) % m]
            oa, ob = nbrs[ia], nbrs[ib]
            gap = (angs[ib] - angs[ia]) % (2 * math.pi)
            if m == 2 and q == 1:
                break
            if gap <= 1e-9 or gap >= math.pi - 1e-9 or self.has_edge(oa, ob):
                continue
            pa = self.xy[oa]
            pb = self.xy[ob]
            ja, jb = slot_of.get(oa), slot_of.get(ob)
            if ja is not None and jb is not None:
                orig = float(np.hypot(*(rel[ja] - rel[jb])))
            else:
                # Fig. 6e compares with the corresponding edge of the reference ring; a
                # pair that does not come from this ring has none: take the ring's
                # longest edge (its mean made extra seeds in every gap a reference with
                # long and short edges has, e.g. between clusters)
                orig = float(self.ring_edge_max[a])
            L = math.hypot(pa[0] - pb[0], pa[1] - pb[1])
            if L > 1.5 * orig:
                # (e) l_long = 1.5 * original length: an extra seed on the bisector, at the
                # average length of the two adjacent edges, without a symbol id
                mid = angs[ia] + 0.5 * gap
                la = math.hypot(pa[0] - x, pa[1] - y)
                lb = math.hypot(pb[0] - x, pb[1] - y)
                d = 0.5 * (la + lb)
                ex, ey = float(x + d * math.cos(mid)), float(y + d * math.sin(mid))
                if not self.in_domain(ex, ey) or self.crosses_boundary((x, y), (ex, ey)):
                    continue
                if self.near(ex, ey, self.l_short):
                    continue
                if self.crosses_edges(s, (x, y), None, (ex, ey)):
                    continue
                t = self.new_object(ex, ey, -1)
                self.add_edge(s, t)
                for o, po in ((oa, pa), (ob, pb)):
                    # (f) edges that would collide are left out; the paper instead joins
                    # the objects found inside triangle (e_tar, s0, s1), which Fig. 6f
                    # shows but the text does not specify.
                    if not self.crosses_edges(o, po, t, (ex, ey)) and not self.crosses_boundary(po, (ex, ey)):
                        self.add_edge(o, t)
            elif not _skewed((x, y), pa, pb):
                # the new edge closes triangle (s, a, b); like §4 we keep no skewed triangle
                if not self.crosses_edges(oa, pa, ob, pb) and not self.crosses_boundary(pa, pb):
                    self.add_edge(oa, ob)

    def copied_columns(self, sub: np.ndarray) -> dict[str, Any]:
        """The exemplar's other per-element columns (``void``, ``layer``, ...), copied
        from the reference element each grown element copies (its sub-id, §3)."""
        out: dict[str, Any] = {}
        for name, col in self.ref.exemplar.columns.items():
            if name in ("sub_id", "color"):
                continue
            a = np.asarray(col)
            if a.ndim >= 1 and len(a) == len(self.ref.exemplar):
                out[name] = a[sub].copy() if len(sub) else a[:0].copy()
        return out

    def _color(self, r: int) -> Any:
        base = self.ex_color[r]
        amt = self.p.jitter_color
        if amt <= 0:
            return base
        rgb = _parse_hex(base)
        if rgb is None:
            return base
        f = 1.0 + float(self.rng.uniform(-amt, amt))
        out = [min(1.0, max(0.0, v * f)) for v in rgb]
        return "#" + "".join(f"{int(round(v * 255)):02x}" for v in out)

    # -- relaxation (§5.5) ----------------------------------------------------------------
    def ring_target(self, i: int, j: int) -> tuple[float, float]:
        t = self.target[i]
        if t is not None and j in t:
            return t[j]
        # §5.5: seeds, and elements that lost or gained an edge, use their current shape.
        # We apply that per edge: an element keeps the reference offsets of the edges it
        # has from its ring and takes the current offset for the others only. (Applied
        # per element, hardly any element qualifies: one ring slot merged or dropped by
        # the heuristics of Fig. 6, or one edge added later by a neighbour, and Eq. 5
        # had no effect at all.)
        xj, xi = self.xy[j], self.xy[i]
        return (xj[0] - xi[0], xj[1] - xi[1])

    def relax_window(self) -> None:
        if self.rep is not None:
            self.rep.tick(len(self.order))
        win = {i for i in self.dirty if self.state[i] != DEAD}
        self.dirty = set()
        for _ in range(self.p.relax_hops):
            win |= {j for i in win for j in self.adj[i]}
        win = [i for i in win if not self.fixed[i]]
        if not win:
            return
        wset = set(win)
        # the terms of Eq. 5 over the window, as local indices (ring_target inlined: this
        # loop runs for every edge of every window)
        nodes = sorted(wset | {j for i in win for j in self.adj[i]})
        local = {g: q for q, g in enumerate(nodes)}
        xy = self.xy
        targets = self.target
        adj = self.adj
        src: list[int] = []
        dst: list[int] = []
        off: list[float] = []
        for i in win:
            ti = targets[i]
            xi, yi = xy[i]
            li = local[i]
            for j in adj[i]:
                lj = local[j]
                src.append(li)
                dst.append(lj)
                t = ti.get(j) if ti is not None else None
                if t is None:
                    xj, yj = xy[j]
                    off += (xj - xi, yj - yi)
                else:
                    off += t
                if j not in wset:
                    src.append(lj)
                    dst.append(li)
                    tj = targets[j]
                    t = tj.get(i) if tj is not None else None
                    if t is None:
                        xj, yj = xy[j]
                        off += (xi - xj, yi - yj)
                    else:
                        off += t
        if not src:
            return
        pos = self.pos[nodes]
        free = np.fromiter((g in wset for g in nodes), dtype=bool, count=len(nodes))
        new = relax_positions(pos, np.array(src, dtype=np.intp), np.array(dst, dtype=np.intp), np.array(off).reshape(-1, 2), free)
        if self.freeze_relaxed:
            for g in win:
                if self.state[g] == ELEMENT:
                    self.fixed[g] = True
        tiny = 1e-9 * self.l
        moved = []
        new_geom: dict[int, Any] = {}
        for g in win:
            nx, ny = float(new[local[g], 0]), float(new[local[g], 1])
            ox, oy = self.xy[g]
            if abs(nx - ox) + abs(ny - oy) <= tiny:
                continue
            # relaxation never takes a centre out of the region or across a boundary stroke
            if not self.in_domain(nx, ny) or self.crosses_boundary((ox, oy), (nx, ny)):
                continue
            # nor an element's centre out of the spray area (§5.1: elements grow within it)
            if self.spray_area is not None and self.state[g] == ELEMENT and not shapely.contains_xy(self.spray_area, nx, ny):
                continue
            moved.append(g)
        # the moved elements' new outlines, in one shapely call per kind
        els = [g for g in moved if self.state[g] == ELEMENT]
        if els:
            for g, ng in zip(els, self.element_geometries(els, new[[local[g] for g in els]])):
                new_geom[g] = ng
            # nor an element across the region's edge or a boundary stroke
            fits = self.fits_domain_many([new_geom[g] for g in els])
            bad = {g for g, ok in zip(els, fits.tolist()) if not ok}
            if bad:
                moved = [g for g in moved if g not in bad]
        old = {g: (*self.xy[g], self.geom[g]) for g in moved}
        for g in moved:
            self._move(g, float(new[local[g], 0]), float(new[local[g], 1]))
            if self.state[g] == ELEMENT:
                self.geom[g] = new_geom[g]
                if self.tile is not None:
                    self._sync(g)
        if not self.p.avoid_overlaps:
            return
        # Keep the no-overlap guarantee: elements that now overlap go back to where they
        # were, with those they overlap, until no overlap is left (the positions before
        # the relaxation had none, so this ends).
        check = [g for g in moved if self.state[g] == ELEMENT]
        while check:
            back: set[int] = set()
            for g, hits in self.overlapping_many(check).items():
                back.add(g)
                back.update(self.orig_of[h] for h in hits if self.orig_of[h] in old)
            back = {g for g in back if self.xy[g] != old[g][:2]}
            for g in back:
                self._move(g, old[g][0], old[g][1])
                self.geom[g] = old[g][2]
                if self.tile is not None:
                    self._sync(g)
            oo = self.orig_of
            check = [g for g in moved if self.state[g] == ELEMENT and g not in back and any(oo[h] in back for h in self.adj[g])] + sorted(back)
            if not back:
                break

    # -- main loop --------------------------------------------------------------------------
    def run(self, start: tuple[float, float], rep: Reporter) -> None:
        p = self.p
        self.begin(start)
        target = p.count if p.count is not None else p.max_elements
        self.advance(rep, target)
        if self.tile is not None or self.boundary is not None:
            for _ in range(p.refill_rounds):
                if len(self.order) >= target or not self.refill():
                    break
                self.advance(rep, target)
        self.settle()

    def refill(self) -> int:
        """Torus: seeds again at the empty slots of the placed elements' rings; how many.

        Not in the paper. On a torus the growth front meets itself (at the tile's edges,
        for a start at its centre); the seeds that the two sides put out there were
        refused (they overlapped or crowded what the other side had not yet placed, or
        crossed its edges), and the paper's growth never comes back to a place: a seam of
        gaps is left. Each ring slot with no object within half its distance from the
        element is proposed again as a seed, as §5.4 would, and the growth goes on.
        """
        made = 0
        rings = self.rings
        for s in list(self.order):
            if self.state[s] != ELEMENT:
                continue
            a = int(self.refslot[s])
            n_ring = int(rings["n"][a])
            rel = rings["rel"][a, :n_ring]
            th = float(self.frame[s])
            c, sn = math.cos(th), math.sin(th)
            x, y = self.xy[s]
            for j in range(n_ring):
                rx, ry = float(rel[j, 0]), float(rel[j, 1])
                cx, cy = x + c * rx - sn * ry, y + sn * rx + c * ry
                kind = int(rings["kind"][a, j])
                if self.near(cx, cy, max(self.l_short, 0.5 * math.hypot(rx, ry))):
                    continue
                if self.too_close_in_kind(cx, cy, kind, s) or self.crosses_edges(s, (x, y), None, (cx, cy)):
                    continue
                if self.crosses_boundary((x, y), (cx, cy)):
                    continue
                t = self.new_object(cx, cy, kind)
                self.add_edge(s, t)
                made += 1
        return made

    def begin(self, start: tuple[float, float]) -> None:
        """§5.1: place the single initial seed at ``start``."""
        p = self.p
        self.max_scale = float(self.ex_scale.max()) * (1.0 + p.jitter_scale)
        self.other_rmax = max(self.other_rmax, float(self.kind_radius.max()) * self.max_scale)
        if self.tile is not None:
            self._torus_margin()
        self.origin = start
        self.s0 = self.new_object(start[0], start[1], p.start_kind)
        self.first = True

    def _torus_margin(self) -> None:
        """How far beyond the tile ghosts are kept: the farthest any lookup of the growth
        reaches from an object (a ring offset, then an overlap, closeness or larger-kind
        lookup there), plus a mean edge of drift. A tile narrower than that is refused:
        its images would have to meet their own copies."""
        n = self.rings["n"]
        rel = self.rings["rel"]
        ring_max = max((float(np.hypot(rel[a, : n[a], 0], rel[a, : n[a], 1]).max()) for a in range(len(n)) if n[a] > 0), default=self.l)
        finite = self.reach_larger[np.isfinite(self.reach_larger)]
        reach = max(2 * self.other_rmax, float(self.pair_close_max.max()), float(self.pair_short_max.max()), self.l_short,
                    float(finite.max()) if len(finite) else 0.0)
        self.margin = 1.25 * ring_max + reach + self.l
        _, _, w, h = self.tile  # type: ignore[misc]
        if min(w, h) < self.margin:
            raise InputError(
                f"periodic: the tile {w:g} x {h:g} is too small for this exemplar: its neighbourhoods reach "
                f"{self.margin:.4g} (about {self.margin / max(self.l, 1e-300):.1f} element spacings); give a tile at least "
                f"{self.margin:.4g} wide and high"
            )

    def advance(self, rep: Reporter, target: int, pause: int | None = None) -> bool:
        """Growth steps until ``target`` elements or no seed can grow.

        With ``pause``, stop early once ``pause`` elements exist and the windowed
        relaxation has just run (so pausing changes nothing); returns True when paused.
        """
        p = self.p
        self.rep = rep
        while self.heap and len(self.order) < target:
            if pause is not None and len(self.order) >= pause and (not p.relax or self.steps_since_relax == 0):
                return True
            _, s = heapq.heappop(self.heap)
            if self.state[s] != SEED or s in self.deferred:
                continue
            x, y = self.xy[s]
            if self.spray_area is not None and not shapely.contains_xy(self.spray_area, x, y):
                # §5.1 spray tool: only seeds within the radius grow; others wait
                if self.waiting is not None:
                    self.waiting.append(s)
                continue
            if not self.in_domain(x, y):
                self.kill(s)
                continue
            if self.outranked(s):
                self.deferred.add(s)
                continue
            if not (self.canopy and self.try_larger(s)):
                pick = self.choose(s)
                self._out_of_domain = False
                if (pick is None or not self.place(s, *pick)) and not (self._out_of_domain and self.try_smaller(s)):
                    self.kill(s)
                    self.release_deferred(s)
                    continue
            if self.first:
                self.fixed[self.s0] = True  # Eq. 6: the initial element holds its position
                self.first = False
            self.release_deferred(s)
            self.steps_since_relax += 1
            # §5.5 relaxes after every growth step over the whole pattern. To keep the
            # cost linear in the element count we relax every ``relax_every`` steps, over
            # a window: the elements and seeds made since, and their 1-ring, with the
            # rest held fixed (Eq. 6).
            if p.relax and self.steps_since_relax >= p.relax_every:
                self.relax_window()
                self.steps_since_relax = 0
            rep.tick(len(self.order))
        return False

    def settle(self) -> None:
        """The last relaxation window, when growth has stopped."""
        if self.p.relax and self.dirty:
            self.relax_window()

    def add_obstacle(self, x: float, y: float, geom: Any, areal: bool, radius: float) -> int:
        """An element that seeds must not overlap, owned by no growth (state OBSTACLE)."""
        if self.n == len(self.state):
            self._grow_capacity()
        i = self.n
        self.n += 1
        self.pos[i] = (x, y)
        self.xy.append((float(x), float(y)))
        self.state[i] = OBSTACLE
        self.kind[i] = len(self.areal)
        self.areal.append(bool(areal))
        self.fixed[i] = True
        self.adj.append(set())
        self.target.append(None)
        self.geom.append(geom)
        self.color.append(None)
        self.orig_of.append(i)
        self.off_of.append((0, 0))
        self.index.insert(i, x, y)
        self.other_rmax = max(self.other_rmax, float(radius))
        return i

    def result(self, meta: dict[str, Any]) -> Arrangement:
        ex = self.ref.exemplar
        idx = np.asarray(self.order, dtype=np.intp)
        columns: dict[str, Any] = {"sub_id": self.sub[idx].copy()}
        if self.want_color:
            columns["color"] = [self.color[i] for i in idx]
        columns.update(self.copied_columns(self.sub[idx]))
        extra: dict[str, Any] = {}
        if self.p.connectivity:
            new = np.full(self.n, -1, dtype=np.int64)
            new[idx] = np.arange(len(idx))
            e = np.array(sorted(self.edges), dtype=np.int64).reshape(-1, 2)
            if len(e):
                e = np.asarray(self.orig_of, dtype=np.int64)[e]  # an edge to an image joins the originals
            e = new[e] if len(e) else e
            e = e[(e >= 0).all(axis=1)] if len(e) else e
            e = np.sort(e, axis=1)
            extra["connectivity"] = {"count": int(len(idx)), "edges": np.unique(e, axis=0).tolist() if len(e) else []}
        return Arrangement(
            ex.shapes,
            self.kind[idx],
            self.pos[idx, 0].copy(),
            self.pos[idx, 1].copy(),
            self.rot[idx].copy(),
            self.scl[idx].copy(),
            columns=columns,
            region=self.region,
            meta=meta,
            extra=extra,
        )


def grow_reference(
    ref: Reference,
    params: GrowParams,
    *,
    rng: int | np.random.Generator | None = None,
    progress: Callable[[int, int | None, str], None] | None = None,
    should_cancel: Callable[[], bool] | None = None,
    meta: dict[str, Any] | None = None,
) -> Arrangement:
    """Grow from one seed with an analysed reference (§5). See :func:`strew.grow.grow`."""
    g = _Grower(ref, params, as_rng(rng))
    start = params.start
    if start is None:
        if params.spray is not None:
            start = (float(params.spray[0][0]), float(params.spray[0][1]))
        elif params.region is not None:
            c = params.region.geometry.centroid
            if not params.region.contains([[c.x, c.y]])[0]:
                c = params.region.geometry.representative_point()
            start = (float(c.x), float(c.y))
        else:
            start = (0.0, 0.0)
    if params.region is not None and not params.region.contains([start])[0]:
        raise InputError(f"--start {start[0]:g},{start[1]:g}: lies outside the region")
    total = params.count
    rep = Reporter(progress, should_cancel, total=total, message="growing")
    sat = satellite_structure(ref.exemplar) if params.clusters and params.spray is None and params.tile is None else None
    if sat is not None:
        out = grow_clusters(ref.exemplar, sat, params, g.rng, (float(start[0]), float(start[1])), rep, meta or {})
        rep.done(len(out))
        return out
    g.run((float(start[0]), float(start[1])), rep)
    rep.done(len(g.order))
    return g.result(meta or {})
