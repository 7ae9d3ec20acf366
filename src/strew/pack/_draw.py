"""The Step 2 draw loop of the fill-gap method (Sakurai & Miyata §4.2), compiled.

:func:`_rounds` runs rounds of: candidate points Q drawn from the distance field with
probability ``alpha = (e / max e)**n`` (:func:`_draw_q`, by pixel blocks whose maxima
bound the draw), P of them chosen at random, and at each the poses tried in turn
against the exact tests of :mod:`._predicates`; a placement updates the field at once
(:func:`._field._occupy_posed`) and the block maxima. The extensions of §4.2 (fit,
suppression, fresh candidates, gap-fitting kind choice) are described in ``_fit.py``.
Random numbers come from the shared compiled stream (:mod:`strew._kernels.prng`).
Split from ``_fit.py`` (issue 15 point 7).
"""

from __future__ import annotations

import math

import numba
import numpy as np

from .._kernels.prng import uniform as _rand
from ._field import _occupy_posed
from ._predicates import (
    _S_CONSEC,
    _S_NE,
    _S_NEXT,
    _S_NP,
    _S_NR,
    _S_NV,
    _S_POSES,
    _S_QID,
    _S_ROUNDS,
    _S_TRIALS,
    _collides,
    _collides_torus,
    _in_region,
    _insert,
    _pose,
    _wrap,
)

__all__ = ["RUNNING", "DONE", "NEED_ROOM", "NO_FIELD", "BLOCK"]

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


@numba.njit(cache=True)
def _rounds(
    rs, max_rounds, limit, p_count, power, fits, suppress, sup_r, ktarget, ktol, sfit, kanch, ka, kdisk, kdo, kbb,
    d, w, fx0, fy0, fcell, qbuf, cand, cdraw,
    kv, kr, kk, hv, hr, hk, same_hull, rot_lo, rot_hi, sc_lo, sc_hi, cumw,
    rv, rr, rsegs, rhead, rent, rext, rstamp,
    pv, pr, pp, pbb, pose, pkind, g, head, tail, ent, ext, stamp,
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
                        if _collides_torus(cv, kr, kk[k], kk[k + 1], cbb, pv, pr, pp, pbb, g, head, ent, ext, stamp,
                                           st, buf, blocker, per, ct, tbb):
                            continue
                        ok = True
                        break
                    if not _in_region(hvv, hr if not same_hull[k] else kr, hk[k] if not same_hull[k] else kk[k],
                                      hk[k + 1] if not same_hull[k] else kk[k + 1], hb, rv, rr, rsegs, g,
                                      rhead, rent, rext, rstamp, st[_S_QID]):
                        continue
                    if _collides(cv, kr, kk[k], kk[k + 1], cbb, pv, pr, pp, pbb, g, head, ent, ext, stamp, st[_S_QID], buf, blocker):
                        continue
                    ok = True
                    break
                if ok:
                    break
            if ok:
                n0 = st[_S_NP]
                _insert(k, x, y, rot, s, cv, kr, kk, cbb, pv, pr, pp, pbb, pose, pkind, g, head, tail, ent, ext, st)
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
