"""Exact tests of the fill-gap engine (Sakurai & Miyata §4.2) and the store they read.

A pose (T + s R p, Eq. 1) of a kind's exclusive region is accepted only when it lies
inside the domain and meets no placed region: closed-segment intersection and even-odd
point-in-polygon tests (:mod:`strew._kernels.geometry`, robust at relative tolerance
:data:`TOL`: touching or too close to call counts as a collision) against the neighbours
found in the hashed incremental grid (:mod:`strew._kernels.grid`, its arrays ``head``,
``tail``, ``ent``, ``ext``; placed regions never move, so every entry is current) and
against the domain's edges (a hashed grid built at once). The placed regions live in flat arrays (a ring layout, see :func:`ring_layout`)
that :func:`_insert` appends to; the integer state vector ``st`` holds the counters
named by the ``_S_*`` indices. Split from ``_fit.py`` (issue 15 point 7).
"""

from __future__ import annotations

import numba
import numpy as np
import shapely

from .._kernels.geometry import TOL, where as _where
from .._kernels.geometry import seg_hit as _seg_hit
from .._kernels.grid import HASH_X, HASH_Y, hash_insert_box, hash_span

__all__ = ["TOL", "ring_layout"]

# indices into the integer state vector
_S_CONSEC, _S_NEXT, _S_TRIALS, _S_POSES, _S_NP, _S_NV, _S_NR, _S_NE, _S_QID, _S_ROUNDS = range(10)


