"""Raster buffer of the growth framework (Wong et al. 1998, §4.1), numba kernels.

The framework keeps a low-resolution buffer into which the proxies of placed elements
and the boundary of the region R are rendered, and a distance field over it whose
local maxima (the medial axis) are the centres of the candidate empty circles.

Grid convention: cell ``(i, j)`` has centre ``(x0 + (j + 0.5) h, y0 + (i + 0.5) h)``.
Distances in the fields are in cells. Two fields are kept:

``dist_all``
    distance to the nearest covered cell of any kind (boundary or element): the radius
    at which a test circle centred on the cell stops inflating;
``dist_el``
    distance to the nearest element cell: whether that circle was stopped by an element
    (kept) or by the boundary (discarded).

A cell is *covered* by a proxy when its centre lies within ``h * sqrt(2) / 2`` of the
proxy, so that every point of the proxy lies in a covered cell; raster distances are
then within about one cell of the exact ones, which the framework computes afterwards.

§4.1 updates the medial axis transform incrementally after each placement; here the
update is a "lower wave" (dynamic brushfire): starting from the newly covered cells, a
cell's distance is lowered, and the wave spreads, only where the new element is nearer
than the old nearest obstacle, so the work is proportional to the cells that change.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from .._kernels.geometry import seg_dist2
# cells inside a polygon: the shared scanline rasteriser (issue 15 point 5; the same
# cells, in the same order, as the per-cell even-odd test that was here)
from .._kernels.raster import scan_cells as cover_polygon

__all__ = [
    "BLOCK",
    "cover_disc",
    "cover_polyline",
    "cover_polygon",
    "lower_wave",
    "mark_excluded",
    "mark_near",
    "mark_rect",
    "scan_blocks",
    "tree_build",
]

_NB = dict(cache=True, nogil=True)

@numba.njit(**_NB)
def cover_disc(rows, cols, x0, y0, h, cx, cy, r, pad):
    """Flat indices of cells whose centre lies within ``r + pad`` of ``(cx, cy)``."""
    rr = r + pad
    j0 = max(0, int(np.floor((cx - rr - x0) / h - 0.5)))
    j1 = min(cols - 1, int(np.ceil((cx + rr - x0) / h - 0.5)))
    i0 = max(0, int(np.floor((cy - rr - y0) / h - 0.5)))
    i1 = min(rows - 1, int(np.ceil((cy + rr - y0) / h - 0.5)))
    n = max(0, (i1 - i0 + 1)) * max(0, (j1 - j0 + 1))
    out = np.empty(n, np.int64)
    k = 0
    r2 = rr * rr
    for i in range(i0, i1 + 1):
        py = y0 + (i + 0.5) * h - cy
        for j in range(j0, j1 + 1):
            px = x0 + (j + 0.5) * h - cx
            if px * px + py * py <= r2:
                out[k] = i * cols + j
                k += 1
    return out[:k]


@numba.njit(**_NB)
def cover_polyline(rows, cols, x0, y0, h, pts, pad):
    """Flat indices (may repeat) of cells whose centre lies within ``pad`` of the polyline.

    ``pts`` is ``(n, 2)``; consecutive points are joined.
    """
    n = pts.shape[0]
    p2 = pad * pad
    # first pass: the cells of every segment's box bound the output (one allocation, no
    # growing copies: slice assignment compiles slowly, issue 16)
    bound = 0
    for s in range(max(1, n - 1)):
        ax, ay = pts[s, 0], pts[s, 1]
        if n > 1:
            bx, by = pts[s + 1, 0], pts[s + 1, 1]
        else:
            bx, by = ax, ay
        j0 = max(0, int(np.floor((min(ax, bx) - pad - x0) / h - 0.5)))
        j1 = min(cols - 1, int(np.ceil((max(ax, bx) + pad - x0) / h - 0.5)))
        i0 = max(0, int(np.floor((min(ay, by) - pad - y0) / h - 0.5)))
        i1 = min(rows - 1, int(np.ceil((max(ay, by) + pad - y0) / h - 0.5)))
        bound += max(0, i1 - i0 + 1) * max(0, j1 - j0 + 1)
    out = np.empty(bound, np.int64)
    total = 0
    for s in range(max(1, n - 1)):
        ax, ay = pts[s, 0], pts[s, 1]
        if n > 1:
            bx, by = pts[s + 1, 0], pts[s + 1, 1]
        else:
            bx, by = ax, ay
        j0 = max(0, int(np.floor((min(ax, bx) - pad - x0) / h - 0.5)))
        j1 = min(cols - 1, int(np.ceil((max(ax, bx) + pad - x0) / h - 0.5)))
        i0 = max(0, int(np.floor((min(ay, by) - pad - y0) / h - 0.5)))
        i1 = min(rows - 1, int(np.ceil((max(ay, by) + pad - y0) / h - 0.5)))
        for i in range(i0, i1 + 1):
            py = y0 + (i + 0.5) * h
            for j in range(j0, j1 + 1):
                px = x0 + (j + 0.5) * h
                if seg_dist2(px, py, ax, ay, bx, by) <= p2:
                    out[total] = i * cols + j
                    total += 1
    return out[:total]


# -- dirty blocks -------------------------------------------------------------------------
# The raster is cut into square blocks of 2**BLOCK_SHIFT cells. Each block keeps its best
# candidate circle (``best_val``, ``best_idx``) and the largest finite distance among its
# cells (``bmax``); a block is recomputed only when something it depends on changed. The
# dirty blocks are flagged in ``dirty`` (brows, bcols) and listed, once each, in
# ``dlist[:dcount[0]]``, so that a scan costs the dirty blocks, not the raster (issue
# 19.6); the largest ``best_val`` is kept at the root of a tournament tree ``tree``
# (2 P,) over the blocks, so finding the largest empty circle costs O(log blocks).
BLOCK_SHIFT = 4
BLOCK = 1 << BLOCK_SHIFT


@numba.njit(**_NB)
def _mark(dirty, dlist, dcount, bi, bj):
    """Flag block ``(bi, bj)`` dirty and list it, unless it already is."""
    if not dirty[bi, bj]:
        dirty[bi, bj] = True
        dlist[dcount[0]] = bi * dirty.shape[1] + bj
        dcount[0] += 1


@numba.njit(**_NB)
def _mark_cell(dirty, dlist, dcount, i, j, rows, cols):
    """Flag the blocks of cells ``(i +- 1, j +- 1)``: a change of cell ``(i, j)`` alters
    its own candidacy and its neighbours' medial-axis test, nothing else (the blocks of
    a cell inside its block are its own only)."""
    bi0 = max(i - 1, 0) >> BLOCK_SHIFT
    bi1 = min(i + 1, rows - 1) >> BLOCK_SHIFT
    bj0 = max(j - 1, 0) >> BLOCK_SHIFT
    bj1 = min(j + 1, cols - 1) >> BLOCK_SHIFT
    _mark(dirty, dlist, dcount, bi0, bj0)
    if bj1 != bj0:
        _mark(dirty, dlist, dcount, bi0, bj1)
    if bi1 != bi0:
        _mark(dirty, dlist, dcount, bi1, bj0)
        if bj1 != bj0:
            _mark(dirty, dlist, dcount, bi1, bj1)


@numba.njit(**_NB)
def mark_rect(dirty, dlist, dcount, bi0, bi1, bj0, bj1):
    """Flag blocks ``bi0 <= bi < bi1``, ``bj0 <= bj < bj1`` (clamped to the grid)."""
    for bi in range(max(bi0, 0), min(bi1, dirty.shape[0])):
        for bj in range(max(bj0, 0), min(bj1, dirty.shape[1])):
            _mark(dirty, dlist, dcount, bi, bj)


@numba.njit(**_NB)
def mark_excluded(dirty, dlist, dcount, best_val, best_idx, cols, x0, y0, h, px, py, rmax):
    """Flag the blocks whose best circle contains ``(px, py)`` (a new exclude point).

    Only blocks whose cells lie within ``rmax`` (the largest best radius, world units)
    of the point are visited; the test is the one the scan applies, widened by a
    relative 1e-9 (a block flagged needlessly is scanned again to the same result).
    """
    brows, bcols = dirty.shape
    i0 = int(np.floor((py - rmax - y0) / h)) - 1
    i1 = int(np.ceil((py + rmax - y0) / h)) + 1
    j0 = int(np.floor((px - rmax - x0) / h)) - 1
    j1 = int(np.ceil((px + rmax - x0) / h)) + 1
    for bi in range(max(i0, 0) >> BLOCK_SHIFT, min(max(i1, 0) >> BLOCK_SHIFT, brows - 1) + 1):
        for bj in range(max(j0, 0) >> BLOCK_SHIFT, min(max(j1, 0) >> BLOCK_SHIFT, bcols - 1) + 1):
            k = best_idx[bi, bj]
            if k < 0 or dirty[bi, bj]:
                continue
            i = k // cols
            j = k - i * cols
            dx = x0 + (j + 0.5) * h - px
            dy = y0 + (i + 0.5) * h - py
            r = best_val[bi, bj] * h
            if dx * dx + dy * dy < r * r * (1.0 + 1e-9):
                _mark(dirty, dlist, dcount, bi, bj)


@numba.njit(**_NB)
def mark_near(dirty, dlist, dcount, bmax, x0, y0, h, px, py, pad, gmax):
    """Flag the blocks holding a cell whose circle may contain ``(px, py)`` (an exclude
    point just removed): those whose box comes within ``bmax * h + pad`` of it (``bmax``:
    the block's largest finite distance, in cells; ``gmax`` bounds every ``bmax``)."""
    brows, bcols = dirty.shape
    bs = BLOCK * h
    reach = gmax * h + pad
    bi0 = max(0, int(np.floor((py - reach - y0) / bs)) - 1)
    bi1 = min(brows - 1, int(np.floor((py + reach - y0) / bs)) + 1)
    bj0 = max(0, int(np.floor((px - reach - x0) / bs)) - 1)
    bj1 = min(bcols - 1, int(np.floor((px + reach - x0) / bs)) + 1)
    for bi in range(bi0, bi1 + 1):
        by0 = y0 + bi * bs
        dy = max(0.0, max(by0 - py, py - (by0 + bs)))
        for bj in range(bj0, bj1 + 1):
            if dirty[bi, bj]:
                continue
            bx0 = x0 + bj * bs
            dx = max(0.0, max(bx0 - px, px - (bx0 + bs)))
            r = max(bmax[bi, bj], 0.0) * h + pad
            if dy * dy + dx * dx <= r * r:
                _mark(dirty, dlist, dcount, bi, bj)


@numba.njit(**_NB)
def lower_wave(dist, near, skip, sources, dirty, dlist, dcount, nbr, cap, cap_tol, use_cap, ring, inq):
    """Lower the distance field from new obstacle cells; flag changed blocks dirty.

    Parameters
    ----------
    dist : (rows, cols) float64
        Distance in cells to the nearest obstacle cell; lowered in place.
    near : (rows, cols) int64
        Flat index of that nearest obstacle cell; updated in place.
    skip : (rows, cols) bool
        Cells rejected as candidates; cleared in place where the distance changes.
    sources : (k,) int64
        Flat indices of the newly covered cells.
    dirty, dlist, dcount
        The dirty blocks (see above); the blocks of changed cells are flagged, and with
        ``nbr`` those of their eight neighbours too (a change of ``dist_all`` alters the
        neighbours' medial-axis test; one of ``dist_el`` only the cell's own candidacy).
    cap : (rows, cols) float64
        With ``use_cap``, the wave does not enter cells where the new distance exceeds
        ``cap + cap_tol``. The element-distance field is capped by the all-obstacle field:
        the framework only asks whether ``dist_el <= dist_all + tol``, and a cell beyond
        the cap keeps the right answer (False) until ``dist_all`` drops there, which only
        a nearer new element does, whose own wave then updates the cell.
    cap_tol : float
    use_cap : bool
    ring : (rows * cols,) int64
        Work space for the FIFO (each cell is queued at most once at a time).
    inq : (rows * cols,) bool
        Work space, all False on entry and on exit.

    Returns
    -------
    int
        Number of cell updates.
    """
    rows, cols = dist.shape
    size = ring.shape[0]
    df = dist.ravel()
    nf = near.ravel()
    sf = skip.ravel()
    cf = cap.ravel()
    head = 0
    tail = 0
    pushes = 0
    count = 0
    n = 0
    for s in sources:
        if df[s] > 0.0:
            df[s] = 0.0
            nf[s] = s
            sf[s] = False
            count += 1
            if not inq[s]:
                inq[s] = True
                ring[tail] = s
                pushes += 1
                tail += 1
                if tail == size:
                    tail = 0
                n += 1
    # A cell is (re)queued only when its distance strictly drops.
    while n > 0:
        p = ring[head]
        head += 1
        if head == size:
            head = 0
        n -= 1
        inq[p] = False
        pi = p // cols
        pj = p - pi * cols
        q = nf[p]
        qi = q // cols
        qj = q - qi * cols
        for di in range(-1, 2):
            ni = pi + di
            if ni < 0 or ni >= rows:
                continue
            a = ni - qi
            a2 = a * a
            row = ni * cols
            for dj in range(-1, 2):
                nj = pj + dj
                if nj < 0 or nj >= cols or (di == 0 and dj == 0):
                    continue  # (the cell itself: its own distance to q, no drop)
                c = row + nj
                dc = df[c]
                b = nj - qj
                d2 = float(a2 + b * b)
                # a pre-test that spares the square root: d2 >= dc^2 (1 + 1e-12) (with
                # rounding, still above dc^2) means sqrt(d2) >= dc, no drop
                if d2 >= dc * dc * (1.0 + 1e-12):
                    continue
                d = np.sqrt(d2)
                if d < dc - 1e-9:
                    if use_cap and d > cf[c] + cap_tol:
                        continue
                    df[c] = d
                    nf[c] = q
                    sf[c] = False
                    count += 1
                    if not inq[c]:
                        inq[c] = True
                        ring[tail] = c
                        pushes += 1
                        tail += 1
                        if tail == size:
                            tail = 0
                        n += 1
    # Every changed cell was queued, so ring[:pushes] lists them all (with repeats)
    # unless the ring wrapped round: flag their blocks now, in one pass (flagging as
    # cells changed cost a third of the wave; the cost of a wave is its own cells, not
    # the raster's size: issue 19.6). A wrapped ring (more pushes than cells) flags all.
    if pushes > size:
        for bi in range(dirty.shape[0]):
            for bj in range(dirty.shape[1]):
                _mark(dirty, dlist, dcount, bi, bj)
        return count
    last = -1
    bcols = dirty.shape[1]
    edge = BLOCK - 1
    for k in range(pushes):
        c = ring[k]
        ci = c // cols
        cj = c - ci * cols
        ri = ci & edge
        rj = cj & edge
        if not nbr or (ri != 0 and ri != edge and rj != 0 and rj != edge):
            # the cell's 3 x 3 neighbourhood lies in its own block
            bk = (ci >> BLOCK_SHIFT) * bcols + (cj >> BLOCK_SHIFT)
            if bk != last:
                _mark(dirty, dlist, dcount, ci >> BLOCK_SHIFT, cj >> BLOCK_SHIFT)
                last = bk
        else:
            _mark_cell(dirty, dlist, dcount, ci, cj, rows, cols)
            last = -1
    return count


@numba.njit(**_NB)
def _tree_val(bf, k):
    return bf[k] if k >= 0 else -np.inf


@numba.njit(**_NB)
def tree_build(tree, best_val):
    """The tournament tree over ``best_val`` (flattened): ``tree[P + b] = b`` for the
    blocks (-1 past them), each inner node the winner of its children, the larger
    value or on a tie the left one, so ``tree[1]`` is ``np.argmax(best_val)``."""
    bf = best_val.ravel()
    nb = bf.shape[0]
    p = tree.shape[0] // 2
    for b in range(p):
        tree[p + b] = b if b < nb else -1
    for k in range(p - 1, 0, -1):
        left = tree[2 * k]
        right = tree[2 * k + 1]
        tree[k] = left if _tree_val(bf, left) >= _tree_val(bf, right) else right


@numba.njit(**_NB)
def scan_blocks(dist_all, dist_el, covered, skip, dirty, dlist, dcount, best_val, best_idx, bmax, tree, adj_tol, ex, n_ex, x0, y0, h):
    """Recompute the best candidate circle of every dirty block (§4.1 FindEmptyCircle).

    A candidate centre is a free cell on the medial axis of the distance transform (its
    circle lies inside none of its eight neighbours' circles: the field rises by less than
    0.85 of the step towards every neighbour; the paper's "at least as great as those of
    its neighbors" would miss the rising ridges between the ornament and the boundary,
    where the largest circle adjacent to the ornament often lies), whose inflation stopped
    at an element rather than at the boundary (``dist_el - dist_all <= adj_tol``), that
    is not marked ``skip`` and whose circle contains no point of the exclude list
    (``ex[:n_ex]``, world coordinates). Each block keeps its largest one in ``best_val``
    (radius in cells, -1 when none) and ``best_idx`` (flat cell index), and its largest
    finite distance in ``bmax``; the tournament tree ``tree`` is brought up to date.

    Returns
    -------
    int
        The block of the largest ``best_val`` (the first of equal ones).
    """
    rows, cols = dist_all.shape
    bcols = dirty.shape[1]
    block = BLOCK
    m = dcount[0]
    p = tree.shape[0] // 2
    bf = best_val.ravel()
    for t in range(m):
        bb = dlist[t]
        bi = bb // bcols
        bj = bb - bi * bcols
        dirty[bi, bj] = False
        bv = -1.0
        bidx = -1
        bm = 0.0
        for i in range(bi * block, min(rows, (bi + 1) * block)):
            for j in range(bj * block, min(cols, (bj + 1) * block)):
                v = dist_all[i, j]
                if v > bm and v < np.inf:
                    bm = v
                if v <= bv or covered[i, j] != 0 or skip[i, j]:
                    continue
                if dist_el[i, j] - v > adj_tol:
                    continue
                ismax = True
                for di in range(-1, 2):
                    ni = i + di
                    if ni < 0 or ni >= rows:
                        ismax = False
                        break
                    for dj in range(-1, 2):
                        nj = j + dj
                        if nj < 0 or nj >= cols:
                            ismax = False
                            break
                        # medial-axis test: the circle at (i, j) is not inside a
                        # neighbour's circle, i.e. the field rises slower than
                        # its unit slope off the skeleton (0.85 < cos 22.5 deg)
                        step = 1.0 if (di == 0 or dj == 0) else 1.4142135623730951
                        if dist_all[ni, nj] - v > 0.85 * step:
                            ismax = False
                            break
                    if not ismax:
                        break
                if not ismax:
                    continue
                cx = x0 + (j + 0.5) * h
                cy = y0 + (i + 0.5) * h
                rw = v * h
                r2 = rw * rw
                excluded = False
                for e in range(n_ex):
                    dx = ex[e, 0] - cx
                    dy = ex[e, 1] - cy
                    if dx * dx + dy * dy < r2:
                        excluded = True
                        break
                if excluded:
                    continue
                bv = v
                bidx = i * cols + j
        best_val[bi, bj] = bv
        best_idx[bi, bj] = bidx
        bmax[bi, bj] = bm
        if m * 16 < p:  # few blocks: walk each one's path up the tree
            k = (p + bb) >> 1
            while k >= 1:
                left = tree[2 * k]
                right = tree[2 * k + 1]
                tree[k] = left if _tree_val(bf, left) >= _tree_val(bf, right) else right
                k >>= 1
    dcount[0] = 0
    if m * 16 >= p:
        tree_build(tree, best_val)
    return tree[1]


@numba.njit(**_NB)
def _clearance(px, py, circ, segs):
    d = np.inf
    for k in range(circ.shape[0]):
        v = np.sqrt((px - circ[k, 0]) ** 2 + (py - circ[k, 1]) ** 2) - circ[k, 2]
        if v < d:
            d = v
    for k in range(segs.shape[0]):
        v = np.sqrt(seg_dist2(px, py, segs[k, 0], segs[k, 1], segs[k, 2], segs[k, 3]))
        if v < d:
            d = v
    return d


@numba.njit(**_NB)
def _near_normal(px, py, circ, segs, k, dmin, band):
    """Unit vector from obstacle k (circles first, then segments) to the point, and
    whether that obstacle lies within ``band`` of the minimum distance ``dmin``."""
    nc = circ.shape[0]
    if k < nc:
        ux = px - circ[k, 0]
        uy = py - circ[k, 1]
        ln = np.sqrt(ux * ux + uy * uy)
        if ln - circ[k, 2] <= dmin + band and ln > 0:
            return True, ux / ln, uy / ln
        return False, 0.0, 0.0
    j = k - nc
    ax, ay, bx, by = segs[j, 0], segs[j, 1], segs[j, 2], segs[j, 3]
    dx = bx - ax
    dy = by - ay
    ll = dx * dx + dy * dy
    t = 0.0
    if ll > 0:
        t = min(1.0, max(0.0, ((px - ax) * dx + (py - ay) * dy) / ll))
    ux = px - (ax + t * dx)
    uy = py - (ay + t * dy)
    ln = np.sqrt(ux * ux + uy * uy)
    if ln <= dmin + band and ln > 0:
        return True, ux / ln, uy / ln
    return False, 0.0, 0.0


@numba.njit(**_NB)
def _ascent_dir(px, py, circ, segs, dmin, band):
    """Direction increasing every obstacle distance within ``band`` of the minimum.

    Two passes over the obstacles (the normals summed, then each checked against the
    sum) instead of a work array: arrays cost compile time (issue 16).
    """
    n = circ.shape[0] + segs.shape[0]
    gx = 0.0
    gy = 0.0
    na = 0
    for k in range(n):
        ok, ux, uy = _near_normal(px, py, circ, segs, k, dmin, band)
        if ok:
            gx += ux
            gy += uy
            na += 1
    ln = np.sqrt(gx * gx + gy * gy)
    if na == 0 or ln < 1e-12:
        return 0.0, 0.0
    gx /= ln
    gy /= ln
    for k in range(n):
        ok, ux, uy = _near_normal(px, py, circ, segs, k, dmin, band)
        if ok and ux * gx + uy * gy <= 1e-9:
            return 0.0, 0.0
    return gx, gy


@numba.njit(**_NB)
def climb(cx, cy, circ, segs, step, min_step, target):
    """Local search for the centre of the largest empty circle near ``(cx, cy)``.

    Ascends the clearance (distance to the nearest obstacle) along the direction that
    increases the distance to every nearly-nearest obstacle, then polishes with a compass
    search; both halve their step on failure.

    Parameters
    ----------
    circ : (k, 3) float64
        Nearby circles ``(x, y, r)`` (points have r = 0).
    segs : (m, 4) float64
        Nearby line segments ``(x0, y0, x1, y1)``: outlines of other proxies and the
        region boundary.
    step, min_step : float
        First and last step length.
    target : float
        Stop as soon as the clearance reaches it.

    Returns
    -------
    (x, y, clearance)
    """
    best = _clearance(cx, cy, circ, segs)
    s = step
    while s > min_step and best < target:
        ux, uy = _ascent_dir(cx, cy, circ, segs, best, s)
        if ux == 0.0 and uy == 0.0:
            s *= 0.5
            continue
        v = _clearance(cx + s * ux, cy + s * uy, circ, segs)
        if v > best:
            cx += s * ux
            cy += s * uy
            best = v
        else:
            s *= 0.5
    s2 = np.sqrt(0.5)
    # the eight compass directions as tuples (arrays here cost compile time: issue 16)
    dx = (1.0, -1.0, 0.0, 0.0, s2, -s2, s2, -s2)
    dy = (0.0, 0.0, 1.0, -1.0, s2, -s2, -s2, s2)
    s = step * 0.25
    while s > min_step and best < target:
        bk = -1
        bv = best
        for k in range(8):
            v = _clearance(cx + s * dx[k], cy + s * dy[k], circ, segs)
            if v > bv:
                bv = v
                bk = k
        if bk >= 0:
            cx += s * dx[bk]
            cy += s * dy[bk]
            best = bv
        else:
            s *= 0.5
    if best < target:
        nx, ny = _newton3(cx, cy, best, circ, segs)
        if abs(nx - cx) + abs(ny - cy) < 4 * step:
            v = _clearance(nx, ny, circ, segs)
            if v > best:
                cx, cy, best = nx, ny, v
    return cx, cy, best


@numba.njit(**_NB)
def _nearest_on(px, py, circ, segs, k):
    """Distance to obstacle k (circles first, then segments) and its unit gradient."""
    nc = circ.shape[0]
    if k < nc:
        ux = px - circ[k, 0]
        uy = py - circ[k, 1]
        ln = np.sqrt(ux * ux + uy * uy)
        if ln == 0:
            return -circ[k, 2], 1.0, 0.0
        return ln - circ[k, 2], ux / ln, uy / ln
    j = k - nc
    ax, ay, bx, by = segs[j, 0], segs[j, 1], segs[j, 2], segs[j, 3]
    dx = bx - ax
    dy = by - ay
    ll = dx * dx + dy * dy
    t = 0.0
    if ll > 0:
        t = min(1.0, max(0.0, ((px - ax) * dx + (py - ay) * dy) / ll))
    ux = px - (ax + t * dx)
    uy = py - (ay + t * dy)
    ln = np.sqrt(ux * ux + uy * uy)
    if ln == 0:
        return 0.0, 1.0, 0.0
    return ln, ux / ln, uy / ln


@numba.njit(**_NB)
def _solve3(a00, a01, a02, a10, a11, a12, a20, a21, a22, b0, b1, b2):
    """Solve the 3 x 3 system by Gaussian elimination with partial pivoting, in scalars.

    Returns ``(ok, x0, x1, x2)``; ``ok`` is False when the determinant (the product of
    the pivots) is below 1e-12 in magnitude. Scalars, not numba's linalg nor LAPACK
    through arrays: those cost most of the ornament kernels' compile time (issue 16).
    """
    # pivot for column 0
    if abs(a10) > abs(a00) and abs(a10) >= abs(a20):
        a00, a01, a02, b0, a10, a11, a12, b1 = a10, a11, a12, b1, a00, a01, a02, b0
    elif abs(a20) > abs(a00):
        a00, a01, a02, b0, a20, a21, a22, b2 = a20, a21, a22, b2, a00, a01, a02, b0
    if a00 == 0.0:
        return False, 0.0, 0.0, 0.0
    l1 = a10 / a00
    l2 = a20 / a00
    a11 -= l1 * a01
    a12 -= l1 * a02
    b1 -= l1 * b0
    a21 -= l2 * a01
    a22 -= l2 * a02
    b2 -= l2 * b0
    # pivot for column 1
    if abs(a21) > abs(a11):
        a11, a12, b1, a21, a22, b2 = a21, a22, b2, a11, a12, b1
    if a11 == 0.0:
        return False, 0.0, 0.0, 0.0
    l = a21 / a11
    a22 -= l * a12
    b2 -= l * b1
    if abs(a00 * a11 * a22) < 1e-12:
        return False, 0.0, 0.0, 0.0
    x2 = b2 / a22
    x1 = (b1 - a12 * x2) / a11
    x0 = (b0 - a01 * x1 - a02 * x2) / a00
    return True, x0, x1, x2


@numba.njit(**_NB)
def _newton3(px, py, rho, circ, segs):
    """Newton steps on the three nearest obstacles: the point equidistant from them.

    At a local maximum of the clearance the nearest three obstacles are at the same
    distance; solving ``d_i(p) = rho`` for them polishes a point found by local search.
    """
    n = circ.shape[0] + segs.shape[0]
    if n < 3:
        return px, py
    # the three nearest, as np.argsort(d)[:3] orders them (ties: the lower index first),
    # by one pass: argsort brought numba's quicksort in, about 1 s of CPU to compile (issue 16)
    i0 = i1 = i2 = -1
    d0 = d1 = d2 = 0.0
    for k in range(n):
        v = _nearest_on(px, py, circ, segs, k)[0]
        if i0 < 0 or v < d0:
            i2, d2 = i1, d1
            i1, d1 = i0, d0
            i0, d0 = k, v
        elif i1 < 0 or v < d1:
            i2, d2 = i1, d1
            i1, d1 = k, v
        elif i2 < 0 or v < d2:
            i2, d2 = k, v
    for _ in range(12):
        f0, g00, g01 = _nearest_on(px, py, circ, segs, i0)
        f1, g10, g11 = _nearest_on(px, py, circ, segs, i1)
        f2, g20, g21 = _nearest_on(px, py, circ, segs, i2)
        f0 -= rho
        f1 -= rho
        f2 -= rho
        if not (math.isfinite(f0) and math.isfinite(f1) and math.isfinite(f2) and math.isfinite(g00) and math.isfinite(g01)
                and math.isfinite(g10) and math.isfinite(g11) and math.isfinite(g20) and math.isfinite(g21)):
            break  # (np.linalg raised here; the point stays as the local search left it)
        ok, s0, s1, s2 = _solve3(g00, g01, -1.0, g10, g11, -1.0, g20, g21, -1.0, -f0, -f1, -f2)
        if not ok:
            break
        px += s0
        py += s1
        rho += s2
        if abs(s0) + abs(s1) + abs(s2) < 1e-12:
            break
    return px, py


@numba.njit(**_NB)
def segments_distance(px, py, segs):
    """Distance from ``(px, py)`` to the nearest of the segments ``(m, 4)``."""
    best = np.inf
    for k in range(segs.shape[0]):
        v = seg_dist2(px, py, segs[k, 0], segs[k, 1], segs[k, 2], segs[k, 3])
        if v < best:
            best = v
    return np.sqrt(best)
