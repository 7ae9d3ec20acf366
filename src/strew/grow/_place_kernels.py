"""Compiled probe of one ring slot of §5.4's seeding (Fig. 6 (b) and the closeness rules).

``_Place.place`` puts each unpaired ring slot of a placed element out as a new seed,
unless an object within ``l_short`` takes it (Fig. 6 (b): merge) or an object of a kind
the reference never has that close forbids it (``too_close_in_kind``); a slot of the
largest kind may go over seeds of smaller kinds (``_over_smaller_seeds``). Each of the
three asked the point grid (``GrowIndex.near``) and filtered the answer in Python: three
queries and three Python loops per slot, some 7,000 slots in a growth of 2,000 stones
(issue 14 point 5). :func:`slot_probe` walks the grid as
:func:`strew._kernels.grid.hash_near` does (the same cells, the same order) and applies
the same three tests in one call. In the plane only (an object's original is itself);
on the torus the grower keeps the Python tests.
"""

from __future__ import annotations

import numba

from ._index_kernels import near_one

#: state bits of SEED (1) and ELEMENT (2): the objects the three tests look at
_SEED = 1
_SEED_OR_ELEMENT = (1 << 1) | (1 << 2)


@numba.njit(cache=True, nogil=True)
def _near_into(x, y, r, h, head, ent, cur, ext, pos, state, out, classes=_SEED_OR_ELEMENT):  # pragma: no cover - numba
    """The objects within ``r`` of (x, y) whose state bit is in ``classes`` (default:
    seeds and elements) in ``out``, in :func:`~strew._kernels.grid.hash_near`'s order
    (cells x-major, creation order in a cell); their count."""
    # near_one's walk (the same cells, the same order), bounded by out's room: each live
    # object is listed once, and out has room for all of them
    return near_one(x, y, r, classes, out.shape[0], h, head, ent, cur, ext, pos, state, out)


@numba.njit(cache=True, nogil=True)
def slot_probe(cx, cy, s, kj, over_on, l_short, size_level, top_level, pair_short, pair_short_max,
               h, head, ent, cur, ext, pos, state, kinds, out):  # pragma: no cover - numba
    """Fig. 6 (b) and the closeness rules for a ring slot of kind ``kj`` at (cx, cy) of
    the element placed by seed ``s``, in the plane.

    Returns ``(over, o, too_close)``: ``over``, the slot goes over seeds of smaller kinds
    (``_Place._over_smaller_seeds``, asked only when ``over_on`` and ``kj`` is of the
    largest level); ``o``, the object it merges with (the nearest seed or element within
    ``l_short`` other than ``s``, the first of equals in grid order; -1: none, and
    always -1 when ``over``); ``too_close``, ``_Collide.too_close_in_kind`` (asked only
    when neither of the others holds)."""
    over = False
    if over_on and kj >= 0 and size_level[kj] == top_level:
        r = l_short if l_short >= pair_short_max[kj] else pair_short_max[kj]  # noqa: FURB136 (no builtin to compile)
        n = _near_into(cx, cy, r, h, head, ent, cur, ext, pos, state, out)
        hit = False
        blocked = False
        ls2 = l_short * l_short
        for q in range(n):
            o = out[q]
            if o == s:
                continue
            ko = kinds[o]
            dx = pos[o, 0] - cx
            dy = pos[o, 1] - cy
            d2 = dx * dx + dy * dy
            if d2 >= ls2 and (ko < 0 or d2 >= pair_short[kj, ko] * pair_short[kj, ko]):
                continue
            if state[o] != _SEED or (ko >= 0 and size_level[ko] >= size_level[kj]):
                blocked = True
                break
            hit = True
        over = hit and not blocked
    if over:
        return True, -1, False
    n = _near_into(cx, cy, l_short, h, head, ent, cur, ext, pos, state, out)
    best = -1
    best_d2 = 0.0
    for q in range(n):
        o = out[q]
        if o == s:
            continue
        dx = pos[o, 0] - cx
        dy = pos[o, 1] - cy
        d2 = dx * dx + dy * dy
        if best < 0 or d2 < best_d2:
            best = o
            best_d2 = d2
    if best >= 0:
        return False, best, False
    if kj < 0:
        return False, -1, False
    r = pair_short_max[kj]
    if r <= l_short:
        return False, -1, False
    return False, -1, too_close(cx, cy, kj, s, r, pair_short, _SEED_OR_ELEMENT, h, head, ent, cur, ext, pos, state, kinds, out)


@numba.njit(cache=True, nogil=True)
def too_close(x, y, kind, s, r, ps, classes, h, head, ent, cur, ext, pos, state, kinds, out):  # pragma: no cover - numba
    """``_Collide.too_close_in_kind`` in the plane, past its early returns: is an object
    (state bit in ``classes``, other than ``s``, of a kind ``ko >= 0``) within
    ``ps[kind, ko]`` of (x, y)? ``r`` is the largest of ``ps[kind]``."""
    n = _near_into(x, y, r, h, head, ent, cur, ext, pos, state, out, classes)
    for q in range(n):
        o = out[q]
        if o == s:
            continue
        ko = kinds[o]
        if ko < 0:
            continue
        d = ps[kind, ko]
        dx = pos[o, 0] - x
        dy = pos[o, 1] - y
        if dx * dx + dy * dy < d * d:
            return True
    return False
