"""Shape overlap tests for elements whose collision disc is smaller than their shape.

Extension of §4.1. The bounding disc is the paper's collision bound, but for an
elongated shape it is far larger than the room the shape takes (the suite's sticks, 24
long, sit 4 apart at random angles), so ``collision_radii`` shrinks such a kind's disc to
the exemplar's spacing, and shrunk discs alone let copies cross each other. Region
growing then packed about 8x more sticks than survived the final overlap clean-up of
``SynthState.to_arrangement`` (65-115 s for the suite's sticks): every copy that
crossed another covered free space, and the optimiser (§5.2) pulled neighbours across
each other, which opened free space again. Here the shapes themselves are tested:
copies a growing step places, before they join the output, and elements the optimiser
moved, after it (a move that makes shapes overlap is put back).

Two shapes clash when they overlap as :func:`strew.metrics.overlaps` counts it
(intersection area above 1e-9; strokes when they touch), or when they come closer than
0.95 of a gap ``g_ab (1 - f)``: ``g_ab`` is the closest approach of the two kinds'
shapes in the exemplar, and ``f`` the smaller of their disc factors ``rc / r`` (see
``collision_radii``), the share of the exemplar's spacing the shrunk discs still carry.
Without the gap the sticks, 1 apart in their exemplar, packed to touching and came out
1.3x too dense; with the whole gap, ring tiles (discs shrunk to 0.8) could not be copied
a little closer than their tightest exemplar pair and the rings broke (0/5 seeds
faithful against 4/5).

Only for exemplars without overlaps and only where some selected element's disc is
shrunk below 0.9 of its bounding radius (a disc that bounds its shape needs no test;
the clean-up still catches what is left).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
import shapely
from scipy.spatial import cKDTree

if TYPE_CHECKING:
    from ._prepare import Prepared
    from ._state import SynthState

__all__ = ["shape_test_needed", "clearance", "element_geometries", "local_segments", "shape_clashes", "shapes_overlapping"]

SHRUNK = 0.9  # a collision disc below this share of the bounding radius needs the shape test


def shape_test_needed(prep: Prepared) -> bool:
    """Whether the selection's collision discs leave shapes free to overlap (see module)."""
    sel = prep.selected_elements
    return bool(prep.overlap_free and (prep.rc < SHRUNK * prep.r)[sel].any())


def element_geometries(prep: Prepared, src: np.ndarray, pos: np.ndarray) -> np.ndarray:
    """(m,) shapely geometries of copies of exemplar elements ``src`` (m,) at ``pos`` (m, 2)."""
    names = list(prep.shapes)
    src = np.asarray(src, np.int64)
    kind, rot, scale = prep.kind[src], prep.rotation[src], np.asarray(prep.scale, float)[src]
    out = np.empty(len(src), dtype=object)
    for k in np.unique(kind):
        idx = np.flatnonzero(kind == k)
        local = prep.shapes[names[int(k)]].geometry
        nc = int(shapely.get_num_coordinates(local))
        c = np.repeat(np.cos(rot[idx]) * scale[idx], nc)
        s = np.repeat(np.sin(rot[idx]) * scale[idx], nc)
        tx, ty = np.repeat(pos[idx, 0], nc), np.repeat(pos[idx, 1], nc)

        def f(p: np.ndarray, c=c, s=s, tx=tx, ty=ty) -> np.ndarray:
            return np.c_[tx + c * p[:, 0] - s * p[:, 1], ty + s * p[:, 0] + c * p[:, 1]]

        out[idx] = shapely.transform(np.full(len(idx), local, dtype=object), f)
    return out


