"""grow's compiled probe of a ring slot (``_place_kernels.slot_probe``): the answers of
the Python tests it replaced in ``_Place.place`` (Fig. 6 (b) merge, ``too_close_in_kind``,
``_over_smaller_seeds``; issue 14 point 5, speed; byte-identical output)."""

from __future__ import annotations

import numpy as np


def _python_answers(g, cx, cy, s, kj):
    """The tests as ``place`` wrote them before the kernel (d67a7c3)."""
    over = g.over_smaller and kj >= 0 and g.size_level[kj] == g.top_level and g._over_smaller_seeds(s, cx, cy, kj)
    close = g.near(cx, cy, g.l_short) if not over else []
    close = [o for o in close if g.orig_of[o] != s]
    if not close and not over and g.too_close_in_kind(cx, cy, kj, s):
        return over, -1, True
    if close:
        return over, min(close, key=lambda o: (g.xy[o][0] - cx) ** 2 + (g.xy[o][1] - cy) ** 2), False
    return over, -1, False


def _probe(g, cx, cy, s, kj, over_on=None):
    from strew.grow._place_kernels import slot_probe

    ix, pts = g.index, g.index.points
    on = g.over_smaller if over_on is None else over_on
    return slot_probe(cx, cy, s, kj, bool(on), float(g.l_short), g.size_level, float(g.top_level), g.pair_short, g.pair_short_max,
                      ix.cell, pts.head, pts.ent, pts.cur, pts.ext, ix.pos, ix.state, g.kind, ix.out)


def test_slot_probe_equals_the_python_tests(monkeypatch):
    """Every slot of a growth of three sizes (the largest kind's slots go over smaller
    seeds), and random points about its objects with every kind, as the Python tests."""
    from strew_testing import fidelity_suite

    import strew.grow._growth as G
    from strew.grow import analyze, grow

    grown = []
    init = G._Grower.__init__

    def keep(self, *a, **k):
        init(self, *a, **k)
        grown.append(self)

    monkeypatch.setattr(G._Grower, "__init__", keep)
    grow(analyze(fidelity_suite().make_exemplar("three_sizes")), count=120, rng=1, relax=True)
    g = grown[-1]
    assert g.over_smaller and g.tile is None
    rng = np.random.default_rng(5)
    n = g.n
    live = np.flatnonzero(g.state[:n] > 0)
    seen = {"over": 0, "merge": 0, "close": 0, "free": 0}
    for _ in range(800):
        o = int(rng.choice(live))
        t = rng.uniform(0, 2 * np.pi)
        d = rng.uniform(0, 2.5) * g.l_short
        cx, cy = float(g.pos[o, 0] + d * np.cos(t)), float(g.pos[o, 1] + d * np.sin(t))
        s = int(rng.choice(live)) if rng.random() < 0.7 else o
        kj = int(rng.integers(-1, g.n_kinds))
        want = _python_answers(g, cx, cy, s, kj)
        got = _probe(g, cx, cy, s, kj)
        assert (bool(got[0]), int(got[1]), bool(got[2])) == (bool(want[0]), int(want[1]), bool(want[2]))
        seen["over" if want[0] else "merge" if want[1] >= 0 else "close" if want[2] else "free"] += 1
    assert min(seen.values()) > 10, seen
    # without the size rule (one size): never over
    g.over_smaller = False
    for _ in range(300):
        o = int(rng.choice(live))
        cx, cy = float(g.pos[o, 0] + 0.3 * g.l_short), float(g.pos[o, 1])
        kj = int(rng.integers(-1, g.n_kinds))
        want = _python_answers(g, cx, cy, int(live[0]), kj)
        got = _probe(g, cx, cy, int(live[0]), kj)
        assert (bool(got[0]), int(got[1]), bool(got[2])) == (bool(want[0]), int(want[1]), bool(want[2]))


def test_too_close_in_kind_equals_the_python_loop(monkeypatch):
    """``too_close_in_kind`` in the plane (compiled) gives the answers of its Python loop,
    for seeds and elements, new seeds and placements, on a growth of three sizes."""
    from strew_testing import fidelity_suite

    import strew.grow._growth as G
    from strew.grow import analyze, grow
    from strew.grow._objects import ELEMENT, SEED
    from strew.grow._place_kernels import too_close

    grown = []
    init = G._Grower.__init__

    def keep(self, *a, **k):
        init(self, *a, **k)
        grown.append(self)

    monkeypatch.setattr(G._Grower, "__init__", keep)
    grow(analyze(fidelity_suite().make_exemplar("three_sizes")), count=100, rng=2, relax=True)
    g = grown[-1]

    def loop(x, y, kind, s, states, placing):
        if kind < 0:
            return False
        ps = g.pair_close if placing else g.pair_short
        r = float((g.pair_close_max if placing else g.pair_short_max)[kind])
        if r <= g.l_short:
            return False
        for o in g.near(x, y, r, states):
            ko = int(g.kind[o])
            if g.orig_of[o] == s or ko < 0:
                continue
            if (g.xy[o][0] - x) ** 2 + (g.xy[o][1] - y) ** 2 < ps[kind, ko] ** 2:
                return True
        return False

    rng = np.random.default_rng(7)
    live = np.flatnonzero(g.state[: g.n] > 0)
    hits = 0
    for _ in range(600):
        o = int(rng.choice(live))
        t, d = rng.uniform(0, 2 * np.pi), rng.uniform(0, 3.0) * g.l_short
        x, y = float(g.pos[o, 0] + d * np.cos(t)), float(g.pos[o, 1] + d * np.sin(t))
        s = o if rng.random() < 0.3 else int(rng.choice(live))
        kind = int(rng.integers(-1, g.n_kinds))
        states = (SEED, ELEMENT) if rng.random() < 0.5 else (ELEMENT,)
        placing = bool(rng.random() < 0.5)
        want = loop(x, y, kind, s, states, placing)
        assert g.too_close_in_kind(x, y, kind, s, states, placing=placing) == want
        if kind >= 0:  # the kernel itself, past the early returns
            ps = g.pair_close if placing else g.pair_short
            r = float((g.pair_close_max if placing else g.pair_short_max)[kind])
            if r > g.l_short:
                ix, pts = g.index, g.index.points
                bits = sum(1 << b for b in states)
                got = too_close(x, y, kind, s, r, ps, bits, ix.cell, pts.head, pts.ent, pts.cur, pts.ext, ix.pos, ix.state, g.kind, ix.out)
                assert bool(got) == want
        hits += want
    assert 50 < hits < 550
