"""Fixed mode, kinds of several sizes: smaller elements farther from every element of a
larger kind than the reference's upper decile (issue 14 point 1, untuned exemplars; not
in the paper). The mirror of :mod:`._lone_larger`, moving instead of swapping.

Three sizes 20:120:20 (``--harder`` h7s7) has every small stone snug beside a medium one
(the gaps between their bounding discs at most 2.72, 90th percentile); the growth left
a fifth of its small stones in holes with no medium or large one within 3 (the
reference: none), the small stones' nearest-medium distances long in the upper deciles
(+0.07..+0.19 s at deciles 7-9; ``nn[small>medium]`` 0.044-0.056 against 0.0509, 3 of
seeds 1-6 fail), and :data:`strew.grow._growth.DISC_WIDE_RINGED`'s gap between medium
and large stones made more such holes (1 of 6 pass).

After the growth (and the lone-larger swap), for a smaller kind ``a`` and a larger kind
``b`` (:func:`._lone_larger.lone_sizes`) where the output's upper deciles of the ``a``
elements' nearest-``b`` distances exceed the reference's by
:data:`._lone_larger.LONE_TRIGGER` of the reference's median nearest-neighbour distance
(the fidelity judge's unit), the ``a`` elements beyond the reference's upper decile of
those distances, farthest first and only as many as the output has in excess beyond it,
are moved: taken out and put beside an element of kind ``b`` near them (within
:data:`MOVE_REACH` ``l_short``), at a reference offset of ``a`` beside ``b`` no longer
than that decile, the spot nearest where it was first (:func:`_near_spots`), matched and
placed (§5.2, §5.4). If none places, the element is put back as it was. The seeds the
moved elements' rings put out are dropped: the pass moves elements, it does not add any
(with them, three sizes 80:20:30, ``--harder`` h6s7, grew small stones into the holes
the moved ones left: density[small] 0.305-0.335 -> 0.398-0.403 against 0.295 at seeds 3
and 6). h7s7 at 3.5x, seeds 1-2: small stones beyond the reference's upper decile from
every medium one 123 -> 52 and 123 -> 48, no count changed; 4 of seeds 1-6 pass with
``DISC_WIDE_RINGED``. (§5 grows every element from a ring slot and never returns to a
placed one; the pass is not in the paper.) Only in fixed mode with kinds of several
sizes, after the lone-larger swap at its call site.
"""

from __future__ import annotations

import math

import numpy as np

from ._lone_larger import (
    LONE_DECILE,
    LONE_TOP,
    LONE_TRIGGER,
    MIN_LONE,
    SNUG_TRIES,
    _place_joined,
    lone_sizes,
)
from ._objects import DEAD, ELEMENT, SEED

__all__ = ["move_lone_smaller", "smaller_reach"]

#: how far (in ``l_short``) from a lone element the elements of the larger kind it may
#: be moved against lie
MOVE_REACH = 2.5


def smaller_reach(g) -> tuple[np.ndarray, np.ndarray, np.ndarray, float]:
    """For a smaller visible kind ``a`` and a larger visible kind ``b``, over the
    reference's elements of ``a`` that see their nearest ``b`` within the frame: the
    upper decile of that distance (``q[a, b]``), the share beyond it (``share[a, b]``)
    and its :data:`._lone_larger.LONE_TOP` quantiles (``top[a, b]``), inf where not told;
    and the reference's median nearest-neighbour distance (``unit``)."""
    cached = getattr(g, "_smaller_reach", None)
    if cached is not None:
        return cached
    from scipy.spatial import cKDTree

    n = g.n_kinds
    q, share = np.full((n, n), np.inf), np.zeros((n, n))
    top = np.full((n, n, len(LONE_TOP)), np.inf)
    ex = g.ref.exemplar
    lv = lone_sizes(g)
    if ex.region is not None and n > 1 and float(lv.max()) > float(lv.min()):
        to_edge = np.asarray(ex.region.distance_to_boundary(ex.xy), dtype=float)
        for b in range(n):
            sb = np.flatnonzero(g.ex_kind == b)
            if len(sb) == 0 or g.void_kind[b]:
                continue
            tree = cKDTree(ex.xy[sb])
            for a in range(n):
                if g.void_kind[a] or not lv[b] > lv[a]:
                    continue
                sa = np.flatnonzero(g.ex_kind == a)
                if len(sa) == 0:
                    continue
                d = tree.query(ex.xy[sa])[0]
                d = d[d <= to_edge[sa]]
                if len(d) >= MIN_LONE:
                    q[a, b] = float(np.quantile(d, LONE_DECILE))
                    share[a, b] = float(np.mean(d > q[a, b]))
                    top[a, b] = np.quantile(d, LONE_TOP)
    unit = float(np.median(cKDTree(ex.xy).query(ex.xy, k=2)[0][:, 1])) if len(ex) >= 2 else 0.0
    g._smaller_reach = (q, share, top, unit)
    return g._smaller_reach