def local_segments(prep: Prepared) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Each kind's shape as plain segments, for compiled shape tests. Cached on ``prep``.

    Returns ``(seg, kptr, areal, centre_in, krad)``: ``seg`` (s, 4) float, the edges
    ``ax, ay, bx, by`` of the kinds' local geometries (``prep.shapes`` in kind order;
    polygons' rings, lines' pieces, a point as a segment of length 0), kind ``k``'s rows
    ``kptr[k]:kptr[k + 1]``; ``areal`` (kinds,) bool, whether the kind's rings bound an
    area (even-odd over its edges); ``centre_in`` (kinds,) bool, whether its origin lies
    in its shape; ``krad`` (kinds,) float, the largest distance of a local vertex from
    its origin.
    """
    got = getattr(prep, "_local_segments", None)
    if got is not None:
        return got
    segs, kptr, areal, centre_in, krad = [], [0], [], [], []
    for name in prep.shapes:
        geom = prep.shapes[name].geometry
        parts = shapely.get_parts(geom)
        rings = []
        for p in parts:
            if isinstance(p, shapely.Polygon):
                rings.extend([p.exterior, *p.interiors])
            elif isinstance(p, shapely.Point):
                xy = shapely.get_coordinates(p)
                rings.append(np.r_[xy, xy])
            else:
                rings.append(p)
        s = [np.c_[c[:-1], c[1:]] for c in (np.asarray(r.coords if hasattr(r, "coords") else r, float)[:, :2] for r in rings) if len(c) >= 2]
        s = np.concatenate(s) if s else np.zeros((0, 4))
        segs.append(s)
        kptr.append(kptr[-1] + len(s))
        areal.append(bool(shapely.area(geom) > 0))
        centre_in.append(bool(shapely.intersects_xy(geom, 0.0, 0.0)))
        krad.append(float(np.sqrt((np.r_[s[:, :2], s[:, 2:]] ** 2).sum(axis=1)).max()) if len(s) else 0.0)
    got = (np.ascontiguousarray(np.concatenate(segs) if segs else np.zeros((0, 4)), dtype=float), np.asarray(kptr, np.int64),
           np.asarray(areal, bool), np.asarray(centre_in, bool), np.asarray(krad, float))
    prep._local_segments = got
    return got


def clearance(prep: Prepared) -> np.ndarray:
    """(kinds, kinds) float: closest approach of two kinds' shapes within one exemplar.

    Times ``1 - f`` (the smaller disc factor of the two kinds, see the module), so
    the gap that :func:`shape_clashes` keeps. Cached on ``prep``. Pairs of kinds that
    never come within twice the largest bounding radius of each other, or that touch,
    get 0 (then only overlap counts).
    """
    if prep.shape_clearance is not None:
        return prep.shape_clearance
    nk = len(prep.shapes)
    out = np.full((nk, nk), np.inf)
    reach = 2.0 * float(prep.r.max())
    for s in np.unique(prep.source):
        el = np.flatnonzero(prep.source == s)
        pairs = cKDTree(prep.pos[el]).query_pairs(reach, output_type="ndarray")
        if len(pairs) == 0:
            continue
        a, b = el[pairs[:, 0]], el[pairs[:, 1]]
        g = element_geometries(prep, el, prep.pos[el])
        where = np.full(len(prep.kind), -1, np.int64)
        where[el] = np.arange(len(el))
        d = shapely.distance(g[where[a]], g[where[b]])
        ka, kb = prep.kind[a], prep.kind[b]
        np.minimum.at(out, (ka, kb), d)
        np.minimum.at(out, (kb, ka), d)
    out[~np.isfinite(out)] = 0.0
    # the share of the spacing that the shrunk discs no longer carry (see module)
    f = np.ones(nk)
    np.minimum.at(f, prep.kind, prep.rc / prep.r)
    out *= 1.0 - np.minimum.outer(f, f)
    prep.shape_clearance = out
    return out


def _pair_overlaps(ga: np.ndarray, gb: np.ndarray, cl: np.ndarray, tolerance: float = 1e-9) -> np.ndarray:
    """(c,) bool: pairs that overlap as :func:`strew.metrics.overlaps` counts it, or come
    closer than 0.95 of their gap ``cl`` (c,) where it is positive (see :func:`clearance`)."""
    apart = cl > 0
    out = shapely.intersects(ga, gb)
    if apart.any():
        out[apart] = shapely.dwithin(ga[apart], gb[apart], 0.95 * cl[apart])
    areal = out & ~apart & (shapely.area(ga) > 0) & (shapely.area(gb) > 0)
    if areal.any():
        out[areal] = shapely.area(shapely.intersection(ga[areal], gb[areal])) > tolerance
    return out


def _against_output(state: SynthState, g: np.ndarray, src: np.ndarray, pos: np.ndarray, skip: np.ndarray | None, gap: bool = True) -> np.ndarray:
    """(m,) bool: geometries ``g`` overlapping an output element (other than ``skip[i]``)."""
    m = len(g)
    prep = state.prep
    if state.n == 0 or m == 0:
        return np.zeros(m, bool)
    near = cKDTree(state.pos).query_ball_point(pos, r=prep.r[src] + float(prep.r.max()))
    cnt = np.fromiter((len(v) for v in near), np.int64, m)
    left = np.repeat(np.arange(m), cnt)
    right = np.fromiter((j for v in near for j in v), np.int64, int(cnt.sum()))
    if skip is not None:
        keep = right != skip[left]
        left, right = left[keep], right[keep]
    if len(left) == 0:
        return np.zeros(m, bool)
    uniq, inv = np.unique(right, return_inverse=True)
    g_old = element_geometries(prep, state.src[uniq], state.pos[uniq])
    cl = clearance(prep)[prep.kind[src[left]], prep.kind[state.src[uniq[inv]]]] * gap
    ov = _pair_overlaps(g[left], g_old[inv], cl)
    return np.bincount(left[ov], minlength=m) > 0


def shape_clashes(state: SynthState, src: np.ndarray, pos: np.ndarray) -> np.ndarray:
    """(m,) bool: copies of exemplar elements ``src`` at ``pos`` (m, 2) whose shapes
    overlap an output element's, or an earlier copy's of the same batch."""
    src = np.asarray(src, np.int64)
    prep = state.prep
    g = element_geometries(prep, src, pos)
    hit = _against_output(state, g, src, pos, None)
    cl = clearance(prep)
    reach = 0.95 * float(cl.max())
    tree = shapely.STRtree(g)
    a, b = tree.query(g, predicate="dwithin", distance=reach) if reach > 0 else tree.query(g, predicate="intersects")
    keep = a < b
    a, b = a[keep], b[keep]
    if len(a):
        ov = _pair_overlaps(g[a], g[b], cl[prep.kind[src[a]], prep.kind[src[b]]])
        a, b = a[ov], b[ov]
        order = np.lexsort((b, a))
        for i, j in zip(a[order], b[order]):
            if not hit[i]:
                hit[j] = True
    return hit


def shapes_overlapping(state: SynthState, idx: np.ndarray) -> np.ndarray:
    """(m,) bool: output elements ``idx`` whose shapes overlap another output element."""
    idx = np.asarray(idx, np.int64)
    src, pos = state.src[idx], state.pos[idx]
    return _against_output(state, element_geometries(state.prep, src, pos), src, pos, idx)
