"""Step 2 of the fill-gap method (Sakurai & Miyata §4.2) as one compiled loop.

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

import math

import numba
import numpy as np
import shapely

from ._exclusive import ExclusiveRegion
from ._field import _occupy_posed

__all__ = ["FitEngine", "ring_layout"]

# kernel status codes
RUNNING, DONE, NEED_ROOM, NO_FIELD = 0, 1, 2, 3
# candidate sampling: side of the pixel blocks whose maxima bound the draw (see _draw_q)
BLOCK = 4
# within blocks near the maximum, pixels whose alpha is at most LOW_P are thinned first
LOW_P = 1.0 / 64.0
# for pb = 2**-j: log(1 - pb), and the chance 1 - (1 - pb)**(BLOCK**2) that a block has a pick
# (j up to 63; the draw's cut keeps pb above 1e-9, so j stays below 30)
_LOGQ = np.r_[-np.inf, np.log1p(-(2.0 ** -np.arange(1.0, 64.0)))]
_ANY = -np.expm1(BLOCK * BLOCK * _LOGQ)
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


# Relative tolerance of the exact tests: an orientation whose value is within TOL of the
# magnitude of its two products, or a crossing within TOL of the point it is compared
# with, counts as touching (far above the rounding of these few operations, about
# 3.3e-16, so the sign of every other decision is certain). Touching is a collision, so
# doubtful cases are cancelled: a placement the tests accept is disjoint from its
# neighbours and inside the domain, with no rounding to argue about.
TOL = 1e-12


@numba.njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _cell_span(gx0, gy0, gc, cols, rows, xmin, ymin, xmax, ymax):  # pragma: no cover - numba
    """Grid cells ``(c0, c1, q0, q1)`` (inclusive, clamped) that a box touches."""
    c0 = max(int((xmin - gx0) / gc), 0)
    c1 = min(int((xmax - gx0) / gc), cols - 1)
    q0 = max(int((ymin - gy0) / gc), 0)
    q1 = min(int((ymax - gy0) / gc), rows - 1)
    return c0, c1, q0, q1


@numba.njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _orient(ax, ay, bx, by, cx, cy):  # pragma: no cover - numba
    """Orientation of c about ab: +1, -1, or 0 when too close to call (within TOL)."""
    u = (bx - ax) * (cy - ay)
    v = (by - ay) * (cx - ax)
    det = u - v
    if abs(det) <= TOL * (abs(u) + abs(v)):
        return 0
    return 1 if det > 0 else -1


@numba.njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _seg_hit(ax, ay, bx, by, cx, cy, dx, dy):  # pragma: no cover - numba
    """Closed segments ab and cd meet, or come too close to call (touching counts;
    collinear overlap counts)."""
    if max(ax, bx) < min(cx, dx) or max(cx, dx) < min(ax, bx):
        return False
    if max(ay, by) < min(cy, dy) or max(cy, dy) < min(ay, by):
        return False
    d1 = _orient(cx, cy, dx, dy, ax, ay)
    d2 = _orient(cx, cy, dx, dy, bx, by)
    if d1 * d2 > 0:
        return False  # ab lies strictly on one side of the line cd
    d3 = _orient(ax, ay, bx, by, cx, cy)
    d4 = _orient(ax, ay, bx, by, dx, dy)
    # a proper crossing, or a zero orientation with overlapping boxes (touching,
    # collinear, or too close to call): reject (a cancellation only makes it stricter)
    return d3 * d4 <= 0


@numba.njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _inside(px, py, v, rings, r0, r1):  # pragma: no cover - numba
    """Even-odd point in the rings ``r0:r1`` of a flat ring layout."""
    inside = False
    for r in range(r0, r1):
        for i in range(rings[r], rings[r + 1] - 1):
            ay = v[i, 1]
            by = v[i + 1, 1]
            if (ay > py) != (by > py):
                ax = v[i, 0]
                xc = ax + (py - ay) * (v[i + 1, 0] - ax) / (by - ay)
                if px < xc:
                    inside = not inside
    return inside


@numba.njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _where(px, py, v, rings, r0, r1):  # pragma: no cover - numba
    """Even-odd point in the rings ``r0:r1``: 1 inside, 0 outside, -1 when a crossing
    lies within TOL of the point (too close to call)."""
    inside = False
    for r in range(r0, r1):
        for i in range(rings[r], rings[r + 1] - 1):
            ay = v[i, 1]
            by = v[i + 1, 1]
            if (ay > py) != (by > py):
                ax = v[i, 0]
                bx = v[i + 1, 0]
                xc = ax + (py - ay) * (bx - ax) / (by - ay)
                if abs(px - xc) <= TOL * (abs(px) + abs(ax) + abs(bx)):
                    return -1
                if px < xc:
                    inside = not inside
    return 1 if inside else 0


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
def _in_region(hv, hr, r0, r1, hbb, rv, rr, rsegs, g, rhead, rnext, rsid, rstamp, qid):  # pragma: no cover - numba
    """True when the posed hull (rings ``r0:r1`` of ``hv``) lies inside the domain.

    ``g`` = (x0, y0, cell, cols, rows) of the grid that holds the domain's edges.
    """
    gx0, gy0, gc, cols, rows = g[0], g[1], g[2], int(g[3]), int(g[4])
    if hbb[0] < gx0 or hbb[1] < gy0 or hbb[2] > gx0 + cols * gc or hbb[3] > gy0 + rows * gc:
        return False
    c0, c1, q0, q1 = _cell_span(gx0, gy0, gc, cols, rows, hbb[0], hbb[1], hbb[2], hbb[3])
    # no hull edge meets a domain edge
    for q in range(q0, q1 + 1):
        for c in range(c0, c1 + 1):
            e = rhead[q * cols + c]
            while e >= 0:
                sid = rsid[e]
                e = rnext[e]
                if rstamp[sid] == qid:
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
def _collides(cv, kr, r0, r1, cbb, pv, pr, pp, pbb, g, head, enext, epoly, stamp, qid, buf, blocker):  # pragma: no cover - numba
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
    gx0, gy0, gc, cols, rows = g[0], g[1], g[2], int(g[3]), int(g[4])
    c0, c1, q0, q1 = _cell_span(gx0, gy0, gc, cols, rows, cbb[0], cbb[1], cbb[2], cbb[3])
    for q in range(q0, q1 + 1):
        for c in range(c0, c1 + 1):
            e = head[q * cols + c]
            while e >= 0:
                p = epoly[e]
                e = enext[e]
                if stamp[p] == qid:
                    continue
                stamp[p] = qid
                if pbb[p, 0] > cbb[2] or pbb[p, 2] < cbb[0] or pbb[p, 1] > cbb[3] or pbb[p, 3] < cbb[1]:
                    continue
                if _polys_hit(cv, kr, r0, r1, cbb, pv, pr, pp[p], pp[p + 1], pbb[p], buf):
                    blocker[0] = p
                    return True
    return False


@numba.njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _insert(k, x, y, rot, s, cv, kr, kk, cbb, pv, pr, pp, pbb, pose, pkind, g, head, enext, epoly, st):  # pragma: no cover - numba
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
    gx0, gy0, gc, cols, rows = g[0], g[1], g[2], int(g[3]), int(g[4])
    c0, c1, q0, q1 = _cell_span(gx0, gy0, gc, cols, rows, cbb[0], cbb[1], cbb[2], cbb[3])
    for q in range(q0, q1 + 1):
        for c in range(c0, c1 + 1):
            cell = q * cols + c
            enext[ne] = head[cell]
            epoly[ne] = n
            head[cell] = ne
            ne += 1
    st[_S_NP], st[_S_NV], st[_S_NR], st[_S_NE] = n + 1, nv, nr, ne


@numba.njit(cache=True)
def _place_sparse(xy, u_rot, u_sc, kinds, kv, kr, kk, hv, hr, hk, same_hull, rot_lo, rot_hi, sc_lo, sc_hi,
                  rv, rr, rsegs, rhead, rnext, rsid, rstamp, cv, ch, cbb, hbb,
                  pv, pr, pp, pbb, pose, pkind, g, head, enext, epoly, st, per):  # pragma: no cover - numba
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
            inside = _in_region(cv, kr, kk[k], kk[k + 1], cbb, rv, rr, rsegs, g, rhead, rnext, rsid, rstamp, st[_S_QID])
        else:
            _pose(hv, hr, hk[k], hk[k + 1], x, y, c, sn, ch, hbb)
            inside = _in_region(ch, hr, hk[k], hk[k + 1], hbb, rv, rr, rsegs, g, rhead, rnext, rsid, rstamp, st[_S_QID])
        if not inside:
            continue
        _insert(k, x, y, rot, s, cv, kr, kk, cbb, pv, pr, pp, pbb, pose, pkind, g, head, enext, epoly, st)
        placed += 1
        if len(kinds) == 0:
            st[_S_NEXT] = (st[_S_NEXT] + 1) % nk
    return placed


@numba.njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _amax(a):  # pragma: no cover - numba
    """Largest value of a non-empty 1-d array, NaN if it holds one: ``a.max()`` written
    as a loop (numba compiles ``ndarray.max`` through ``np.nditer`` and ``take``, several
    seconds of a first run; issue 16)."""
    m = a[0]
    if np.isnan(m):
        return m
    for i in range(1, len(a)):
        v = a[i]
        if np.isnan(v):
            return v
        if v > m:
            m = v
    return m


@numba.njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _alpha(r, power):  # pragma: no cover - numba
    if power == 16.0:
        r = r * r
        r = r * r
        r = r * r
        return r * r
    return r**power


@numba.njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _rand(state):  # pragma: no cover - numba
    """Uniform double in [0, 1) from xoshiro256+ (``state``: (4,) uint64, not all zero),
    compiled: the loops draw several numbers per pose, and a call into numpy's generator
    costs more than the rest of a rejected pose. Small helpers here are plain kernels,
    not ``inline="always"``: LLVM inlines them just the same, while numba's own inlining
    retypes each call site (issue 16: first-run compile of pack about 15% shorter)."""
    s0, s1, s2, s3 = state[0], state[1], state[2], state[3]
    out = s0 + s3
    t = s1 << np.uint64(17)
    s2 ^= s0
    s3 ^= s1
    s1 ^= s2
    s0 ^= s3
    s2 ^= t
    s3 = (s3 << np.uint64(45)) | (s3 >> np.uint64(19))
    state[0], state[1], state[2], state[3] = s0, s1, s2, s3
    return float(out >> np.uint64(11)) * (1.0 / 9007199254740992.0)


def rand_state(gen: np.random.Generator) -> np.ndarray:
    """(4,) uint64 seed of the compiled loops' generator (:func:`_rand`), drawn from
    ``gen``: the same ``gen`` gives the same stream."""
    return gen.integers(1, 2**63, size=4, dtype=np.uint64)


@numba.njit(cache=True)
def _block_max(d, w, bme, bmd, br0, br1, bc0, bc1):  # pragma: no cover - numba
    """Refresh the maxima of ``e = d w`` and of ``d`` over the BLOCK x BLOCK pixel
    blocks ``br0:br1`` x ``bc0:bc1``."""
    rows, cols = d.shape
    bcols = (cols + BLOCK - 1) // BLOCK
    for br in range(br0, br1):
        for bc in range(bc0, bc1):
            me = 0.0
            md = 0.0
            for r in range(br * BLOCK, min(br * BLOCK + BLOCK, rows)):
                for c in range(bc * BLOCK, min(bc * BLOCK + BLOCK, cols)):
                    md = max(md, d[r, c])
                    me = max(me, d[r, c] * w[r, c])
            bme[br * bcols + bc] = me
            bmd[br * bcols + bc] = md


@numba.njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _refresh(d, w, bme, bmd, r0, r1, c0, c1):  # pragma: no cover - numba
    """Refresh the block maxima after a change to pixels ``r0:r1`` x ``c0:c1``."""
    rows, cols = d.shape
    r0 = max(r0, 0)
    c0 = max(c0, 0)
    r1 = min(r1, rows)
    c1 = min(c1, cols)
    if r1 > r0 and c1 > c0:
        _block_max(d, w, bme, bmd, r0 // BLOCK, (r1 - 1) // BLOCK + 1, c0 // BLOCK, (c1 - 1) // BLOCK + 1)


@numba.njit(cache=True)
def _draw_q(rs, d, w, bme, cut, emax, power, qbuf):  # pragma: no cover - numba
    """Candidate points Q (§4.2): each pixel with ``e = d w > cut`` joins with probability
    ``alpha = (e / emax)**power``, independently; their flat indices go to ``qbuf``.
    Returns their number. ``rs``: the generator state of :func:`_rand`.

    Pixels are visited by blocks. A block whose largest e gives ``(max e / emax)**power
    <= pb = 2**-j`` picks its pixels with probability pb by geometric skips (the pixels
    between are never read; one uniform number decides whether the block has any pick
    at all) and accepts a picked pixel with ``alpha / pb``: the same independent
    Bernoulli(alpha) draws, at a cost that follows the expected number of points rather
    than the number of pixels (most blocks lie far below the maximum, where alpha =
    r**16 is tiny). Blocks at or below the cut are skipped whole. Blocks near the
    maximum (pb at least 1/16) are read pixel by pixel, and there only the pixels whose
    alpha exceeds LOW_P draw a number each; the others are thinned the same way with
    probability LOW_P.
    """
    rows, cols = d.shape
    bcols = (cols + BLOCK - 1) // BLOCK
    inv = 1.0 / emax
    low = emax * LOW_P ** (1.0 / power)  # pixels at or below this have alpha <= LOW_P
    low_step = 1.0 / np.log1p(-LOW_P)
    skip = int(np.floor(np.log1p(-_rand(rs)) * low_step))
    nq = 0
    for b in range(len(bme)):
        if bme[b] <= cut:
            continue
        r0 = (b // bcols) * BLOCK
        c0 = (b % bcols) * BLOCK
        bh = min(BLOCK, rows - r0)
        bw = min(BLOCK, cols - c0)
        n = bh * bw
        pb = _alpha(bme[b] * inv, power)
        if pb >= 0.0625:
            # a block near the maximum: read every pixel; those with alpha above LOW_P
            # draw one number each, the rest are picked with probability LOW_P by
            # geometric skips and accepted with alpha / LOW_P (the same law again)
            for j in range(n):
                r = r0 + j // bw
                c = c0 + j % bw
                e = d[r, c] * w[r, c]
                if e <= cut:
                    continue
                if e > low:
                    if _rand(rs) < _alpha(e * inv, power):
                        qbuf[nq] = r * cols + c
                        nq += 1
                elif skip > 0:
                    skip -= 1
                else:
                    if _rand(rs) * LOW_P < _alpha(e * inv, power):
                        qbuf[nq] = r * cols + c
                        nq += 1
                    skip = int(np.floor(np.log1p(-_rand(rs)) * low_step))
            continue
        else:
            # a power of two at least pb: its logarithm and the chance of no pick in a
            # full block come from tables
            j2 = -math.frexp(pb)[1]  # 2**-(j2 + 1) <= pb < 2**-j2
            pb = math.ldexp(1.0, -j2)
            u = _rand(rs)
            if n == BLOCK * BLOCK and u >= _ANY[j2]:
                continue  # the first pick, at floor(log(1 - u) / log(1 - pb)), lies past the block
            step = 1.0 / _LOGQ[j2]
            j = int(np.floor(np.log1p(-u) * step))
        while j < n:
            r = r0 + j // bw
            c = c0 + j % bw
            e = d[r, c] * w[r, c]
            if e > cut and _rand(rs) * pb < _alpha(e * inv, power):
                qbuf[nq] = r * cols + c
                nq += 1
            j += 1 + int(np.floor(np.log1p(-_rand(rs)) * step))
    return nq


@numba.njit(cache=True)
def _kind_order(target, tol, cnt, n, order):  # pragma: no cover - numba
    """The kinds a candidate tries, in order: most behind its requested share first.

    Gap-fitting kind choice (an extension of §4.2; the paper cycles through the kinds,
    §3.2, and a candidate whose next kind does not fit its gap is cancelled, although
    another kind would). Kind ``k`` may take the ``n + 1``-th place while its count
    stays within ``max(ceil(target[k] (n + 1)), (target[k] + tol) (n + 1))``, so that
    every share stays within ``tol`` above its target (and, the shares summing to one,
    within ``(K - 1) tol`` below) once ``tol (n + 1) >= 1``. Kinds with a zero target
    are never tried.

    Parameters
    ----------
    target : (K,) float
        Requested shares, summing to one.
    tol : float
    cnt : (K,) int64
        Elements of each kind placed so far (``n`` in all).
    order : (K,) int64
        Filled with the kinds to try; returns their number (at least 1).
    """
    nk = len(target)
    m = 0
    for k in range(nk):
        if target[k] <= 0.0:
            continue
        cap = max(math.ceil(target[k] * (n + 1) - 1e-9), (target[k] + tol) * (n + 1))
        if cnt[k] + 1 <= cap:
            order[m] = k
            m += 1
    # insertion sort by deficit target (n + 1) - count, largest first (ties: lower index)
    for i in range(1, m):
        k = order[i]
        dk = target[k] * (n + 1) - cnt[k]
        j = i - 1
        while j >= 0 and target[order[j]] * (n + 1) - cnt[order[j]] < dk:
            order[j + 1] = order[j]
            j -= 1
        order[j + 1] = k
    return m


@numba.njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _wrap(v, lo, period):  # pragma: no cover - numba
    """``v`` moved by whole periods into ``[lo, lo + period)``."""
    v = v - period * np.floor((v - lo) / period)
    if v >= lo + period:  # rounding of a tiny negative offset
        v = lo
    return v


@numba.njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _collides_torus(cv, kr, r0, r1, cbb, pv, pr, pp, pbb, g, head, enext, epoly, stamp, st, buf, blocker, per, ct, tbb):  # pragma: no cover - numba
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
                if _collides(cv, kr, r0, r1, cbb, pv, pr, pp, pbb, g, head, enext, epoly, stamp, st[_S_QID], buf, blocker):
                    return True
                continue
            for i in range(kr[r0], kr[r1]):
                ct[i, 0] = cv[i, 0] + dx
                ct[i, 1] = cv[i, 1] + dy
            tbb[0] = cbb[0] + dx
            tbb[1] = cbb[1] + dy
            tbb[2] = cbb[2] + dx
            tbb[3] = cbb[3] + dy
            if _collides(ct, kr, r0, r1, tbb, pv, pr, pp, pbb, g, head, enext, epoly, stamp, st[_S_QID], buf, blocker):
                return True
    return False


@numba.njit(cache=True)
def _rounds(
    rs, max_rounds, limit, p_count, power, fits, suppress, sup_r, ktarget, ktol, sfit, kanch, ka, kdisk, kdo, kbb,
    d, w, fx0, fy0, fcell, qbuf, cand, cdraw,
    kv, kr, kk, hv, hr, hk, same_hull, rot_lo, rot_hi, sc_lo, sc_hi, cumw,
    rv, rr, rsegs, rhead, rnext, rsid, rstamp,
    pv, pr, pp, pbb, pose, pkind, g, head, enext, epoly, stamp,
    cv, ch, cbb, hbb, buf, segs, caps, st, fcell_y, per, ct, tbb,
):  # pragma: no cover - numba
    """Up to ``max_rounds`` rounds of Step 2 (§4.2); returns a status code.

    ``caps`` = (polygons, vertices, rings, grid entries) that the store can hold; the
    loop returns NEED_ROOM before a round that could overflow it.

    ``ktarget`` (K,) float: the kinds' requested shares for the gap-fitting kind choice
    (see :func:`_kind_order`); empty: one kind per candidate, cyclic or drawn by the
    cumulative weights ``cumw`` (empty: cyclic), as the paper. ``ktol``: the share a
    kind may run ahead of its target. ``sfit``: a candidate's poses run from the largest
    scale of the kind's range down (True) or draw scales uniformly (False, the paper).

    Repeat tiles (issue 18): ``per`` = (x0, y0, W, H, R) makes the domain the torus of
    the tile ``[x0, x0 + W) x [y0, y0 + H)``, R the largest circumscribed radius of a
    posed region; None: the plane. The tests are ``per is None`` on the argument itself,
    so that numba prunes the other branches when it compiles a specialisation: a plain
    pack compiles none of the torus code (issue 16). On the torus a pose's reference point is wrapped
    into the tile, the domain test is void, a pose is tested for collision with its
    images by the lattice translations that reach placed regions, the field's pixels
    (``fcell`` by ``fcell_y``, a whole number across the tile) wrap, and a placement
    updates the field with its wrapped images. ``ct``, ``tbb``: scratch for a translated
    pose.
    """
    rows, cols = d.shape
    pw0 = 0.0
    ph0 = 0.0
    pw = 0.0
    ph = 0.0
    preach = 0.0
    nt = 0  # lattice translations -nt..nt per axis (0: the plane)
    if per is not None:
        pw0, ph0, pw, ph, preach = per[0], per[1], per[2], per[3], per[4]
        nt = 1
    fcm = max(fcell, fcell_y)  # the longer side of a pixel bounds offsets within it
    dflat = d.ravel()
    wflat = w.ravel()
    nkinds = len(kk) - 1
    maxv = 0
    maxr = 0
    for k in range(nkinds):
        maxv = max(maxv, kr[kk[k + 1]] - kr[kk[k]])
        maxr = max(maxr, kk[k + 1] - kk[k])
    blocker = np.empty(1, dtype=np.int64)
    blocker[0] = -1
    # kinds placed so far, and the order in which a candidate tries them
    cnt = np.zeros(nkinds, dtype=np.int64)
    for i in range(st[_S_NP]):
        cnt[pkind[i]] += 1
    korder = np.zeros(nkinds, dtype=np.int64)
    icell = 1.0 / fcell
    icell_y = 1.0 / fcell_y
    thr = 1e-9 ** (1.0 / power)  # pixels below this alpha (1e-9) are skipped without a draw
    # maxima of e = d w and of d over pixel blocks, kept up to date below
    nb = ((rows + BLOCK - 1) // BLOCK) * ((cols + BLOCK - 1) // BLOCK)
    bme = np.zeros(nb)
    bmd = np.zeros(nb)
    # np.int64(0), not a literal 0: numba compiles a second specialisation of a kernel
    # called with a literal (issue 16)
    _block_max(d, w, bme, bmd, np.int64(0), (rows + BLOCK - 1) // BLOCK, np.int64(0), (cols + BLOCK - 1) // BLOCK)
    for _ in range(max_rounds):
        if (st[_S_NP] + p_count > caps[0] or st[_S_NV] + p_count * maxv > caps[1]
                or st[_S_NR] + p_count * maxr > caps[2] or st[_S_NE] + p_count * 9 > caps[3]):
            return NEED_ROOM
        st[_S_ROUNDS] += 1
        # -- candidate points Q: each pixel with probability (e / max e)**n (§4.2), where
        #    e is the distance d times the suppression weight
        emax = _amax(bme)
        dmax = _amax(bmd)
        if emax <= 0.0:
            return NO_FIELD
        nq = _draw_q(rs, d, w, bme, emax * thr, emax, power, qbuf)
        # -- choose P of them at random (§4.2): a partial Fisher-Yates shuffle
        m = min(nq, p_count)
        for i in range(m):
            j = i + int(_rand(rs) * (nq - i))
            t = qbuf[i]
            qbuf[i] = qbuf[j]
            qbuf[j] = t
            cand[i] = qbuf[i]
            cdraw[i] = dflat[qbuf[i]] * wflat[qbuf[i]]
        for ci in range(m):
            q = cand[ci]
            jx = _rand(rs)
            jy = _rand(rs)
            e_now = dflat[q] * wflat[q]
            if e_now <= 0.0:
                continue  # now inside a placed region: no longer a point of Q
            if e_now < cdraw[ci] and _rand(rs) >= _alpha(e_now / cdraw[ci], power):
                continue  # thinned: the field shrank here since the draw (extension, §4.2)
            px = fx0 + (q % cols + jx) * fcell
            py = fy0 + (q // cols + jy) * fcell_y
            if ktarget.size:
                nko = _kind_order(ktarget, ktol, cnt, st[_S_NP], korder)
            elif cumw.size == 0:
                korder[0] = st[_S_NEXT]
                nko = 1
            else:
                u = _rand(rs)
                k = 0
                while k < nkinds - 1 and u >= cumw[k]:
                    k += 1
                korder[0] = k
                nko = 1
            st[_S_TRIALS] += 1
            ok = False
            rot = 0.0
            s = 1.0
            x = px
            y = py
            k = korder[0]
            # distance from the candidate point to its pixel's centre
            off_q = np.sqrt((jx - 0.5) * (jx - 0.5) + (jy - 0.5) * (jy - 0.5)) * fcm
            for kj in range(nko):
                k = korder[kj]
                fixed = rot_lo[k] == rot_hi[k] and sc_lo[k] == sc_hi[k]
                tries = 1 if fixed else fits
                for t in range(tries):
                    rot = rot_lo[k]
                    if rot_hi[k] > rot_lo[k]:
                        rot += _rand(rs) * (rot_hi[k] - rot_lo[k])
                    s = sc_lo[k]
                    if sc_hi[k] > sc_lo[k]:
                        if sfit:
                            # scale that fits the gap (extension, §4.2): poses run from the
                            # largest scale down, one random scale per stratum of the range
                            s += (1.0 - (t + _rand(rs)) / tries) * (sc_hi[k] - sc_lo[k])
                        else:
                            s += _rand(rs) * (sc_hi[k] - sc_lo[k])
                    anchored = t > 0 and ka[k + 1] > ka[k]
                    if anchored:
                        # later poses put one of the kind's anchor points (inside its
                        # exclusive region) on the candidate point, not its box centre
                        if t % 2 == 1:
                            # the widest of the kind's disks that the gap can hold
                            a = kdo[k]
                            while a < kdo[k + 1] - 1 and kdisk[a, 2] * s > dflat[q]:
                                a += 1
                            ax_, ay_ = kdisk[a, 0], kdisk[a, 1]
                        else:
                            a = ka[k] + int(_rand(rs) * (ka[k + 1] - ka[k]))
                            ax_, ay_ = kanch[a, 0], kanch[a, 1]
                            if kanch[a, 2] * s > dflat[q] + off_q:
                                # the anchor's own inscribed disk, centred on the point, is
                                # wider than the field allows there (as below): certain
                                st[_S_POSES] += 1
                                continue
                    c = np.cos(rot) * s
                    sn = np.sin(rot) * s
                    if anchored:
                        x = px - (c * ax_ - sn * ay_)
                        y = py - (sn * ax_ + c * ay_)
                    if per is not None:
                        x = _wrap(x, pw0, pw)
                        y = _wrap(y, ph0, ph)
                    st[_S_POSES] += 1
                    # certain rejection from the field (extension, §4.2): the field is never
                    # below the true distance to the obstacles at a pixel centre, so a disk
                    # inside the body that is wider than the field there plus the offset to
                    # the pixel centre must meet an obstacle; no exact test is needed
                    hit = False
                    for i in range(kdo[k], kdo[k + 1]):
                        # the disk's centre in pixel units
                        u = (x + c * kdisk[i, 0] - sn * kdisk[i, 1] - fx0) * icell
                        v = (y + sn * kdisk[i, 0] + c * kdisk[i, 1] - fy0) * icell_y
                        if not (0.0 <= u < cols and 0.0 <= v < rows):
                            if per is not None:
                                u = _wrap(u, 0.0, float(cols))
                                v = _wrap(v, 0.0, float(rows))
                            else:
                                hit = True  # outside the domain's box
                                break
                        fc = min(int(u), cols - 1)
                        fr = min(int(v), rows - 1)
                        ox = u - (fc + 0.5)
                        oy = v - (fr + 0.5)
                        if kdisk[i, 2] * s > d[fr, fc] + np.sqrt(ox * ox + oy * oy) * fcm:
                            hit = True
                            break
                    if hit:
                        continue
                    _pose(kv, kr, kk[k], kk[k + 1], x, y, c, sn, cv, cbb)
                    if same_hull[k]:
                        hb = cbb
                        hvv = cv
                    else:
                        _pose(hv, hr, hk[k], hk[k + 1], x, y, c, sn, ch, hbb)
                        hb = hbb
                        hvv = ch
                    st[_S_QID] += 1
                    if per is not None:
                        if _collides_torus(cv, kr, kk[k], kk[k + 1], cbb, pv, pr, pp, pbb, g, head, enext, epoly, stamp,
                                           st, buf, blocker, per, ct, tbb):
                            continue
                        ok = True
                        break
                    if not _in_region(hvv, hr if not same_hull[k] else kr, hk[k] if not same_hull[k] else kk[k],
                                      hk[k + 1] if not same_hull[k] else kk[k + 1], hb, rv, rr, rsegs, g,
                                      rhead, rnext, rsid, rstamp, st[_S_QID]):
                        continue
                    if _collides(cv, kr, kk[k], kk[k + 1], cbb, pv, pr, pp, pbb, g, head, enext, epoly, stamp, st[_S_QID], buf, blocker):
                        continue
                    ok = True
                    break
                if ok:
                    break
            if ok:
                n0 = st[_S_NP]
                _insert(k, x, y, rot, s, cv, kr, kk, cbb, pv, pr, pp, pbb, pose, pkind, g, head, enext, epoly, st)
                # the distance field, updated locally at once (see _field.DistanceField.occupy)
                ns = 0
                for r in range(pp[n0], pp[n0 + 1]):
                    for i in range(pr[r], pr[r + 1] - 1):
                        segs[ns, 0] = pv[i, 0]
                        segs[ns, 1] = pv[i, 1]
                        segs[ns, 2] = pv[i + 1, 0]
                        segs[ns, 3] = pv[i + 1, 1]
                        ns += 1
                grow = dmax + fcm
                if per is None:
                    _occupy_posed(d, fx0, fy0, fcell, fcell_y, segs[:ns], cbb, grow, x, y, c, sn, kbb[k])
                    _refresh(d, w, bme, bmd, int(np.floor((cbb[1] - grow - fy0) / fcell_y)),
                             int(np.ceil((cbb[3] + grow - fy0) / fcell_y)) + 1,
                             int(np.floor((cbb[0] - grow - fx0) / fcell)),
                             int(np.ceil((cbb[2] + grow - fx0) / fcell)) + 1)
                else:
                    # the region and its wrapped images whose grown boxes reach the raster
                    fx1 = fx0 + cols * fcell
                    fy1 = fy0 + rows * fcell_y
                    for ti in range(-nt, nt + 1):
                        for tj in range(-nt, nt + 1):
                            dx = ti * pw
                            dy = tj * ph
                            if (cbb[0] + dx - grow >= fx1 or cbb[2] + dx + grow <= fx0
                                    or cbb[1] + dy - grow >= fy1 or cbb[3] + dy + grow <= fy0):
                                continue
                            for i in range(ns):
                                segs[i, 0] += dx
                                segs[i, 1] += dy
                                segs[i, 2] += dx
                                segs[i, 3] += dy
                            tbb[0] = cbb[0] + dx
                            tbb[1] = cbb[1] + dy
                            tbb[2] = cbb[2] + dx
                            tbb[3] = cbb[3] + dy
                            _occupy_posed(d, fx0, fy0, fcell, fcell_y, segs[:ns], tbb, grow, x + dx, y + dy, c, sn, kbb[k])
                            _refresh(d, w, bme, bmd, int(np.floor((tbb[1] - grow - fy0) / fcell_y)),
                                     int(np.ceil((tbb[3] + grow - fy0) / fcell_y)) + 1,
                                     int(np.floor((tbb[0] - grow - fx0) / fcell)),
                                     int(np.ceil((tbb[2] + grow - fx0) / fcell)) + 1)
                            for i in range(ns):
                                segs[i, 0] -= dx
                                segs[i, 1] -= dy
                                segs[i, 2] -= dx
                                segs[i, 3] -= dy
                st[_S_CONSEC] = 0
                cnt[k] += 1
                if cumw.size == 0:
                    st[_S_NEXT] = (st[_S_NEXT] + 1) % nkinds
            else:
                st[_S_CONSEC] += 1
                if suppress < 1.0:
                    # damp the failed spot (extension, §4.2)
                    cc = int((px - fx0) / fcell)
                    rq = int((py - fy0) / fcell_y)
                    rad = int(sup_r / fcell) + 1
                    rad_y = int(sup_r / fcell_y) + 1
                    if per is None:
                        for r in range(max(rq - rad_y, 0), min(rq + rad_y + 1, rows)):
                            for c in range(max(cc - rad, 0), min(cc + rad + 1, cols)):
                                ddx = fx0 + (c + 0.5) * fcell - px
                                ddy = fy0 + (r + 0.5) * fcell_y - py
                                if ddx * ddx + ddy * ddy <= sup_r * sup_r:
                                    w[r, c] *= suppress
                        _refresh(d, w, bme, bmd, rq - rad_y, rq + rad_y + 1, cc - rad, cc + rad + 1)
                    else:
                        # the disk wraps (it is narrower than half the tile: see pack)
                        for r in range(rq - rad_y, rq + rad_y + 1):
                            for c in range(cc - rad, cc + rad + 1):
                                ddx = fx0 + (c + 0.5) * fcell - px
                                ddy = fy0 + (r + 0.5) * fcell_y - py
                                if ddx * ddx + ddy * ddy <= sup_r * sup_r:
                                    w[r % rows, c % cols] *= suppress
                        for ti in range(-1, 2):
                            for tj in range(-1, 2):
                                _refresh(d, w, bme, bmd, rq - rad_y + tj * rows, rq + rad_y + 1 + tj * rows,
                                         cc - rad + ti * cols, cc + rad + 1 + ti * cols)
                if st[_S_CONSEC] >= limit:
                    return DONE
    return RUNNING


@numba.njit(cache=True)
def _grid_segments(segs, gx0, gy0, gc, cols, rows):  # pragma: no cover - numba
    """Linked lists of the segments (s, 4) per grid cell that their boxes touch."""
    n = 0
    for s in range(len(segs)):
        c0, c1, q0, q1 = _cell_span(gx0, gy0, gc, cols, rows, min(segs[s, 0], segs[s, 2]), min(segs[s, 1], segs[s, 3]), max(segs[s, 0], segs[s, 2]), max(segs[s, 1], segs[s, 3]))
        n += max(c1 - c0 + 1, 0) * max(q1 - q0 + 1, 0)
    head = np.empty(rows * cols, dtype=np.int64)
    for i in range(rows * cols):
        head[i] = -1
    nxt = np.empty(n, dtype=np.int64)
    sid = np.empty(n, dtype=np.int64)
    e = 0
    for s in range(len(segs)):
        c0, c1, q0, q1 = _cell_span(gx0, gy0, gc, cols, rows, min(segs[s, 0], segs[s, 2]), min(segs[s, 1], segs[s, 3]), max(segs[s, 0], segs[s, 2]), max(segs[s, 1], segs[s, 3]))
        for q in range(q0, q1 + 1):
            for c in range(c0, c1 + 1):
                nxt[e] = head[q * cols + c]
                sid[e] = s
                head[q * cols + c] = e
                e += 1
    return head, nxt, sid


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
        self.g = np.array([x0, y0, gc, cols, rows], dtype=float)
        same = np.flatnonzero(self.rr[1:] - self.rr[:-1] > 0)
        starts = np.concatenate([np.arange(self.rr[r], self.rr[r + 1] - 1) for r in same]) if len(same) else np.zeros(0, int)
        self.rsegs = np.ascontiguousarray(np.c_[self.rv[starts], self.rv[starts + 1]]) if len(starts) else np.zeros((0, 4))
        self.rhead, self.rnext, self.rsid = _grid_segments(self.rsegs, x0, y0, gc, cols, rows)
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
        self.head = np.full(cols * rows, -1, dtype=np.int64)
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
        self.enext = grow(self.enext if old else None, ne, (), np.int64)
        self.epoly = grow(self.epoly if old else None, ne, (), np.int64)
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
                                 self.rr, self.rsegs, self.rhead, self.rnext, self.rsid, self.rstamp, self.cv, self.ch,
                                 self.cbb, self.hbb, self.pv, self.pr, self.pp, self.pbb, self.pose, self.pkind, self.g,
                                 self.head, self.enext, self.epoly, self.st, self.per))

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
                self.rv, self.rr, self.rsegs, self.rhead, self.rnext, self.rsid, self.rstamp,
                self.pv, self.pr, self.pp, self.pbb, self.pose, self.pkind, self.g, self.head, self.enext, self.epoly,
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
