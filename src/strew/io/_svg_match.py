"""SVG import, kind matching: similarity invariants, signatures, poses and candidates.

Objects equal up to a similarity (translation, rotation, uniform scale) share a kind. An
object's :class:`_Signature` holds its complex moments ``c_k = integral (z - centroid)^k
dA`` (or along its lines), which turn by ``k t`` under a rotation by ``t``; their
magnitudes over ``size gyration^k`` are the similarity invariants (:func:`_invariants`)
that pick the candidate kinds (:func:`_candidates`, and :func:`_candidate_pairs` for all
objects of a file at once on a grid of the invariants), and :func:`_match` recovers the
rotation and scale of a candidate and checks it by the largest outline distance both
ways. :func:`control_outline_of` hashes control points up to a similarity, so that
copies moved by rewriting their path data are found without flattening. Signatures are
computed in bulk (:func:`_signatures`: shapely's array functions and numpy for a whole
batch, issue 17.3).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import shapely

from ..shape import Path, paths_to_polygon
from ._svg_flatten import ARC, Segments

__all__: list[str] = []

# Matching flattens each object at this fraction of its own radius: a scale-invariant
# tolerance samples similar copies at the same curve parameters, so that their vertex sets
# are similar too and scale and rotation come out exact.
_SIGNATURE_TOLERANCE = 1e-3


# -- geometry: moments and similarity matching ----------------------------------------
def _geometry(paths: list[Path]) -> shapely.Geometry:
    if len(paths) == 1 and paths[0].closed and len(paths[0].points) >= 3:
        # one closed path (most objects): what paths_to_polygon returns for a valid ring of
        # positive area, in two shapely calls instead of about ten (issue 17.3)
        ring = shapely.Polygon(paths[0].points)
        if shapely.is_valid(ring) and shapely.area(ring) > 0:
            return ring
    area = paths_to_polygon(paths)
    if not area.is_empty:
        return area
    lines = [shapely.LineString(p.points) for p in paths if not p.closed and len(p.points) >= 2]
    lines += [shapely.LinearRing(p.points) for p in paths if p.closed and len(p.points) >= 3]
    if not lines:
        return shapely.LineString()
    return lines[0] if len(lines) == 1 else shapely.MultiLineString([shapely.LineString(g.coords) for g in lines])


def _connected(geoms: list[shapely.Geometry]) -> bool:
    """Whether geometries form one piece (each linked to the rest by intersections)."""
    n = len(geoms)
    tree = shapely.STRtree(geoms)
    i, j = tree.query(geoms, predicate="intersects")
    parent = list(range(n))

    def find(a: int) -> int:
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a

    for a, b in zip(i.tolist(), j.tolist()):
        ra, rb = find(a), find(b)
        if ra != rb:
            parent[ra] = rb
    return len({find(a) for a in range(n)}) == 1


# Five Gauss-Legendre points integrate polynomials of degree 9 exactly: the integrands
# below, conj(z) z^k dz and z^k ds along a straight edge, have degree k + 1 <= _KMAX + 1.
_GL_X, _GL_W = np.polynomial.legendre.leggauss(5)
_GL_T = (_GL_X + 1) / 2
_GL_W = _GL_W / 2
_KMAX = 8


@dataclass(slots=True)
class _Signature:
    """Similarity invariants of a flattened geometry (complex moments about its centroid)."""

    points: np.ndarray  # (n, 2) all vertices
    outline: shapely.Geometry | None  # boundary lines, for distance checks (None: made when asked, see _outline)
    size: float  # area, or length for line-only geometry
    is_area: bool
    centroid: np.ndarray  # (2,)
    moments: np.ndarray  # (_KMAX + 1,) complex: c_k = integral of (z - centroid)^k
    gyration: float  # radius of gyration
    radius: float  # largest vertex distance from the centroid
    tolerance: float = 0.0  # the flattening tolerance it was computed at


def _outline(sig: _Signature) -> shapely.Geometry:
    """The signature's outline; :func:`_signatures` leaves it to be made here for a ring it
    knows to be simple (the boundary of the polygon of its points, as it would have made
    it; most objects' outlines are never used: issue 17.3)."""
    if sig.outline is None:
        sig.outline = shapely.boundary(shapely.polygons(shapely.linearrings(sig.points)))
    return sig.outline


def _edges(geom: shapely.Geometry, is_area: bool) -> tuple[np.ndarray, np.ndarray]:
    """(m,) complex start and end points of the oriented edges of a geometry.

    In a few vectorised shapely calls (parts, rings, coordinates with their ring index)
    instead of a Python loop over rings (issue 17.3); the same edges in the same order.
    """
    if is_area:
        geom = shapely.orient_polygons(geom) if hasattr(shapely, "orient_polygons") else _orient(geom)
        rings = shapely.get_rings(shapely.get_parts(geom))
    else:
        rings = shapely.get_parts(geom)
    c, idx = shapely.get_coordinates(rings, return_index=True)
    if len(c) < 2:
        return np.zeros(0, complex), np.zeros(0, complex)
    z = c[:, 0] + 1j * c[:, 1]
    same = idx[1:] == idx[:-1]  # consecutive vertices of one ring
    return z[:-1][same], z[1:][same]


def _orient(geom: shapely.Geometry) -> shapely.Geometry:
    from shapely.geometry.polygon import orient

    polys = [orient(p, 1.0) for p in shapely.get_parts(geom)]
    return polys[0] if len(polys) == 1 else shapely.MultiPolygon(polys)


def _moments(a: np.ndarray, b: np.ndarray, is_area: bool, shift: complex, kmax: int = _KMAX) -> tuple[np.ndarray, float]:
    """Complex moments ``c_k`` (k = 0..kmax) and the polar moment about ``shift``.

    Area moments use Green's theorem, ``integral z^k dA = 1/(2i) contour z^k conj(z) dz``;
    line moments integrate ``z^k ds``. Both are exact for polygons (Gauss-Legendre). The
    powers ``z^k`` come from one running product and the sums from one matrix product
    (issue 17.3: a tenth of the cost of a ``(m, q, K)`` power array on small shapes).
    """
    a = a - shift
    b = b - shift
    d = b - a
    z = (a[:, None] + _GL_T[None, :] * d[:, None]).ravel()  # (m q,)
    if is_area:
        w = (np.conj(z) * np.repeat(d, len(_GL_T))) * np.tile(_GL_W, len(d))  # conj(z) dz
    else:
        w = np.repeat(np.abs(d), len(_GL_T)) * np.tile(_GL_W, len(d))  # ds
    zk = np.empty((len(z), kmax + 1), complex)
    zk[:, 0] = 1.0
    if kmax >= 1:
        for k in range(1, kmax + 1):  # the running product (np.cumprod's order, at a tenth of its cost)
            np.multiply(zk[:, k - 1], z, out=zk[:, k])
    c = w @ zk
    zz = (z * np.conj(z)).real
    if is_area:
        c = c / 2j
        polar = float(np.real((zz * w).sum() / 2 / 2j))
    else:
        polar = float((zz * w).sum())
    return c, polar


def _area_centroid(a: np.ndarray, b: np.ndarray, is_area: bool) -> tuple[complex, complex]:
    """``c_0`` and ``c_1`` of :func:`_moments` about 0 in closed form (exact for polygons).

    Per edge ``z = a + t d``: ``integral conj(z) dz = d (conj(a) + conj(d) / 2)`` and
    ``integral z conj(z) dz = d (|a|^2 + Re(a conj(d)) + |d|^2 / 3)``; for lines
    ``|d|`` and ``|d| (a + b) / 2``. A third of the cost of the quadrature (issue 17.3).
    """
    d = b - a
    if is_area:
        c0 = complex((d * (np.conj(a) + np.conj(d) / 2)).sum()) / 2j
        c1 = complex((d * ((a * np.conj(a)).real + (a * np.conj(d)).real + (d * np.conj(d)).real / 3)).sum()) / 2j
    else:
        ds = np.abs(d)
        c0 = complex(ds.sum())
        c1 = complex((ds * (a + b)).sum()) / 2
    return c0, c1


def _signature(paths: list[Path]) -> _Signature | None:
    geom = _geometry(paths)
    if geom.is_empty:
        return None
    is_area = geom.geom_type in ("Polygon", "MultiPolygon")
    a, b = _edges(geom, is_area)
    c0 = _area_centroid(a, b, is_area)
    size = float(np.real(c0[0]))
    if not size > 0:
        return None
    centroid = complex(c0[1] / c0[0])
    c, polar = _moments(a, b, is_area, centroid)
    pts = np.concatenate([p.points for p in paths])
    cen = np.array([centroid.real, centroid.imag])
    outline = geom.boundary if is_area else geom
    return _Signature(
        points=pts,
        outline=outline,
        size=size,
        is_area=is_area,
        centroid=cen,
        moments=c,
        gyration=math.sqrt(max(polar, 0.0) / size),
        radius=float(np.sqrt(((pts - cen) ** 2).sum(axis=1)).max()),
    )


_SIMPLE_MAX = 16  # most vertices of a ring that _surely_simple tests (pairs of edges grow as k^2)
# Shewchuk's error bound for the orientation's sign in floating point, (3 + 16 eps) eps,
# times 4 to spare
_ORIENT_BOUND = 4 * (3 + 16 * 2.0**-53) * 2.0**-53


def _surely_simple(coords: np.ndarray, lens: np.ndarray) -> np.ndarray:
    """(n,) bool: whether each ring (``coords`` (m, 2) cut into rings of ``lens`` points,
    each closed back to its first) is certainly simple, so that its polygon is valid and
    of positive area; False where that is not certain (shapely then decides).

    A ring of at most ``_SIMPLE_MAX`` points is certainly simple when every three
    consecutive vertices turn (no repeated point, no spike, no straight vertex) and every
    two edges that share no vertex lie apart: the ends of one on one side of the other's
    line. Each side is decided by the sign of an orientation determinant only where it
    exceeds its rounding error bound (Shewchuk's filter, the test shapely's GEOS makes
    exactly), so what is found simple is (issue 17.3: GEOS's validity test of every
    object cost more than the moments).
    """
    n = len(lens)
    out = np.zeros(n, dtype=bool)
    first = np.cumsum(lens) - lens
    for k in range(3, _SIMPLE_MAX + 1):
        objs = np.flatnonzero(lens == k)
        if not len(objs):
            continue
        p = coords[first[objs][:, None] + np.arange(k)]  # (n_k, k, 2)
        x, y = p[..., 0], p[..., 1]

        def turns(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> np.ndarray:
            """The sign (+1, -1, or 0 where unsure) of the turn a -> b -> c, per pair of columns."""
            left = (x[:, a] - x[:, c]) * (y[:, b] - y[:, c])
            right = (y[:, a] - y[:, c]) * (x[:, b] - x[:, c])
            det = left - right
            sure = np.abs(det) > _ORIENT_BOUND * (np.abs(left) + np.abs(right))
            return np.where(sure, np.sign(det), 0.0)

        with np.errstate(invalid="ignore", over="ignore"):
            i = np.arange(k)
            ok = (turns(i, (i + 1) % k, (i + 2) % k) != 0).all(axis=1)
            # edges (i, i + 1) and (j, j + 1) that share no vertex
            ii, jj = np.triu_indices(k, 2)
            apart = ~((ii == 0) & (jj == k - 1))
            ii, jj = ii[apart], jj[apart]
            if len(ii):
                i1, j1 = (ii + 1) % k, (jj + 1) % k
                s1, s2 = turns(ii, i1, jj), turns(ii, i1, j1)
                s3, s4 = turns(jj, j1, ii), turns(jj, j1, i1)
                ok &= (((s1 * s2) > 0) | ((s3 * s4) > 0)).all(axis=1)
        out[objs] = ok
    return out


def _signatures(batch: list[list[Path]]) -> list[_Signature | None]:
    """:func:`_signature` of many objects at once (issue 17.3).

    Objects drawn by one closed path whose polygon is valid (most objects), or whose
    self-intersecting polygon shapely's ``make_valid`` repairs into polygons, go through
    shapely's array functions and numpy once for the whole batch: polygons, validity,
    repair, orientation, edges, then the moments of every edge, summed per object; the
    rest go through :func:`_signature` one by one. The same figures up to rounding (the sums run
    in another order).
    """
    out: list[_Signature | None] = [None] * len(batch)
    one = [i for i, paths in enumerate(batch) if len(paths) == 1 and paths[0].closed and len(paths[0].points) >= 3]
    polys = np.zeros(0, dtype=object)
    valid = good = np.zeros(0, dtype=bool)
    if one:
        pts_list = [batch[i][0].points for i in one]
        lens = np.array([len(p) for p in pts_list])
        coords = np.concatenate(pts_list)
        last = np.cumsum(lens) - 1
        open_ring = (coords[last - lens + 1] != coords[last]).any(axis=1)  # first point not repeated at the end
        if not open_ring.all():
            one = [i for i, o in zip(one, open_ring.tolist()) if o]
            pts_list = [p for p, o in zip(pts_list, open_ring.tolist()) if o]
            lens = lens[open_ring]
            coords = np.concatenate(pts_list) if pts_list else np.zeros((0, 2))
    if one:
        # rings certainly simple need no polygon (their outlines are made when asked, see
        # _outline); shapely decides the others
        valid = _surely_simple(coords, lens)
        good = valid.copy()
        polys = np.full(len(one), None, dtype=object)
        unsure = np.flatnonzero(~valid)
        if len(unsure):
            cnt = lens[unsure]
            at = np.repeat(np.arange(len(unsure)), cnt)
            pick = np.repeat((np.cumsum(lens) - lens)[unsure], cnt) + (np.arange(len(at)) - np.repeat(np.cumsum(cnt) - cnt, cnt))
            polys[unsure] = shapely.polygons(shapely.linearrings(coords[pick], indices=at))
            valid[unsure] = shapely.is_valid(polys[unsure])
            good[unsure] = valid[unsure] & (shapely.area(polys[unsure]) > 0)
    # Self-intersecting rings: repaired as paths_to_polygon repairs them (make_valid, its
    # polygons of positive area), all at once; where that gives anything but polygons,
    # or nothing, the object goes through _signature.
    geom_of = {k: g for k, g in zip(np.flatnonzero(good).tolist(), polys[good])}
    broken = np.flatnonzero(~valid)
    if len(broken):
        parts, owner = shapely.get_parts(shapely.make_valid(polys[broken]), return_index=True)
        kind = shapely.get_type_id(parts)
        odd = set(owner[(kind != 3) & (kind != 1) & (kind != 0) & (kind != 5) & (kind != 4)].tolist())  # not polygon, line or point
        areal = (kind == 3) & (shapely.area(parts) > 0)
        for j in sorted(set(owner[areal].tolist()) - odd):
            found = parts[areal & (owner == j)]
            geom_of[int(broken[j])] = found[0] if len(found) == 1 else shapely.MultiPolygon(list(found))
    sel = np.array(sorted(geom_of), dtype=np.intp)
    rest = set(range(len(batch))) - {one[k] for k in sel.tolist()}
    for i in sorted(rest):
        out[i] = _signature(batch[i])
    if not len(sel):
        return out
    polys = np.array([geom_of[k] for k in sel.tolist()], dtype=object)
    n = len(sel)
    # Valid one-ring polygons: their edges straight from the path's points, in the path's
    # direction; a clockwise ring's contour integrals change sign, and are turned back
    # below (what orienting it first gives, up to rounding, at no shapely call).
    simple = np.isin(sel, np.flatnonzero(good))
    js = np.flatnonzero(simple)
    cnt_s = lens[sel[js]]
    first_s = (np.cumsum(lens) - lens)[sel[js]]
    pos = np.repeat(first_s - (np.cumsum(cnt_s) - cnt_s), cnt_s) + np.arange(int(cnt_s.sum()))
    nxt = pos + 1
    ring_end = np.cumsum(cnt_s) - 1  # each ring's last point is followed by its first
    nxt[ring_end] = first_s
    zs = coords[:, 0] + 1j * coords[:, 1]
    a_s, b_s, obj_s = zs[pos], zs[nxt], np.repeat(js, cnt_s)
    # the others (repaired): every ring of every oriented polygon, holes clockwise
    jr = np.flatnonzero(~simple)
    if len(jr):
        parts, part_owner = shapely.get_parts(shapely.orient_polygons(polys[jr]), return_index=True)
        rings, ring_part = shapely.get_rings(parts, return_index=True)
        c, ridx = shapely.get_coordinates(rings, return_index=True)
        z = c[:, 0] + 1j * c[:, 1]
        same = ridx[1:] == ridx[:-1]
        order = np.argsort(np.r_[obj_s, jr[part_owner[ring_part[ridx[:-1][same]]]]], kind="stable")
        a = np.r_[a_s, z[:-1][same]][order]
        b = np.r_[b_s, z[1:][same]][order]
        obj = np.r_[obj_s, jr[part_owner[ring_part[ridx[:-1][same]]]]][order]
    else:
        a, b, obj = a_s, b_s, obj_s
    d = b - a
    # area and centroid in closed form (as _area_centroid), summed per object
    e0 = d * (np.conj(a) + np.conj(d) / 2) / 2j
    e1 = d * ((a * np.conj(a)).real + (a * np.conj(d)).real + (d * np.conj(d)).real / 3) / 2j
    c0 = np.bincount(obj, e0.real, n) + 1j * np.bincount(obj, e0.imag, n)
    c1 = np.bincount(obj, e1.real, n) + 1j * np.bincount(obj, e1.imag, n)
    turn = np.where(c0.real < 0, -1.0, 1.0)  # clockwise rings: every contour integral negated
    c0, c1 = c0 * turn, c1 * turn
    size = c0.real
    centroid = c1 / c0
    # moments about each object's centroid (as _moments, area case)
    q = len(_GL_T)
    a, b = a - centroid[obj], b - centroid[obj]
    d = b - a
    zq = (a[:, None] + _GL_T[None, :] * d[:, None]).ravel()
    w = (np.conj(zq) * np.repeat(d, q)) * np.tile(_GL_W, len(d))
    # w z^k for k = 0, 1, ... in one running product, summed per object as it goes (one
    # array of the quadrature points, not one per power: large fresh arrays cost more in
    # page faults than in arithmetic)
    starts = np.searchsorted(obj, np.arange(n)) * q  # edges come object by object
    mom = np.empty((n, _KMAX + 1), complex)
    acc = w.copy()
    for k in range(_KMAX + 1):
        mom[:, k] = np.add.reduceat(acc, starts)
        if k < _KMAX:
            acc *= zq
    mom /= 2j
    mom *= turn[:, None]
    polar = (np.add.reduceat((zq * np.conj(zq)).real * w, starts) / 2 / 2j).real * turn
    outlines = np.full(n, None, dtype=object)
    made = np.array([g is not None for g in polys.tolist()], dtype=bool)
    outlines[made] = shapely.boundary(polys[made])
    pts_all = coords if len(sel) == len(one) else np.concatenate([pts_list[k] for k in sel.tolist()])
    cnt = lens[sel]
    first = np.cumsum(cnt) - cnt
    cen_all = np.c_[centroid.real, centroid.imag]
    radius = np.maximum.reduceat(np.sqrt(((pts_all - np.repeat(cen_all, cnt, axis=0)) ** 2).sum(axis=1)), first)
    for k, outline, cen, mom_j, size_j, polar_j, radius_j in zip(sel.tolist(), outlines.tolist(), cen_all, mom, size.tolist(), polar.tolist(), radius.tolist()):
        if not size_j > 0:
            continue
        i = one[k]
        out[i] = _Signature(batch[i][0].points, outline, size_j, True, cen, mom_j, math.sqrt(max(polar_j, 0.0) / size_j), radius_j)
    return out


def _invariants(sig: _Signature | None) -> list[float]:
    """size, radius, gyration, tolerance, +-1 (area or lines), then ``|c_k| / (size gyration^k)``
    for k = 2 .. _KMAX: the similarity invariants :meth:`._svg_import._Reader.candidate_kinds` compares."""
    if sig is None or not sig.size > 0:
        return [math.nan] * 4 + [0.0] + [math.nan] * (_KMAX - 1)
    g = max(sig.gyration, 1e-300)
    mags = [abs(sig.moments[k]) / (sig.size * g**k) for k in range(2, _KMAX + 1)]
    return [sig.size, sig.radius, sig.gyration, sig.tolerance, 1.0 if sig.is_area else -1.0, *mags]


_POWERS = [float(k) for k in range(2, _KMAX + 1)]


def _invariants_many(sigs: list[_Signature | None]) -> np.ndarray:
    """(n, 5 + _KMAX - 1) the rows :func:`_invariants` gives, for many signatures at once
    (the same arithmetic elementwise, so the same numbers)."""
    rows = np.empty((len(sigs), 5 + _KMAX - 1))
    rows[:] = _invariants(None)
    ok = [i for i, sig in enumerate(sigs) if sig is not None and sig.size > 0]
    if not ok:
        return rows
    have = [sigs[i] for i in ok]
    size = np.array([sig.size for sig in have])  # type: ignore[union-attr]
    g = np.maximum(np.array([sig.gyration for sig in have]), 1e-300)  # type: ignore[union-attr]
    mom = np.array([sig.moments[2:] for sig in have])  # type: ignore[union-attr]
    # Python's powers and hypot (numpy's array power and complex abs round otherwise)
    # (math.pow(v, float(k)) is v**k: both C's pow of the same doubles; mapped at once,
    # at a third of a list comprehension's cost)
    power = np.fromiter(map(math.pow, np.repeat(g, _KMAX - 1).tolist(), _POWERS * len(g)), float, (_KMAX - 1) * len(g)).reshape(-1, _KMAX - 1)
    rows[ok, 0] = size
    rows[ok, 1] = [sig.radius for sig in have]  # type: ignore[union-attr]
    rows[ok, 2] = [sig.gyration for sig in have]  # type: ignore[union-attr]
    rows[ok, 3] = [sig.tolerance for sig in have]  # type: ignore[union-attr]
    rows[ok, 4] = [1.0 if sig.is_area else -1.0 for sig in have]  # type: ignore[union-attr]
    rows[ok, 5:] = np.hypot(mom.real, mom.imag) / (size[:, None] * power)
    return rows


def _match(ref: _Signature, other: _Signature) -> tuple[float, float] | None:
    """Similarity ``other = s R(t) (ref - ref.centroid) + other.centroid``, or None.

    The rotation comes from the phase of the first complex moment ``c_k`` (k >= 2) that
    the shape's symmetry does not cancel: ``c_k`` turns by ``k t`` under a rotation by ``t``.
    Each candidate is checked by the largest vertex-to-outline distance both ways.
    """
    if ref.is_area != other.is_area:
        return None
    s = math.sqrt(other.size / ref.size) if ref.is_area else other.size / ref.size
    tolerance = max(other.tolerance, s * ref.tolerance)
    if abs(other.radius - s * ref.radius) > 2 * tolerance + 0.02 * other.radius:
        return None
    if abs(other.gyration - s * ref.gyration) > 2 * tolerance + 0.02 * other.gyration:
        return None
    candidates: list[float] = []
    first_wins = False
    used = 0
    norm_r = ref.size * max(ref.gyration, 1e-300)
    norm_o = other.size * max(other.gyration, 1e-300)
    for k in range(2, _KMAX + 1):
        mr = abs(ref.moments[k]) / (norm_r * ref.gyration ** (k - 1))
        mo = abs(other.moments[k]) / (norm_o * other.gyration ** (k - 1))
        if mr > 0.02 and mo > 0.02:
            base = (np.angle(other.moments[k]) - np.angle(ref.moments[k])) / k
            candidates.extend(base + 2 * math.pi * j / k for j in range(k))
            used += 1
            if used == 2:  # a second order guards against a noisy phase in the first
                break
    if not candidates:
        # Nearly round: align the farthest vertex, else try no rotation.
        far = np.argmax(((other.points - other.centroid) ** 2).sum(axis=1))
        vo = other.points[far] - other.centroid
        vr = ref.points - ref.centroid
        rr = np.sqrt((vr**2).sum(axis=1))
        near = np.flatnonzero(np.abs(s * rr - np.hypot(*vo)) <= 2 * tolerance + 0.01 * other.radius)
        candidates = [0.0] + [math.atan2(vo[1], vo[0]) - math.atan2(vr[i, 1], vr[i, 0]) for i in near[:32]]
        first_wins = True  # a round shape: keep rotation 0 when it fits
    # Both outlines lie within ``tolerance`` of the true curves; allow a little more for
    # the pose estimate and for rounding in the file's numbers.
    limit = 3 * tolerance + 1e-4 * other.radius
    best: tuple[float, float] | None = None
    best_err = math.inf
    for t in candidates:
        c, sn = math.cos(t), math.sin(t)
        rot = s * np.array([[c, -sn], [sn, c]])
        moved = (ref.points - ref.centroid) @ rot.T + other.centroid
        err = float(shapely.distance(_outline(other), shapely.points(moved)).max())
        if err > limit:
            continue
        outline = shapely.transform(_outline(ref), lambda p, rot=rot: (p - ref.centroid) @ rot.T + other.centroid)
        err = max(err, float(shapely.distance(outline, shapely.points(other.points)).max()))
        if err <= limit and err < best_err:
            best, best_err = (float(math.atan2(sn, c)), s), err
            if first_wins:
                break
    return best


_GRID = 0.05  # cell size of the kinds' grid on the invariants |c_k| / (size gyration^k), k = 2, 3, 4
_GRID_DIMS = (5, 6, 7)  # their columns in :func:`_invariants`' rows


def _cell(row: list[float] | np.ndarray) -> tuple[int, ...]:
    return tuple(int(math.floor(float(row[j]) / _GRID)) for j in _GRID_DIMS)


def _cells_near(row: list[float]) -> list[tuple[int, ...]]:
    """Cells holding every value ``a`` that :func:`_candidates` accepts next to ``b``:
    ``|a - b| <= 0.01 + 0.02 max(a, b)``, so ``0.98 b - 0.01 <= a <= (b + 0.01) / 0.98``."""
    if not all(math.isfinite(row[j]) for j in _GRID_DIMS):
        return []
    spans = []
    for j in _GRID_DIMS:
        b = float(row[j])
        lo, hi = 0.98 * b - 0.01, (b + 0.01) / 0.98  # widened below by far more than rounding
        spans.append(range(int(math.floor((lo - 1e-6) / _GRID)), int(math.floor((hi + 1e-6) / _GRID)) + 1))
    return [(i, j, k) for i in spans[0] for j in spans[1] for k in spans[2]]


def _candidates(table: np.ndarray, sig: _Signature, row: list[float] | None = None) -> np.ndarray:
    """Rows of ``table`` (kinds' :func:`_invariants`) that may match ``sig`` (see :meth:`._svg_import._Reader.candidate_kinds`);
    ``row`` is ``_invariants(sig)`` where the caller has it."""
    if row is None:
        row = _invariants(sig)
    size, radius, gyration, tol, area = table[:, :5].T
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        scale = np.sqrt(sig.size / size) if sig.is_area else sig.size / size
        t = np.maximum(sig.tolerance, scale * tol)
        ok = (area == row[4]) & np.isfinite(size)
        ok &= ~(np.abs(sig.radius - scale * radius) > 2 * t + 0.02 * sig.radius)
        ok &= ~(np.abs(sig.gyration - scale * gyration) > 2 * t + 0.02 * sig.gyration)
        mk, mo = table[:, 5:], np.array(row[5:])
        # 0.01 + 2%: copies matched in the tests differ by at most 0.001 + 0.25% (their
        # flattenings differ); 0.05 + 10% let a growing share of n distinct shapes reach
        # the full match, n^2 in all (10 MB of distinct polygons: 28 s/MB against 11 at 1 MB)
        ok &= ~(np.abs(mk - mo) > 0.01 + 0.02 * np.maximum(mk, mo)).any(axis=1)
    return np.flatnonzero(ok)


def control_outline_of(key: str | None, segs: Segments, own: np.ndarray) -> tuple[tuple[Any, ...], np.ndarray] | None:
    """``(hash, points)``: the control points of segments ``segs`` drawn by the map ``own``
    in world coordinates (complex, ``(n,)``) and a hash of their shape up to a similarity,
    or None.

    The hash holds ``key``, the segment kinds and the points in the frame that puts the
    first point at 0 and the farthest one at 1, rounded to 1% of the size: copies that
    Inkscape moved, turned or scaled by writing new numbers into the path data hash
    alike (see :meth:`._svg_import._Reader.moved_copy`). Arcs are left out (their radii
    are not points).
    """
    n = len(segs.code)
    if n == 0 or n > 512 or ARC in segs.code:
        return None
    if own[0, 0] * own[1, 1] - own[0, 1] * own[1, 0] <= 0:
        return None  # a mirror image is another kind: leave it to the matcher
    if segs.code.any():
        used = np.ones((n, 4), dtype=bool)
        used[:, 1] = segs.code != 0
        used[:, 2] = segs.code == 2
        local = segs.pts[used]
    else:  # lines only: starts and ends
        local = segs.pts[:, ::3].reshape(-1, 2)
    z = (local[:, 0] * own[0, 0] + local[:, 1] * own[0, 1] + own[0, 2]) + 1j * (local[:, 0] * own[1, 0] + local[:, 1] * own[1, 1] + own[1, 2])
    rel = z - z[0]
    d = np.abs(rel)
    far = int(np.argmax(d))
    if not (d[far] > 0) or not math.isfinite(float(d[far])):
        return None
    canon = rel / rel[far]
    q = np.round(canon.view(np.float64) * 100).astype(np.int64)
    return (key or "", segs.code.tobytes(), segs.sub.tobytes(), segs.closed.tobytes(), far, q.tobytes()), z


def _outline_table(items: list[tuple[str | None, Segments, np.ndarray]]) -> dict[str, Any] | None:
    """The arrays :func:`_control_outlines` and :func:`_outline_digests` cut per object:
    ``sel`` (the objects that may have an outline), their control points ``z`` and
    rounded canonical points ``q``, per object ``start``, ``end``, ``far``, ``top`` and
    the running count ``bad`` of non-finite points; None when no object may have one."""
    if not items:
        return None
    counts = np.array([len(segs.code) for _, segs, _ in items])
    maps = np.array([own for _, _, own in items]).reshape(len(items), 2, 3)
    det = maps[:, 0, 0] * maps[:, 1, 1] - maps[:, 0, 1] * maps[:, 1, 0]
    arcs = np.zeros(len(items), dtype=bool)
    if counts.any():
        codes = np.concatenate([segs.code for _, segs, _ in items])
        has = counts > 0
        arcs[has] = np.logical_or.reduceat(codes == ARC, (np.cumsum(counts) - counts)[has])
    # no arcs, at most 512 segments; a mirror image (det <= 0) is another kind: left to the matcher
    sel = np.flatnonzero((counts > 0) & (counts <= 512) & ~arcs & (det > 0)).tolist()
    if not sel:
        return None
    code = np.concatenate([items[i][1].code for i in sel])
    pts = np.concatenate([items[i][1].pts for i in sel])
    nseg = np.array([len(items[i][1].code) for i in sel])
    used = np.ones((len(code), 4), dtype=bool)
    used[:, 1] = code != 0
    used[:, 2] = code == 2
    local = pts[used]
    npts = np.bincount(np.repeat(np.arange(len(sel)), nseg), used.sum(axis=1), len(sel)).astype(np.intp)
    own = np.array([items[i][2] for i in sel])[np.repeat(np.arange(len(sel)), npts)]
    z = (local[:, 0] * own[:, 0, 0] + local[:, 1] * own[:, 0, 1] + own[:, 0, 2]) + 1j * (local[:, 0] * own[:, 1, 0] + local[:, 1] * own[:, 1, 1] + own[:, 1, 2])
    start = np.cumsum(npts) - npts
    obj = np.repeat(np.arange(len(sel)), npts)
    rel = z - z[start][obj]
    d = np.abs(rel)
    finite = np.isfinite(rel)
    bad = np.r_[0, np.cumsum(~finite)]
    end = start + npts
    top = np.maximum.reduceat(d, start)
    # the first point at the largest distance (np.argmax's choice)
    is_top = d == top[obj]
    far_at = np.minimum.reduceat(np.where(is_top, np.arange(len(d)), len(d)), start)
    far = far_at - start
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        canon = rel / rel[far_at][obj]
        q = np.round(canon.view(np.float64) * 100).astype(np.int64)
    return {"sel": sel, "code": code, "nseg": nseg, "z": z, "q": q, "start": start, "end": end, "far": far, "top": top, "bad": bad}


def _control_outlines(items: list[tuple[str | None, Segments, np.ndarray]]) -> list[tuple[tuple[Any, ...], np.ndarray] | None]:
    """:func:`control_outline_of` of many objects, ``(key, segments, own map)`` each,
    in one batch of numpy (issue 17.3): the same hashes and points, elementwise the same
    arithmetic. Objects with a point that is not finite are left to the function."""
    out: list[tuple[tuple[Any, ...], np.ndarray] | None] = [None] * len(items)
    t = _outline_table(items)
    if t is None:
        return out
    sel, code, nseg, z, q, start, end, far, top, bad = (t[k] for k in ("sel", "code", "nseg", "z", "q", "start", "end", "far", "top", "bad"))
    # the hash's bytes cut from the bytes of all objects at once (the same bytes as each
    # object's own arrays give)
    qb = q.tobytes()
    codeb = code.tobytes()
    subb = np.concatenate([items[i][1].sub for i in sel]).tobytes()
    closed = [items[i][1].closed for i in sel]
    nclosed = np.fromiter(map(len, closed), dtype=np.intp, count=len(sel))
    closedb = np.concatenate(closed).tobytes()
    seg0 = (np.cumsum(nseg) - nseg).tolist()
    cl0 = (np.cumsum(nclosed) - nclosed).tolist()
    bad_l, top_l, far_l = bad.tolist(), top.tolist(), far.tolist()
    wq, wcode, wsub, wcl = q.itemsize * 2, code.itemsize, subb and len(subb) // len(code), closedb and len(closedb) // max(1, int(nclosed.sum()))
    for j, (i, s0, s1, a0, na, c0, nc) in enumerate(zip(sel, start.tolist(), end.tolist(), seg0, nseg.tolist(), cl0, nclosed.tolist())):
        if bad_l[s1] != bad_l[s0] or not math.isfinite(top_l[j]):
            out[i] = control_outline_of(*items[i])
            continue
        if not top_l[j] > 0:
            continue
        key = (items[i][0] or "", codeb[wcode * a0 : wcode * (a0 + na)], subb[wsub * a0 : wsub * (a0 + na)], closedb[wcl * c0 : wcl * (c0 + nc)], far_l[j], qb[wq * s0 : wq * s1])
        out[i] = (key, z[s0:s1])
    return out


def _outline_digests(items: list[tuple[str | None, Segments, np.ndarray]]) -> tuple[np.ndarray, np.ndarray]:
    """A 64-bit digest of each object's :func:`control_outline_of` hash, all at once.

    Objects whose hashes are equal have equal digests (the digest is a sum of the hash's
    numbers times fixed random weights, wrapping), so an object whose digest no other
    object shares is a moved copy of none of them, and its hash need not be made
    (issue 17.3: on a drawing of distinct shapes, making every hash cost 10% of the
    reading). ``key`` is left out (equal shapes under other names share a digest).

    Returns
    -------
    state : (n,) int8
        0: no outline (``control_outline_of`` gives None); 1: digested; 2: not digested
        (a point that is not finite: left to ``control_outline_of``).
    digest : (n,) uint64
        The digest where ``state`` is 1.
    """
    n = len(items)
    if n > _DIGEST_BLOCK:
        # in blocks: each object's digest is its own, and one block's arrays stay small
        # (fresh large arrays cost more in page faults than in arithmetic: 10 MB of
        # distinct polygons in one batch took 2x the time per object of 1 MB)
        done = [_outline_digests(items[lo : lo + _DIGEST_BLOCK]) for lo in range(0, n, _DIGEST_BLOCK)]
        return np.concatenate([d[0] for d in done]), np.concatenate([d[1] for d in done])
    state = np.zeros(n, np.int8)
    digest = np.zeros(n, np.uint64)
    t = _outline_table(items)
    if t is None:
        return state, digest
    sel = np.asarray(t["sel"], dtype=np.intp)
    start, end, far, top, bad, q, code, nseg = (t[k] for k in ("start", "end", "far", "top", "bad", "q", "code", "nseg"))
    with np.errstate(invalid="ignore"):
        finite = (bad[end] == bad[start]) & np.isfinite(top)
        has = finite & (top > 0)
    state[sel[~finite]] = 2
    state[sel[has]] = 1
    m = len(sel)
    npts = end - start
    # weights by position within an object (up to 4 points per segment, 512 segments)
    weights = _DIGEST_WEIGHTS
    pos = np.arange(len(q) // 2) - np.repeat(start, npts)
    qq = q.reshape(-1, 2).astype(np.uint64)
    per_point = qq[:, 0] * weights[2 * pos] + qq[:, 1] * weights[2 * pos + 1]
    h = np.add.reduceat(per_point, start) if len(per_point) else np.zeros(m, np.uint64)
    seg0 = np.cumsum(nseg) - nseg
    spos = np.arange(len(code)) - np.repeat(seg0, nseg)
    subs = np.concatenate([items[i][1].sub for i in t["sel"]]).astype(np.uint64)
    per_seg = code.astype(np.uint64) * weights[4096 + spos] + subs * weights[4608 + spos]
    h = h + np.add.reduceat(per_seg, seg0) * weights[5120]
    closed = [items[i][1].closed for i in t["sel"]]
    ncl = np.fromiter(map(len, closed), dtype=np.intp, count=m)
    cpos = np.arange(int(ncl.sum())) - np.repeat(np.cumsum(ncl) - ncl, ncl)
    per_cl = np.concatenate(closed).astype(np.uint64) * weights[5121 + np.minimum(cpos, 511)] + weights[5633]
    hc = np.zeros(m, np.uint64)
    some = ncl > 0
    if some.any():
        hc[some] = np.add.reduceat(per_cl, (np.cumsum(ncl) - ncl)[some])
    h = h + hc * weights[5634] + far.astype(np.uint64) * weights[5635] + npts.astype(np.uint64) * weights[5636] + nseg.astype(np.uint64) * weights[5637]
    digest[sel] = h
    return state, digest


_DIGEST_BLOCK = 4096  # objects per block in _outline_digests
# fixed random odd weights for _outline_digests (any fixed values keep equal hashes' digests equal)
_DIGEST_WEIGHTS = np.random.default_rng(20261123).integers(0, 2**63, 5640, dtype=np.uint64) * np.uint64(2) + np.uint64(1)


def _candidate_pairs(rows: np.ndarray, valid: np.ndarray) -> tuple[np.ndarray, np.ndarray] | None:
    """For each object ``j``, the earlier objects ``i < j`` whose :func:`_invariants` row
    passes :func:`_candidates`' tests as a kind against ``j``'s signature (issue 17.3).

    ``rows`` (n, 5 + _KMAX - 1) are the objects' invariants; ``valid`` (n,) says which
    have a signature (the others are neither kinds that can match nor matched). Pairs
    are found on a grid of the moment invariants k = 2, 3, 4 whose cells are as wide as
    the largest difference :func:`_candidates` accepts, so only neighbouring cells are
    compared, then tested with :func:`_candidates`' own arithmetic on the pairs.

    Returns
    -------
    (start (n + 1,), earlier (m,)) or None
        Object ``j``'s candidates are ``earlier[start[j]:start[j + 1]]``, ascending. None
        when an invariant is not finite (:func:`_candidates`' NaN rules are left to it)
        or the grid would be too large.
    """
    n = len(rows)
    idx = np.flatnonzero(valid)
    if len(idx) and not np.isfinite(rows[idx]).all():
        return None
    if len(idx) < 2:
        return np.zeros(n + 1, dtype=np.intp), np.zeros(0, dtype=np.intp)
    sub = rows[idx]
    # |a - b| <= 0.01 + 0.02 max(a, b) (a, b >= 0) gives min + 0.5 >= 0.98 (max + 0.5):
    # on log(v + 0.5) every accepted pair is within -log(0.98) in each dimension
    with np.errstate(invalid="ignore"):
        pts = np.log(sub[:, list(_GRID_DIMS)] + 0.5)
    if not np.isfinite(pts).all():
        return None
    r = -math.log(0.98) * (1 + 1e-6) + 1e-9
    cell = np.floor(pts / r).astype(np.int64)
    cell -= cell.min(axis=0)
    span = cell.max(axis=0) + 3
    if float(span[0]) * float(span[1]) * float(span[2]) > 2.0**60:
        return None
    key = ((cell[:, 0] + 1) * span[1] + (cell[:, 1] + 1)) * span[2] + (cell[:, 2] + 1)
    order = np.argsort(key, kind="stable")
    sorted_key = key[order]
    # the occupied cells, each with its first position in sorted_key and its count: one
    # search per neighbouring cell instead of two (issue 17.3)
    cells, cell_lo = np.unique(sorted_key, return_index=True)
    cell_cnt = np.diff(np.r_[cell_lo, len(sorted_key)])
    last_cell = len(cells) - 1
    qs, ks = [], []
    m = len(idx)
    cols = {col: np.ascontiguousarray(sub[:, col]) for col in _PRE_COLS}
    # Queries in blocks, each block's pairs tested before the next block's are made, so
    # that memory holds one block's neighbours, not all (on 50 MB of distinct polygons,
    # 460k objects, every neighbour at once took 20 GB).
    # The queries go in the order of their cells (a sorted search is faster), blocks of
    # them at a time; the pairs are sorted at the end.
    # each occupied cell's neighbour in each direction, found once per cell rather than
    # once per query: (the cell's index, whether it is occupied)
    steps = [(dx * span[1] + dy) * span[2] + dz for dx in (-1, 0, 1) for dy in (-1, 0, 1) for dz in (-1, 0, 1)]
    near_at, near_hit = [], []
    for step in steps:
        target = cells + step
        at = np.minimum(np.searchsorted(cells, target), last_cell)
        near_at.append(at)
        near_hit.append(cells[at] == target)
    cell_of = np.repeat(np.arange(len(cells)), cell_cnt)  # of each position in sorted_key
    for b0 in range(0, m, _PAIR_BLOCK):
        qidx = order[b0 : b0 + _PAIR_BLOCK]
        qcell = cell_of[b0 : b0 + _PAIR_BLOCK]
        for at_all, hit_all in zip(near_at, near_hit):
            at = at_all[qcell]
            hit = hit_all[qcell]
            lo = cell_lo[at]
            cnt = np.where(hit, cell_cnt[at], 0)
            total = int(cnt.sum())
            if not total:
                continue
            q = np.repeat(qidx, cnt)
            k = order[np.repeat(lo - (np.cumsum(cnt) - cnt), cnt) + np.arange(total)]
            keep = k < q  # the kind is the earlier object
            q, k = q[keep], k[keep]
            # the moment tests of the columns the grid does not hold first, column
            # by column on what passes (the same elementwise arithmetic as
            # _pair_test's, so a pair dropped here fails it too): the full test then
            # gathers whole rows only for the few left (on 10 MB of distinct
            # polygons, 1.9M neighbours to 500 pairs)
            for col in _PRE_COLS:
                if len(q) <= 64:
                    break
                a, b = cols[col][k], cols[col][q]
                near = ~(np.abs(a - b) > 0.01 + 0.02 * np.maximum(a, b))
                q, k = q[near], k[near]
            ok = _pair_test(sub[k], sub[q])
            qs.append(q[ok])
            ks.append(k[ok])
    q = np.concatenate(qs) if qs else np.zeros(0, dtype=np.intp)
    k = np.concatenate(ks) if ks else np.zeros(0, dtype=np.intp)
    q, k = idx[q], idx[k]
    order = np.lexsort((k, q))
    q, k = q[order], k[order]
    start = np.searchsorted(q, np.arange(n + 1), "left")
    return start.astype(np.intp), k.astype(np.intp)


_PAIR_BLOCK = 4096  # queries per block in _candidate_pairs
# moment invariant columns (k = 5 .. _KMAX) tested alone before the full test in _candidate_pairs
_PRE_COLS = tuple(range(5 + len(_GRID_DIMS), 5 + _KMAX - 1))


def _pair_test(kr: np.ndarray, qr: np.ndarray) -> np.ndarray:
    """_candidates' tests of kind rows ``kr`` against the rows ``qr`` of the signatures,
    pair by pair, in its arithmetic: (m,) bool."""
    size, radius, gyration, tol, area = kr[:, :5].T
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        scale = np.where(qr[:, 4] == 1.0, np.sqrt(qr[:, 0] / size), qr[:, 0] / size)
        t = np.maximum(qr[:, 3], scale * tol)
        ok = (area == qr[:, 4]) & np.isfinite(size)
        ok &= ~(np.abs(qr[:, 1] - scale * radius) > 2 * t + 0.02 * qr[:, 1])
        ok &= ~(np.abs(qr[:, 2] - scale * gyration) > 2 * t + 0.02 * qr[:, 2])
        mk, mo = kr[:, 5:], qr[:, 5:]
        ok &= ~(np.abs(mk - mo) > 0.01 + 0.02 * np.maximum(mk, mo)).any(axis=1)
    return ok


def _candidates_few(table: list[list[float]], rows: list[int], sig: _Signature, row: list[float]) -> list[int]:
    """:func:`_candidates` on a few rows of the table, in plain floats (the same tests and the
    same answers; a non-finite number anywhere goes to :func:`_candidates`, whose NaN rules
    it then keeps)."""
    vals = [table[i] for i in rows]
    if not all(math.isfinite(v) for r in vals for v in r) or not all(math.isfinite(v) for v in row):
        sub = np.array(vals).reshape(len(vals), len(row))
        return [rows[j] for j in _candidates(sub, sig, row)]
    out = []
    mo = row[5:]
    for i, r in zip(rows, vals):
        size, radius, gyration, tol, area = r[:5]
        if area != row[4]:
            continue
        if not size > 0:  # an infinite scale: numpy's rules
            out.extend(i for _ in _candidates(np.array([r]), sig, row))
            continue
        scale = math.sqrt(sig.size / size) if sig.is_area else sig.size / size
        t = max(sig.tolerance, scale * tol)
        if abs(sig.radius - scale * radius) > 2 * t + 0.02 * sig.radius:
            continue
        if abs(sig.gyration - scale * gyration) > 2 * t + 0.02 * sig.gyration:
            continue
        if any(abs(a - b) > 0.01 + 0.02 * max(a, b) for a, b in zip(r[5:], mo)):
            continue
        out.append(i)
    return out