def ring_layout(geoms: list) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Flat closed rings of several geometries.

    Returns
    -------
    verts : (v, 2) float
        Ring vertices, each ring closed (its last vertex repeats the first).
    rings : (r + 1,) int64
        Ring ``i`` spans ``verts[rings[i]:rings[i + 1]]``.
    owner : (g + 1,) int64
        Geometry ``j`` owns rings ``owner[j]:owner[j + 1]``.
    """
    verts, rings, owner = [], [0], [0]
    for g in geoms:
        for ring in shapely.get_rings(shapely.get_parts(g)):
            xy = shapely.get_coordinates(ring)
            verts.append(xy)
            rings.append(rings[-1] + len(xy))
        owner.append(len(rings) - 1)
    v = np.concatenate(verts) if verts else np.zeros((0, 2))
    return np.ascontiguousarray(v, dtype=float), np.asarray(rings, dtype=np.int64), np.asarray(owner, dtype=np.int64)


@numba.njit(cache=True)
def _polys_hit(av, arings, ar0, ar1, abb, bv, brings, br0, br1, bbb, buf):  # pragma: no cover - numba
    """True when polygon a (rings ``ar0:ar1``) and polygon b intersect (closed sets)."""
    ox0 = max(abb[0], bbb[0])
    oy0 = max(abb[1], bbb[1])
    ox1 = min(abb[2], bbb[2])
    oy1 = min(abb[3], bbb[3])
    if ox0 > ox1 or oy0 > oy1:
        return False
    # b's edges that reach the boxes' overlap
    nb = 0
    for r in range(br0, br1):
        for i in range(brings[r], brings[r + 1] - 1):
            x1, y1, x2, y2 = bv[i, 0], bv[i, 1], bv[i + 1, 0], bv[i + 1, 1]
            if min(x1, x2) > ox1 or max(x1, x2) < ox0 or min(y1, y2) > oy1 or max(y1, y2) < oy0:
                continue
            buf[nb] = i
            nb += 1
    if nb > 0:
        for r in range(ar0, ar1):
            for i in range(arings[r], arings[r + 1] - 1):
                x1, y1, x2, y2 = av[i, 0], av[i, 1], av[i + 1, 0], av[i + 1, 1]
                if min(x1, x2) > ox1 or max(x1, x2) < ox0 or min(y1, y2) > oy1 or max(y1, y2) < oy0:
                    continue
                for t in range(nb):
                    j = buf[t]
                    if _seg_hit(x1, y1, x2, y2, bv[j, 0], bv[j, 1], bv[j + 1, 0], bv[j + 1, 1]):
                        return True
    # no edges cross: each ring lies in one face of the other polygon, so one vertex per
    # ring decides containment either way
    for r in range(ar0, ar1):
        px, py = av[arings[r], 0], av[arings[r], 1]
        if bbb[0] <= px <= bbb[2] and bbb[1] <= py <= bbb[3] and _where(px, py, bv, brings, br0, br1) != 0:
            return True
    for r in range(br0, br1):
        px, py = bv[brings[r], 0], bv[brings[r], 1]
        if abb[0] <= px <= abb[2] and abb[1] <= py <= abb[3] and _where(px, py, av, arings, ar0, ar1) != 0:
            return True
    return False


@numba.njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _pose(kv, kr, r0, r1, x, y, c, sn, out, bb):  # pragma: no cover - numba
    """Transform rings ``r0:r1`` of a kind (T + s R p, Eq. 1, with ``c = s cos t`` and
    ``sn = s sin t``) into ``out``; fill bbox."""
    bb[0] = np.inf
    bb[1] = np.inf
    bb[2] = -np.inf
    bb[3] = -np.inf
    for i in range(kr[r0], kr[r1]):
        px = x + c * kv[i, 0] - sn * kv[i, 1]
        py = y + sn * kv[i, 0] + c * kv[i, 1]
        out[i, 0] = px
        out[i, 1] = py
        bb[0] = min(bb[0], px)
        bb[1] = min(bb[1], py)
        bb[2] = max(bb[2], px)
        bb[3] = max(bb[3], py)


@numba.njit(cache=True)
def _in_region(hv, hr, r0, r1, hbb, rv, rr, rsegs, g, rhead, rent, rext, rstamp, qid):  # pragma: no cover - numba
    """True when the posed hull (rings ``r0:r1`` of ``hv``) lies inside the domain.

    ``g`` = (cell, x0, y0, x1, y1): the hashed grids' cell side and a box around the
    domain; ``rhead``, ``rent``, ``rext``: the hashed grid of the domain's edges.
    """
    if hbb[0] < g[1] or hbb[1] < g[2] or hbb[2] > g[3] or hbb[3] > g[4]:
        return False
    cx0, cy0, cx1, cy1 = hash_span(hbb[0], hbb[1], hbb[2], hbb[3], g[0], rext)
    mask = rhead.shape[0] - 1
    # no hull edge meets a domain edge
    for cx in range(cx0, cx1 + 1):
        for cy in range(cy0, cy1 + 1):
            e = rhead[((cx * HASH_X) ^ (cy * HASH_Y)) & mask]
            while e >= 0:
                sid = rent[e, 0]
                hit = rent[e, 1] == cx and rent[e, 2] == cy and rstamp[sid] != qid
                e = rent[e, 3]
                if not hit:
                    continue
                rstamp[sid] = qid
                ax, ay, bx, by = rsegs[sid, 0], rsegs[sid, 1], rsegs[sid, 2], rsegs[sid, 3]
                if max(ax, bx) < hbb[0] or min(ax, bx) > hbb[2] or max(ay, by) < hbb[1] or min(ay, by) > hbb[3]:
                    continue
                for r in range(r0, r1):
                    for i in range(hr[r], hr[r + 1] - 1):
                        if _seg_hit(hv[i, 0], hv[i, 1], hv[i + 1, 0], hv[i + 1, 1], ax, ay, bx, by):
                            return False
    # every hull ring inside the domain (even-odd over all domain rings)
    for r in range(r0, r1):
        if _where(hv[hr[r], 0], hv[hr[r], 1], rv, rr, np.int64(0), len(rr) - 1) != 1:  # np.int64: see _rounds
            return False
    # and no domain ring (a hole) inside the hull
    for r in range(len(rr) - 1):
        px, py = rv[rr[r], 0], rv[rr[r], 1]
        if hbb[0] <= px <= hbb[2] and hbb[1] <= py <= hbb[3] and _where(px, py, hv, hr, r0, r1) != 0:
            return False
    return True


@numba.njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _collides(cv, kr, r0, r1, cbb, pv, pr, pp, pbb, g, head, ent, ext, stamp, qid, buf, blocker):  # pragma: no cover - numba
    """True when the posed body meets a placed exclusive region (grid neighbours only).

    ``blocker[0]`` is the region that stopped the last pose (-1: none); it is tested
    first, since the poses tried at one candidate point mostly meet the same neighbour.
    """
    b = blocker[0]
    if b >= 0:
        stamp[b] = qid
        if not (pbb[b, 0] > cbb[2] or pbb[b, 2] < cbb[0] or pbb[b, 1] > cbb[3] or pbb[b, 3] < cbb[1]):
            if _polys_hit(cv, kr, r0, r1, cbb, pv, pr, pp[b], pp[b + 1], pbb[b], buf):
                return True
    cx0, cy0, cx1, cy1 = hash_span(cbb[0], cbb[1], cbb[2], cbb[3], g[0], ext)
    mask = head.shape[0] - 1
    for cx in range(cx0, cx1 + 1):
        for cy in range(cy0, cy1 + 1):
            e = head[((cx * HASH_X) ^ (cy * HASH_Y)) & mask]
            while e >= 0:
                p = ent[e, 0]
                hit = ent[e, 1] == cx and ent[e, 2] == cy and stamp[p] != qid
                e = ent[e, 3]
                if not hit:
                    continue
                stamp[p] = qid
                if pbb[p, 0] > cbb[2] or pbb[p, 2] < cbb[0] or pbb[p, 1] > cbb[3] or pbb[p, 3] < cbb[1]:
                    continue
                if _polys_hit(cv, kr, r0, r1, cbb, pv, pr, pp[p], pp[p + 1], pbb[p], buf):
                    blocker[0] = p
                    return True
    return False


@numba.njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _insert(k, x, y, rot, s, cv, kr, kk, cbb, pv, pr, pp, pbb, pose, pkind, g, head, tail, ent, ext, st):  # pragma: no cover - numba
    """Append the posed body (already in ``cv``) to the placed store and the grid."""
    n, nv, nr, ne = st[_S_NP], st[_S_NV], st[_S_NR], st[_S_NE]
    for r in range(kk[k], kk[k + 1]):
        for i in range(kr[r], kr[r + 1]):
            pv[nv, 0] = cv[i, 0]
            pv[nv, 1] = cv[i, 1]
            nv += 1
        nr += 1
        pr[nr] = nv
    pp[n + 1] = nr
    for j in range(4):
        pbb[n, j] = cbb[j]
    pose[n, 0] = x
    pose[n, 1] = y
    pose[n, 2] = rot
    pose[n, 3] = s
    pkind[n] = k
    ne = hash_insert_box(g[0], head, tail, ent, ext, ne, n, cbb[0], cbb[1], cbb[2], cbb[3])
    st[_S_NP], st[_S_NV], st[_S_NR], st[_S_NE] = n + 1, nv, nr, ne


@numba.njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _wrap(v, lo, period):  # pragma: no cover - numba
    """``v`` moved by whole periods into ``[lo, lo + period)``."""
    v = v - period * np.floor((v - lo) / period)
    if v >= lo + period:  # rounding of a tiny negative offset
        v = lo
    return v


@numba.njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _collides_torus(cv, kr, r0, r1, cbb, pv, pr, pp, pbb, g, head, ent, ext, stamp, st, buf, blocker, per, ct, tbb):  # pragma: no cover - numba
    """:func:`_collides` on the torus of a repeat tile (issue 18): the posed body at its
    canonical place and its images by the lattice translations whose boxes reach the
    placed regions (their reference points lie in the tile, so their boxes lie within
    ``per[4]`` of it). The body cannot meet its own images: the tile is at least twice
    its circumscribed diameter (checked in :func:`strew.pack.pack`)."""
    x0, y0, w, h, reach = per[0], per[1], per[2], per[3], per[4]
    for ti in range(-1, 2):
        for tj in range(-1, 2):
            dx = ti * w
            dy = tj * h
            if (cbb[0] + dx > x0 + w + reach or cbb[2] + dx < x0 - reach
                    or cbb[1] + dy > y0 + h + reach or cbb[3] + dy < y0 - reach):
                continue
            st[_S_QID] += 1  # a fresh stamp: each image meets the neighbours anew
            if ti == 0 and tj == 0:
                if _collides(cv, kr, r0, r1, cbb, pv, pr, pp, pbb, g, head, ent, ext, stamp, st[_S_QID], buf, blocker):
                    return True
                continue
            for i in range(kr[r0], kr[r1]):
                ct[i, 0] = cv[i, 0] + dx
                ct[i, 1] = cv[i, 1] + dy
            tbb[0] = cbb[0] + dx
            tbb[1] = cbb[1] + dy
            tbb[2] = cbb[2] + dx
            tbb[3] = cbb[3] + dy
            if _collides(ct, kr, r0, r1, tbb, pv, pr, pp, pbb, g, head, ent, ext, stamp, st[_S_QID], buf, blocker):
                return True
    return False
