"""Flow mode: the network passes' measures of one set of positions made once
(issue 14 point 5; :mod:`strew.grow._flow_memo`).

The memo must give what measuring again gives: each wrapped measure of
:mod:`strew.grow._flow_net` against its measuring function on positions of a grown
lattice moved at random, a changed position measured anew, the answers read-only,
and a whole flow growth the same to the last bit with the memo as with every measure
made each time.
"""

from __future__ import annotations

import numpy as np
from test_grow_flow14d_stretch import hex_ref  # noqa: F401 (a fixture)
from test_grow_flow14g_retry import _turning_90
from test_grow_flow_gaps import SP

from strew import Region
from strew.grow import _flow_net
from strew.grow._growth import GrowParams, grow_reference
from strew.grow._objects import ELEMENT


def _grown(hex_ref, monkeypatch):
    """A flow growth of the hexagonal lattice over 14 x 10 spacings along the 90 degree
    field, and its grower (kept at its last network pass)."""
    from strew.grow import _growth

    region = Region.rectangle(14 * SP, 10 * SP)
    seen = {}
    orig = _growth.relax_network

    def keep(g, band=None):
        seen["g"] = g
        return orig(g, band)

    monkeypatch.setattr(_growth, "relax_network", keep)
    out = grow_reference(hex_ref, GrowParams(region=region, mode="flow", flow=_turning_90(14 * SP)), rng=1)
    return out, seen["g"]


def _same(a, b) -> bool:
    if isinstance(a, np.ndarray):
        return a.shape == b.shape and a.dtype == b.dtype and a.tobytes() == b.tobytes()
    return a == b


def test_memo_answers_what_measuring_gives(hex_ref, monkeypatch):
    from strew.grow._flow_memo import memo

    _, g = _grown(hex_ref, monkeypatch)
    els = [i for i in g.order if g.state[i] == ELEMENT]
    xy0 = g.pos[els].copy()
    rng = np.random.default_rng(7)
    grid = _flow_net._grid(g)
    inner = rng.random(len(xy0)) < 0.8
    for _ in range(4):
        xy = xy0 + rng.normal(scale=0.04 * g.l, size=xy0.shape)
        for _twice in range(2):  # (the second time from the memo)
            assert _same(_flow_net._six_share(g, xy), _flow_net._six_share_at(g, xy))
            assert _same(_flow_net._turns(g, xy), _flow_net._turns_at(g, xy))
            assert _same(_flow_net._six_sites(g, inner, xy), _flow_net._six_sites_at(g, inner, xy))
            assert _same(_flow_net._far_circles(g, xy), _flow_net._far_circles_at(g, xy))
    # the far points of the elements where they are (no positions asked)
    assert _same(_flow_net._far_points(g, grid), _flow_net._far_points_at(g, xy0, grid))
    # answers are kept read-only, and a position changed by one ulp is measured anew
    calls = []

    def measure():
        calls.append(1)
        return np.arange(3.0)

    a = memo(g, "probe", (xy0,), measure)
    assert memo(g, "probe", (xy0,), measure) is a and len(calls) == 1
    assert not a.flags.writeable
    moved = xy0.copy()
    moved[5, 0] = np.nextafter(moved[5, 0], np.inf)
    memo(g, "probe", (moved,), measure)
    assert len(calls) == 2
    # past the byte budget the oldest answers go, and are measured anew when asked
    from strew.grow import _flow_memo

    monkeypatch.setattr(_flow_memo, "MEMO_BYTES", 3 * xy0.nbytes)
    for k in range(4):
        memo(g, "budget", (xy0 + k,), measure)
    store, used = _flow_memo._STORE[g]
    assert used[0] <= 3 * xy0.nbytes and used[0] == sum(size for _, size in store.values())
    n = len(calls)
    memo(g, "budget", (xy0 + 3,), measure)  # (kept)
    memo(g, "budget", (xy0 + 0,), measure)  # (dropped: measured again)
    assert len(calls) == n + 1
    # a stand-in without weak references is measured each time
    from types import SimpleNamespace

    s = SimpleNamespace()
    memo(s, "probe", (xy0,), measure)
    memo(s, "probe", (xy0,), measure)
    assert len(calls) == n + 3


def test_flow_growth_is_the_same_with_the_memo(hex_ref, monkeypatch):
    out, _ = _grown(hex_ref, monkeypatch)
    monkeypatch.setattr(_flow_net, "memo", lambda g, name, arrays, compute: compute())
    base, _ = _grown(hex_ref, monkeypatch)
    assert len(out) == len(base)
    assert out.xy.tobytes() == base.xy.tobytes()
    assert np.array_equal(out.rotation, base.rotation)
