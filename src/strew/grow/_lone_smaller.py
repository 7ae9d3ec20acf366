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

import numpy as np

from ._lone_larger import (
    LONE_DECILE,
    LONE_TOP,
    SNUG_TRIES,
    _place_joined,
    lone_candidates,
    lone_pass,
    put_back,
    ref_nearest,
    ring_offsets,
    take_out,
)
from ._objects import ELEMENT, SEED

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
    for a, b, d in ref_nearest(g, larger=False):
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
    q, share, top, unit = smaller_reach(g)
    pairs = [(int(a), int(b)) for a, b in zip(*np.nonzero(np.isfinite(q)))]
    if unit <= 0:
        return 0
    cand = lone_candidates(g, pairs, q, q, share, top, unit)
    n0 = g.n
    # (an earlier move may have put a ``b`` element within the decile: then it is left)
    made = lone_pass(g, cand, q, lambda o, b: _move_one(g, o, int(g.kind[o]), b, float(q[int(g.kind[o]), b])))
    # the moved elements' rings' seeds: the pass adds no element
    for i in range(n0, g.n):
        if g.state[i] == SEED:
            g.kill(i)
    return made


def _move_one(g, o: int, a: int, b: int, lim: float) -> bool:
    """Element ``o`` of kind ``a`` taken out and placed snug against an element of kind
    ``b`` near it (:func:`_near_spots`); put back if none places."""
    x, y = g.xy[o]
    near_b = {int(k) for k in g.near(x, y, MOVE_REACH * g.l_short, (ELEMENT,)) if int(g.kind[k]) == b and k != o}
    nbs, tg, st = take_out(g, o)
    cands = [j for j in sorted(set(nbs) | near_b) if g.state[j] == ELEMENT and int(g.kind[j]) == b]
    for px, py, j in _near_spots(g, x, y, a, b, cands, lim):
        if _place_joined(g, px, py, a, j):
            return True
    put_back(g, o, x, y, nbs, tg, st)
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
        off = ring_offsets(g, b, a)
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
