"""Issue 14 point 5: the flow passes' snapshot of the grower's state
(:func:`strew.grow._flow_retry.snapshot`) copies its plain containers in one call each
(:mod:`strew.grow._state_copy`); the copy must be the one ``copy.deepcopy`` made:
the same values, the same sharing between its parts, nothing mutable shared with the
grower."""

from __future__ import annotations

import copy
import math

import numpy as np
import pytest
import shapely

from strew import Region


def _deepcopy_snapshot(g) -> dict:
    """The snapshot as :func:`strew.grow._flow_retry.snapshot` made it at 9dffc62."""
    from strew.grow._flow_retry import _SHARED

    d = vars(g)
    memo = {id(d[k]): d[k] for k in _SHARED if k in d}
    memo[id(g)] = g
    for k in ("geom", "xy"):
        memo[id(d[k])] = list(d[k])
    memo[id(d["adj"])] = [set(a) for a in d["adj"]]
    memo[id(d["edges"])] = set(d["edges"])
    memo[id(d["target"])] = [None if t is None else dict(t) for t in d["target"]]
    return copy.deepcopy(dict(d), memo)


def _same(a, b, pairs: dict, path: str = "") -> None:
    """``a`` and ``b`` hold the same values, and an object met twice in ``a`` is met
    as the same object in ``b`` (``pairs``: id in a -> id in b)."""
    assert type(a) is type(b), path
    if isinstance(a, (list, dict, set, np.ndarray)) or hasattr(a, "__dict__"):
        if id(a) in pairs:
            assert pairs[id(a)] == id(b), f"{path}: shared differently"
            return
        pairs[id(a)] = id(b)
    if isinstance(a, np.ndarray):
        assert a.dtype == b.dtype and a.shape == b.shape and a.strides == b.strides, (
            path
        )
        assert a.tobytes() == b.tobytes(), path
    elif isinstance(a, (list, tuple)):
        assert len(a) == len(b), path
        for q, (u, v) in enumerate(zip(a, b)):
            _same(u, v, pairs, f"{path}[{q}]")
    elif isinstance(a, dict):
        assert list(a) == list(b), path
        for k in a:
            _same(a[k], b[k], pairs, f"{path}[{k!r}]")
    elif isinstance(a, set):
        assert a == b, path
    elif isinstance(a, shapely.Geometry):
        assert shapely.to_wkb(a) == shapely.to_wkb(b), path
    elif isinstance(a, np.random.Generator):
        assert a.bit_generator.state == b.bit_generator.state, path
    elif hasattr(a, "__dict__"):
        _same(vars(a), vars(b), pairs, f"{path}.")
    else:
        assert a == b or (isinstance(a, float) and math.isnan(a) and math.isnan(b)), (
            path
        )


def _mutables(x, out: dict, skip: set) -> None:
    """Every list, dict, set and array reachable from ``x`` (not through ``skip``)."""
    if id(x) in skip or id(x) in out:
        return
    if isinstance(x, (list, dict, set, np.ndarray)) or hasattr(x, "__dict__"):
        out[id(x)] = x
    if isinstance(x, (list, tuple, set)):
        for v in x:
            _mutables(v, out, skip)
    elif isinstance(x, dict):
        for v in x.values():
            _mutables(v, out, skip)
    elif hasattr(x, "__dict__") and not isinstance(x, shapely.Geometry):
        _mutables(vars(x), out, skip)


@pytest.mark.slow
def test_snapshot_is_the_deep_copy_it_replaces(monkeypatch):
    import strew.grow._flow_densify as FD
    from strew.grow import analyze, grow
    from strew.grow._exemplars import hex_exemplar
    from strew.grow._flow_retry import _SHARED, restore, snapshot

    got = []
    score = FD._score

    def keep(g, grid):
        got.append(g)
        return score(g, grid)

    monkeypatch.setattr(FD, "_score", keep)
    hex_ref = analyze(hex_exemplar())
    sp = hex_ref.mean_edge
    w = 12 * sp

    def field(p):
        a = np.radians(90.0) * np.clip(np.asarray(p)[:, 0] / w, 0, 1)
        return np.c_[np.cos(a), np.sin(a)]

    grow(hex_ref, rng=1, region=Region.rectangle(w, 8 * sp), mode="flow", flow=field)
    assert got
    g = got[-1]
    old, new = _deepcopy_snapshot(g), snapshot(g)
    _same(old, new, {})
    # and deep_copy_state on its own: copy.deepcopy's copy of the whole state
    from strew.grow._state_copy import deep_copy_state

    def shared_memo():
        return {id(vars(g)[k]): vars(g)[k] for k in _SHARED if k in vars(g)} | {id(g): g}

    _same(copy.deepcopy(dict(vars(g)), shared_memo()), deep_copy_state(vars(g), shared_memo()), {})
    # nothing mutable in the copy is the grower's (but the shared reference, parameters
    # and reporter, and the grower itself)
    shared = {id(vars(g)[k]) for k in _SHARED if k in vars(g)} | {id(g)}
    mine: dict = {}
    _mutables(vars(g), mine, shared)
    theirs: dict = {}
    _mutables(new, theirs, shared)
    assert len(theirs) > 50
    assert not set(mine) & set(theirs)
    # put back and grown on, the grower is as it was
    xy0 = [tuple(v) for v in g.xy]
    g.xy[0] = (1e9, 1e9)
    g.adj[0].add(-5)
    restore(g, new)
    assert g.xy == xy0 and -5 not in g.adj[0]
    assert g.index.xy is g.xy and g.index.adj is g.adj and g.index.pos is g.pos
