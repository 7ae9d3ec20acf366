"""The grower's predicates: overlap with placed elements, the region and boundary
strokes, and the closeness rules of Fig. 6 (b) and ``lean_ok`` (Ijiri et al. 2008, §5.4).

Split out of :mod:`strew.grow._growth` (issue 15).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np
import shapely

from ._objects import (
    _ELEMENT_OR_OBSTACLE,
    ELEMENT,
    OBSTACLE,
    SEED,
)
from ._overlap_kernels import overlap_certain
from ._place_kernels import too_close

_SEED_OR_ELEMENT = (1 << SEED) | (1 << ELEMENT)
_STATE_BITS: dict[tuple[int, ...], int] = {}


def _state_bits(states: tuple[int, ...]) -> int:
    m = _STATE_BITS.get(states)
    if m is None:
        m = _STATE_BITS[states] = sum(1 << s for s in set(states))
    return m


def _fast_polygon() -> Any:
    """A polygon from one closed ring of coordinates (k, 2), as ``shapely.polygons``
    makes it, through shapely's compiled constructors directly: the public function's
    argument handling costs as much as building the polygon, and the grower builds one
    per candidate placement. Falls back to ``shapely.polygons`` where the compiled
    layer differs (another shapely version)."""
    try:
        from shapely import lib

        allow = np.intc(0)  # shapely.creation.HandleNaN.allow, the default
        no_holes = np.empty((0,), dtype=object)

        def polygon(coords: np.ndarray) -> Any:
            return lib.polygons(lib.linearrings(coords, allow), no_holes)

        probe = np.array([[0.0, 0.0], [1.5, 0.0], [1.0, 2.0], [0.0, 0.0]])
        if polygon(probe) == shapely.polygons(probe):
            return polygon
    except Exception:  # pragma: no cover - other shapely versions
        pass
    return shapely.polygons  # pragma: no cover


_polygon = _fast_polygon()
try:
    from shapely.lib import intersects as _intersects  # the ufunc, without the Python wrapper
except ImportError:  # pragma: no cover
    _intersects = shapely.intersects
try:
    from shapely.lib import area as _area
    from shapely.lib import intersection as _intersection
except ImportError:  # pragma: no cover
    _area, _intersection = shapely.area, shapely.intersection
try:
    from shapely.lib import dwithin as _dwithin
except ImportError:  # pragma: no cover - shapely < 2.1

    def _dwithin(a: Any, b: Any, d: Any) -> Any:
        return shapely.distance(a, b) <= d


try:
    from shapely.lib import get_coordinates as _get_coordinates
    from shapely.lib import get_num_coordinates as _get_num_coordinates
    from shapely.lib import get_num_interior_rings as _get_num_interior_rings
    from shapely.lib import get_type_id as _get_type_id

    def _coordinates(a: Any) -> Any:
        return _get_coordinates(a, False, False, False)
except ImportError:  # pragma: no cover - other shapely versions
    _get_num_coordinates, _get_num_interior_rings, _get_type_id = shapely.get_num_coordinates, shapely.get_num_interior_rings, shapely.get_type_id

    def _coordinates(a: Any) -> Any:
        return shapely.get_coordinates(a)


def _big_overlaps(A: Any, B: np.ndarray) -> np.ndarray:
    """``area(A & B) > 1e-9 * max(area(A), 1e-300)`` pair by pair (``A`` one geometry or
    an object array as long as ``B``), (n,) bool: the overlap test of two areal elements.

    The same answers as the overlay (``_intersection``, ``_area``) for every pair: a pair
    of simple polygons whose overlap :func:`~strew.grow._overlap_kernels.overlap_certain`
    proves large is True without it, the others take it (issue 14 point 5; most pairs
    tested are candidates that overlap a neighbour plainly).
    """
    n = len(B)
    out = np.zeros(n, dtype=bool)
    if n == 0:
        return out
    if not isinstance(A, np.ndarray):
        a = np.empty(n, dtype=object)
        a[:] = [A] * n
        A = a
    simple = (_get_type_id(A) == 3) & (_get_type_id(B) == 3) & (_get_num_interior_rings(A) == 0) & (_get_num_interior_rings(B) == 0)
    if simple.all():
        As, Bs, idx = A, B, None
    else:
        idx = np.flatnonzero(simple)
        As, Bs = A[idx], B[idx]
    if len(As):
        oa = np.zeros(len(As) + 1, dtype=np.int64)
        np.cumsum(_get_num_coordinates(As), out=oa[1:])
        ob = np.zeros(len(Bs) + 1, dtype=np.int64)
        np.cumsum(_get_num_coordinates(Bs), out=ob[1:])
        cert = np.zeros(len(As), dtype=bool)
        overlap_certain(_coordinates(As), oa, _coordinates(Bs), ob, cert)
        if idx is None:
            out = cert
        else:
            out[idx[cert]] = True
    rest = np.flatnonzero(~out)
    if len(rest):
        ar = A[rest]
        out[rest] = _area(_intersection(ar, B[rest])) > 1e-9 * np.maximum(_area(ar), 1e-300)
    return out


#: most outlines :meth:`_Collide.turned_ring` keeps. In flow mode every element has
#: its own rotation, and the network passes (:mod:`strew.grow._flow_net`) put every
#: moved element's outline again at each step: with 1,024 kept, a flow growth of
#: more elements than that cleared the store before the next pass came back to an
#: element, so it missed from about 1,000 elements on (the hexagonal lattice along
#: the 90 degree field, 63 x 42 spacings, 2,980 elements: 181,318 calls at 64
#: microseconds each under cProfile, against 16 at 281 elements, where all were
#: kept): a cost per element that grew with the count (issue 14 point 5,
#: ``benchmarks/g63v_flow_scaling.py``). An outline of a few corners is some 300
#: bytes with its key, so this many is about 20 MB at most (the same products either
#: way: byte-identical output).
TURNED_KEEP = 1 << 16


class _Collide:
    """Overlap, domain and closeness tests on candidate elements."""

    def element_geometry(self, kind: int, x: float, y: float, rot: float, scale: float) -> Any:
        if self.local_ring[kind] is not None:  # a simple polygon: the same coordinates, built directly
            return _polygon(self.turned_ring(kind, rot, scale) + np.array([x, y]))
        m = np.array([[math.cos(rot) * scale, -math.sin(rot) * scale], [math.sin(rot) * scale, math.cos(rot) * scale]])
        t = np.array([x, y])
        return shapely.transform(self.local_geom[kind], lambda q: q @ m.T + t)

    def turned_ring(self, kind: int, rot: float, scale: float) -> np.ndarray:
        """The outline of ``kind`` (a simple polygon) turned by ``rot`` and scaled by
        ``scale`` about its centre, (n, 2): ``local_ring[kind] @ m.T``.

        Kept per (kind, rot, scale): in fixed mode an element takes its reference's
        rotation and scale, so a growth turns the same few outlines thousands of times
        (the same products, once; issue 14 point 5). At most :data:`TURNED_KEEP` are kept.
        """
        key = (kind, rot, scale)
        cache = self._turned
        base = cache.get(key)
        if base is None:
            m = np.array([[math.cos(rot) * scale, -math.sin(rot) * scale], [math.sin(rot) * scale, math.cos(rot) * scale]])
            base = self.local_ring[kind] @ m.T
            base.flags.writeable = False
            if len(cache) >= TURNED_KEEP:
                cache.clear()  # (rotation mode: every element its own angle)
            cache[key] = base
        return base

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
        for j in self.index.near(x, y, r, _ELEMENT_OR_OBSTACLE):
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
        return self._hits_any(g, kind, others)

    def overlap_pool(self, kind: int, x: float, y: float, scale: float, reach: float) -> list[int]:
        """The objects :meth:`overlaps_any` can test for an element of ``kind`` and
        ``scale`` centred within ``reach`` of (x, y) (for :meth:`overlaps_pool`)."""
        r = self.kind_radius[kind] * scale + self.other_rmax
        return self.index.near(x, y, r + reach, _ELEMENT_OR_OBSTACLE)

    def overlaps_pool(self, g: Any, kind: int, x: float, y: float, scale: float, pool: list[int]) -> bool:
        """:meth:`overlaps_any` with the candidates from :meth:`overlap_pool`: the same
        answer (an object beyond the bounding radii cannot touch ``g``)."""
        return self._hits_any(g, kind, self._pool_others(kind, x, y, scale, pool))

    def _pool_others(self, kind: int, x: float, y: float, scale: float, pool: list[int]) -> list[int]:
        """The objects of ``pool`` within reach of an element of ``kind`` and ``scale`` at
        (x, y): those :meth:`overlaps_pool` tests with shapely."""
        kr = self.kind_radius
        nk = len(kr)
        rg = float(kr[kind]) * abs(scale)
        r2 = (self.kind_radius[kind] * scale + self.other_rmax) ** 2
        xy, kinds, state, scl = self.xy, self.kind, self.state, self.scl
        others = []
        for j in pool:
            px, py = xy[j]
            d2 = (px - x) ** 2 + (py - y) ** 2
            if d2 > r2:
                continue
            if state[j] == ELEMENT:
                kj = kinds[j]
                if kj < nk:
                    reach = (rg + float(kr[kj]) * abs(float(scl[j]))) * (1.0 + 1e-9)
                    if d2 > reach * reach:
                        continue
            others.append(j)
        return others

    def overlaps_pool_many(self, gs: Sequence[Any], kind: int, pts: Sequence[tuple[float, float]], scale: float, pool: list[int]) -> list[bool]:
        """:meth:`overlaps_pool` for several candidate outlines ``gs`` of one element
        (centred at ``pts``), with one shapely call for all their pairs: the same
        answers (issue 14 point 5; the tests are pure, so testing every candidate and
        taking the first that passes picks what testing them one by one did)."""
        qs: list[int] = []
        js: list[int] = []
        for q, (nx, ny) in enumerate(pts):
            others = self._pool_others(kind, nx, ny, scale, pool)
            qs.extend([q] * len(others))
            js.extend(others)
        out = [False] * len(gs)
        if not js:
            return out
        geom = self.geom
        A = np.array(gs, dtype=object)[qs]
        B = np.array([geom[j] for j in js], dtype=object)
        hit = np.flatnonzero(_intersects(A, B))
        if len(hit) == 0:
            return out
        if not self.areal[kind]:
            for p in hit.tolist():
                out[qs[p]] = True
            return out
        areal, kinds = self.areal, self.kind
        both = []
        for p in hit.tolist():
            if areal[kinds[js[p]]]:
                both.append(p)
            else:
                out[qs[p]] = True  # (a hit on an outline without area: an overlap, as in _hits_any)
        if both:
            # (_hits_any's test of each hit's overlap area, for all the hits at once)
            b = np.array(both)
            big = _big_overlaps(A[b], B[b])
            for p in b[big].tolist():
                out[qs[p]] = True
        return out

    def crowds_gap(self, g: Any, kind: int, x: float, y: float, scale: float, s: int) -> bool:
        """Would element geometry ``g`` of ``kind`` and ``scale`` at (x, y) come nearer a
        placed element than the reference has their two kinds: outline to outline
        (:attr:`pair_gap`), or bounding disc to bounding disc (:attr:`pair_disc`)?

        Not in the paper: §5.2's collision test is per element; here it is per pair of
        kinds, with the reference's least gaps between them (see ``_Grower._pair_gaps``).
        """
        gmax = float(self.pair_gap_max[kind])
        if gmax <= 0:
            return False
        row = self.pair_gap[kind]
        disc = self.pair_disc[kind]
        far = self.pair_reach[kind]
        kr = self.kind_radius
        nk = len(kr)
        rg = float(kr[kind]) * abs(scale)
        xy, kinds, scl, orig_of = self.xy, self.kind, self.scl, self.orig_of
        others = []
        gaps = []
        for j in self.index.near(x, y, rg + self.other_rmax + gmax, 1 << ELEMENT):
            kj = int(kinds[j])
            if kj < 0 or kj >= nk or orig_of[j] == s:
                continue
            gj = float(row[kj])
            if gj <= 0:
                continue
            rj = rg + float(kr[kj]) * abs(float(scl[j]))
            reach = rj + float(far[kj])
            px, py = xy[j]
            d2 = (px - x) ** 2 + (py - y) ** 2
            if d2 > reach * reach:
                continue
            dm = rj + float(disc[kj])
            if dm > 0 and d2 < dm * dm:
                return True
            others.append(j)
            gaps.append(gj)
        if not others:
            return False
        geom = self.geom
        gs = np.array([geom[j] for j in others], dtype=object)
        return bool(_dwithin(g, gs, np.array(gaps)).any())

    def _hits_any(self, g: Any, kind: int, others: list[int]) -> bool:
        if not others:
            return False
        geom = self.geom
        gs = np.array([geom[j] for j in others], dtype=object)
        hit = _intersects(g, gs)
        if not hit.any():
            return False
        if not self.areal[kind]:
            return True
        hit = np.flatnonzero(hit)
        areal, kinds = self.areal, self.kind
        if not all(areal[kinds[others[j]]] for j in hit.tolist()):
            return True
        # the overlap areas of all the hits in one call (shapely's compiled functions:
        # the same values as shapely.intersection(g, h).area one by one; issue 14 point 5)
        return bool(_big_overlaps(g, gs[hit]).any())

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
        # (shapely's compiled functions without their Python wrappers: the same calls,
        # and this runs for every element a relaxation pass moves)
        hit = np.flatnonzero(_intersects(geom, gs)).tolist()
        if not hit:
            return []
        areal, kinds = self.areal, self.kind
        # the overlap test of the areal pairs in one call (_big_overlaps: the same answers)
        both = [q for q in hit if areal[kind] and areal[kinds[others[q]]]]
        big = dict(zip(both, _big_overlaps(geom, gs[both]).tolist())) if both else {}
        return [others[q] for q in hit if big.get(q, True)]

    def overlapping_each(self, check: Sequence[int]) -> dict[int, list[int]]:
        """:meth:`overlapping` of each element of ``check`` (placed elements), those with
        a hit only: {element: the elements it overlaps}, each list as a set (its order
        may differ from :meth:`overlapping`'s).

        With no gaps kept between kinds (:attr:`pair_gap`), :meth:`overlapping_many`
        answers the same pairs in one query and one shapely call (its bounding discs
        skip only pairs that cannot touch); else one :meth:`overlapping` each.
        (Issue 14 point 5, g70v: the flow passes' overlap checks of every moved
        element, one by one, were 3-5 % of the hexflow growth.)"""
        if len(self.pair_gap_max) and float(self.pair_gap_max.max()) > 0:
            return {o: h for o in check if (h := self.overlapping(o))}
        return self.overlapping_many(check)

    def overlapping_many(self, check: Sequence[int]) -> dict[int, list[int]]:
        """:meth:`overlapping` for several elements, with one vectorised shapely call.

        Where :attr:`pair_gap` holds a gap for two kinds, a pair nearer than it counts
        as overlapping too (the relaxation then moves neither: see :meth:`crowds_gap`)."""
        out: dict[int, list[int]] = {}
        ca = np.asarray(check, dtype=np.int64)
        if len(ca) == 0:
            return out
        # the candidates of every element in one query of the index
        kr = self.kind_radius
        nk = len(kr)
        rg = kr[self.kind[ca]] * self.scl[ca]
        pos = self.pos
        pg = self.pair_gap if len(self.pair_gap_max) and float(self.pair_gap_max.max()) > 0 else None
        qi, js = self.index.near_many(pos[ca, 0], pos[ca, 1], rg + self.other_rmax + (float(self.pair_gap_max.max()) if pg is not None else 0.0),
                                      _ELEMENT_OR_OBSTACLE)
        gs = ca[qi]
        keep = js != gs
        if self.tile is not None:  # not an image of the element itself
            oo = self.orig_of
            keep &= np.fromiter((oo[j] != g for j, g in zip(js.tolist(), gs.tolist())), dtype=bool, count=len(js))
        # bounding radius of each element: pairs farther apart than the sum of theirs
        # cannot touch, and skip the shapely test (obstacles have no kind of ours)
        kj = self.kind[js]
        el = (self.state[js] == ELEMENT) & (kj < nk)
        gap = pg[self.kind[gs], np.where(el, kj, 0)] * el if pg is not None else 0.0
        far = self.pair_reach[self.kind[gs], np.where(el, kj, 0)] * el if pg is not None else 0.0
        reach = (rg[qi] + kr[np.where(el, kj, 0)] * self.scl[js] + far) * (1.0 + 1e-9)
        d2 = (pos[js, 0] - pos[gs, 0]) ** 2 + (pos[js, 1] - pos[gs, 1]) ** 2
        keep &= ~(el & (d2 > reach * reach))
        ga: list[int] = gs[keep].tolist()
        gb: list[int] = js[keep].tolist()
        if not ga:
            return out
        geoms = self.geom
        A = np.array([geoms[g] for g in ga], dtype=object)
        B = np.array([geoms[j] for j in gb], dtype=object)
        if pg is not None:
            gk = np.asarray(gap)[keep]
            near = gk > 0
            hit_b = np.zeros(len(ga), dtype=bool)
            if near.any():
                # nearer than the bounding discs' gap (see crowds_gap), or the outlines'
                pd = np.maximum(self.pair_disc, self.pair_disc.T)
                dm = (rg[qi] + kr[np.where(el, kj, 0)] * self.scl[js] + pd[self.kind[gs], np.where(el, kj, 0)])[keep]
                hit_b = near & (dm > 0) & (d2[keep] < dm * dm)
                rest = near & ~hit_b
                if rest.any():
                    hit_b[rest] = _dwithin(A[rest], B[rest], gk[rest])
            if (~near).any():
                hit_b[~near] = shapely.intersects(A[~near], B[~near])
            hit = np.flatnonzero(hit_b)
        else:
            near = None
            hit = np.flatnonzero(shapely.intersects(A, B))
        if len(hit) == 0:
            return out
        areal = self.areal
        both = np.array([areal[self.kind[ga[q]]] and areal[self.kind[gb[q]]] for q in hit], dtype=bool)
        if near is not None:
            both &= ~near[hit]  # too near: a hit whatever the overlap's area
        keep = ~both
        if both.any():
            hb = hit[both]
            keep[both] = _big_overlaps(A[hb], B[hb])
        for q in hit[keep].tolist():
            out.setdefault(ga[q], []).append(gb[q])
        return out

    # -- growth -------------------------------------------------------------------------
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
        classes = _SEED_OR_ELEMENT if states == (SEED, ELEMENT) else _state_bits(states)
        if self.tile is None and not classes >> OBSTACLE & 1:
            # the loop below in one compiled call (in the plane an object's original is
            # itself; the same answers: issue 14 point 5)
            ix, pts = self.index, self.index.points
            return too_close(x, y, kind, s, r, ps, classes, ix.cell, pts.head, pts.ent, pts.cur, pts.ext, ix.pos, ix.state, self.kind, ix.out)
        xy, orig_of, kinds = self.xy, self.orig_of, self.kind
        for o in self.index.near(x, y, r, classes):
            if orig_of[o] == s:
                continue
            ko = int(kinds[o])
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