def move_lone_smaller(g) -> int:
    """Elements of a smaller kind beyond the reference's upper decile from every element
    of a larger kind, where more of them than in the reference lie beyond it, moved snug
    against one of that kind; how many moved (see the module docstring)."""
    from scipy.spatial import cKDTree

    q, share, top, unit = smaller_reach(g)
    pairs = [(int(a), int(b)) for a, b in zip(*np.nonzero(np.isfinite(q)))]
    if not pairs or unit <= 0:
        return 0
    els = np.asarray([i for i in g.order if g.state[i] == ELEMENT], dtype=np.int64)
    if len(els) < 4:
        return 0
    kinds = g.kind[els]
    pos = g.pos[els]
    cand: list[tuple[float, int, int]] = []
    for a, b in pairs:
        ia, ib = els[kinds == a], els[kinds == b]
        if len(ia) == 0 or len(ib) == 0:
            continue
        d = cKDTree(pos[kinds == b]).query(pos[kinds == a])[0]
        # the elements that see their nearest larger one inside the region (the region
        # crops the pattern as the reference's frame does)
        if g.region is not None:
            seen = d <= np.asarray(g.region.distance_to_boundary(pos[kinds == a]), dtype=float)
            ia, d = ia[seen], d[seen]
        if len(d) < MIN_LONE:
            continue
        over = float(np.mean(np.quantile(d, LONE_TOP) - top[a, b])) / unit
        if over < LONE_TRIGGER:
            continue
        excess = round((float(np.mean(d > q[a, b])) - share[a, b]) * len(d))
        beyond = np.flatnonzero(d > q[a, b])
        beyond = beyond[np.argsort(-d[beyond], kind="stable")][: max(excess, 0)]
        cand.extend((-float(d[i]), int(ia[i]), b) for i in beyond.tolist())
    cand.sort()
    n0 = g.n
    made = 0
    moved: set[int] = set()
    for _, o, b in cand:
        if g.state[o] != ELEMENT or g.fixed[o]:
            continue
        x, y = g.xy[o]
        a = int(g.kind[o])
        lim = float(q[a, b])
        if any(int(g.kind[k]) == b and math.hypot(g.xy[k][0] - x, g.xy[k][1] - y) <= lim for k in g.near(x, y, lim, (ELEMENT,))):
            continue  # an earlier move put one near it
        if _move_one(g, o, a, b, lim):
            moved.add(o)
            made += 1
    if moved:
        g.order[:] = [i for i in g.order if i not in moved]
    # the moved elements' rings' seeds: the pass adds no element
    for i in range(n0, g.n):
        if g.state[i] == SEED:
            g.kill(i)
    return made


def _move_one(g, o: int, a: int, b: int, lim: float) -> bool:
    """Element ``o`` of kind ``a`` taken out and placed snug against an element of kind
    ``b`` near it (:func:`._lone_larger._snug_spots`); put back if none places."""
    x, y = g.xy[o]
    nbs = sorted(g.adj[o])
    near_b = {int(k) for k in g.near(x, y, MOVE_REACH * g.l_short, (ELEMENT,)) if int(g.kind[k]) == b and k != o}
    tg = {j: g.target[j].pop(o) for j in nbs if g.target[j] is not None and o in g.target[j]}
    st = int(g.state[o])
    for j in nbs:
        g.remove_edge(o, j)
    g.state[o] = DEAD
    g.index.remove(o)
    cands = [j for j in sorted(set(nbs) | near_b) if g.state[j] == ELEMENT and int(g.kind[j]) == b]
    for px, py, j in _near_spots(g, x, y, a, b, cands, lim):
        if _place_joined(g, px, py, a, j):
            return True
    g.state[o] = st
    g.index.insert(o, x, y)
    for j in nbs:
        if g.state[j] in (ELEMENT, SEED):
            if not g.has_edge(o, j):
                g.add_edge(o, j)
            if j in tg:
                g.target[j][o] = tg[j]
    return False


def _near_spots(g, x: float, y: float, a: int, b: int, nbs: list[int], lim: float) -> list[tuple[float, float, int]]:
    """Spots for an element of kind ``a`` taken out at ``(x, y)``: each element ``j`` of
    kind ``b`` in ``nbs``, its position plus a reference offset of ``a`` beside ``b``
    (ring slots, fixed mode's frame) no longer than ``lim`` (the reference's upper decile
    of the nearest-``b`` distance), the one nearest ``(x, y)``; nearest first, at most
    :data:`._lone_larger.SNUG_TRIES`. (:func:`._lone_larger._snug_spots`' shorter half
    of the offsets reached 13.2-14.1 beside medium stones at 20:120:20, beyond the
    decile, 11.8: the moved stones stayed beyond it.)"""
    cache = g.__dict__.setdefault("_smaller_near", {})
    off = cache.get((a, b))
    if off is None:
        rings = g.rings
        n = rings["n"]
        own = g.ex_kind[g.ref_ids] == b
        rel = rings["rel"][own]
        sel = (rings["kind"][own] == a) & (np.arange(rel.shape[1])[None, :] < n[own][:, None])
        off = rel[sel].reshape(-1, 2)
        off = off[np.hypot(off[:, 0], off[:, 1]) <= lim]
        cache[(a, b)] = off
    spots: list[tuple[float, int, float, float]] = []
    if len(off) == 0:
        return []
    for j in nbs:
        jx, jy = g.xy[j]
        px, py = jx + off[:, 0], jy + off[:, 1]
        dc = np.hypot(px - x, py - y)
        i = int(np.argmin(dc))
        spots.append((float(dc[i]), int(j), float(px[i]), float(py[i])))
    spots.sort()
    return [(px, py, j) for _, j, px, py in spots[:SNUG_TRIES] if g.in_domain(px, py)]
