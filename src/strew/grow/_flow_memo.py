"""Flow mode: the network passes' measures of one set of positions, made once (issue 14
point 5).

:mod:`strew.grow._flow_net` measures the placed elements again and again at
positions it has measured before: each band pass starts with the six-neighbour sites,
the six share, the grid's far points and the Delaunay bonds of the positions it
starts from, and :func:`strew.grow._flow_net._band_passes` makes its three runs from
the same positions, so the second and third runs' first passes measure what the
first run's did; a pass that is kept leaves the positions whose six share, far
points and turn the next pass measures again. On the hexagonal lattice grown along
the field turning 90 degrees (``benchmarks/grow.py --against``'s ``hexflow``), 31
six shares were asked of 14 positions, 22 far-point sets of 7, 30 six-site masks of
18, 14 empty-circle sets of 6, 33 turn fields of 14 and 17 bond sets of 13
(``benchmarks/spd15_passes.py``).

Each measure is a function of its array arguments and of what stays fixed through a
growth (the region, the exemplar, the field, the six-neighbour spacing), so
:func:`memo` keeps its answer per grower, keyed by the arrays' bytes (exact: equal
keys are equal arrays), and gives the same answer when asked again; answers are
made read-only so no caller can change a kept one. The store is not in the grower's
state (``vars``), so :func:`strew.grow._flow_retry.snapshot` does not copy it and
:func:`strew.grow._flow_retry.restore` does not drop it (an answer stays true of its
positions whatever state is put back), and it goes with the grower. The keys hold
the arrays' bytes, so at most :data:`MEMO_BYTES` of keys are kept per grower (the
oldest answers dropped first: a far-point key holds the quarter-edge grid too, some
0.1 MB for 30 x 20 spacings, 2.6 MB for 10,000 elements).
"""

from __future__ import annotations

import weakref
from collections.abc import Callable
from typing import Any

import numpy as np

__all__ = ["memo"]

#: how many bytes of keys are kept per grower (the hexflow growth of
#: ``benchmarks/grow.py --against`` keeps 72 answers, 1.5 MB)
MEMO_BYTES = 32 << 20

# grower -> (answers by key, [bytes of their keys]), insertion-ordered
_STORE: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def _key(name: str, arrays: tuple) -> tuple[tuple, int]:
    parts: list[Any] = [name]
    size = 0
    for a in arrays:
        if isinstance(a, np.ndarray):
            b = np.ascontiguousarray(a).tobytes()
            size += len(b)
            parts.append((a.shape, a.dtype.str, b))
        else:
            parts.append(a)
    return tuple(parts), size


def memo(g, name: str, arrays: tuple, compute: Callable[[], Any]) -> Any:
    """``compute()``, or the answer it gave before for the same grower ``g``, measure
    ``name`` and arguments ``arrays`` (numpy arrays, compared by value, or hashable
    values); array answers come back read-only."""
    try:
        kept = _STORE.get(g)
    except TypeError:  # (a stand-in that takes no weak reference: measured each time)
        return compute()
    if kept is None:
        kept = ({}, [0])
        _STORE[g] = kept
    store, used = kept
    key, size = _key(name, arrays)
    got = store.get(key)
    if got is not None:
        return got[0]
    got = compute()
    if isinstance(got, np.ndarray):
        got.setflags(write=False)
    elif isinstance(got, tuple):
        for a in got:
            if isinstance(a, np.ndarray):
                a.setflags(write=False)
    while store and used[0] + size > MEMO_BYTES:
        used[0] -= store.pop(next(iter(store)))[1]
    store[key] = (got, size)
    used[0] += size
    return got
