"""The grower's state copied as :func:`copy.deepcopy` copies it, in less time (issue 14
point 5).

:func:`strew.grow._flow_retry.snapshot` keeps the grower's whole state before each
round of :mod:`strew.grow._flow_densify` (a round that is not kept puts it back). At
3,000 elements :func:`copy.deepcopy` of it took about 0.5 s a round, most of it in
walking containers of plain values one item at a time: the positions (tuples of
floats), the ring counts and flow angles (dicts of ints and floats), the edge ids
(a dict keyed by tuples of ints), the index's arrays. :func:`deep_copy_state` copies
each such container in one call (``list(x)``, ``dict(x)``, ``set(x)``,
``ndarray.copy``) and hands the copies to :func:`copy.deepcopy` through its memo, which
copies the rest as before. A container holding anything but plain values (ints,
floats, bools, strings, None, numpy scalars, or tuples of these) is left to
:func:`copy.deepcopy`, so the copy is the one it makes: the same values, the same
sharing (a container met twice is copied once), and nothing mutable shared with the
original.
"""

from __future__ import annotations

import copy
from typing import Any

import numpy as np

__all__ = ["deep_copy_state"]

#: immutable values that copy.deepcopy returns as they are (numpy scalars: a copy, of
#: the same value; immutable either way)
_PLAIN = frozenset(
    {
        int,
        float,
        bool,
        str,
        type(None),
        np.int64,
        np.int32,
        np.int8,
        np.float64,
        np.bool_,
    }
)


def _plain_items(items: Any) -> bool:
    """Are all ``items`` plain values or tuples of plain values?"""
    plain = _PLAIN
    for t in items:
        ty = type(t)
        if ty in plain:
            continue
        if ty is tuple:
            for u in t:
                if type(u) not in plain:
                    return False
            continue
        return False
    return True


def _flat_copy(v: Any) -> Any:
    """``v`` copied in one call where that is its deep copy, else None."""
    ty = type(v)
    if ty is np.ndarray:
        # (ndarray.__deepcopy__: a copy in the same memory order; object arrays deep)
        return v.copy(order="K") if v.dtype != object else None
    if ty is list:
        return list(v) if _plain_items(v) else None
    if ty is dict:
        return dict(v) if _plain_items(v.keys()) and _plain_items(v.values()) else None
    if ty is set:
        return set(v) if _plain_items(v) else None
    return None


def deep_copy_state(d: dict, memo: dict) -> dict:
    """``copy.deepcopy(dict(d), memo)``, the plain containers among ``d``'s values and
    among the attributes of the objects there (one level down: the grower's index and
    its grids) copied in one call each first. ``memo`` may hold copies made already
    (or objects to share, mapped to themselves); it is filled in."""

    def ours(v: Any) -> bool:  # (an object of strew's, not one the memo shares)
        return (
            id(v) not in memo
            and hasattr(v, "__dict__")
            and type(v).__module__.startswith("strew.")
        )

    todo = list(d.values())
    for v in list(todo):
        if ours(v):
            inner = list(vars(v).values())
            todo.extend(inner)
            todo.extend(x for w in inner if ours(w) for x in vars(w).values())
    for v in todo:
        if id(v) in memo:
            continue
        c = _flat_copy(v)
        if c is not None:
            memo[id(v)] = c
            # (deepcopy keeps the originals alive in the memo; these are alive in ``d``)
    return copy.deepcopy(dict(d), memo)
