"""Issue 13 point 1 (helper s37k): two classes keep the exemplar's closest approach less
the gap to its next smallest distance (``_prepare.approach_bound``), not a fixed 0.95 of
it, so a hard-core scatter near jamming (stripes) is not packed beyond its hard core."""

from __future__ import annotations

import numpy as np
from scipy.spatial.distance import cdist, pdist
from strew_testing import fidelity_suite

from strew import Region
from strew.metrics import fidelity
from strew.synth import as_selection, prepare, synthesize
from strew.synth._prepare import approach_bound, closest_approach


def test_closest_approach_second_is_the_next_distinct_pair():
    rng = np.random.default_rng(3)
    for _ in range(30):
        n = int(rng.integers(4, 30))
        p = rng.uniform(0, 100, (n, 2))
        c = np.r_[0, 0, 0, 1, rng.integers(0, 2, n - 4)]
        first, second = closest_approach(p, c, np.zeros(n, np.int64), second=True)
        for a in range(2):
            for b in range(2):
                pa, pb = p[c == a], p[c == b]
                d = np.sort(pdist(pa)) if a == b else np.sort(cdist(pa, pb).ravel())
                if len(d) < 2:
                    assert np.isinf(second[a, b])
                    continue
                assert np.isclose(first[a, b], d[0]) and np.isclose(second[a, b], d[1])


def test_bound_is_the_endpoint_estimate_never_below_095():
    b = approach_bound(np.array([10.0, 10.0, 10.0]), np.array([10.01, 10.3, np.inf]))
    assert np.allclose(b, [9.99, 9.7, 9.5])


def test_jammed_stripes_keep_their_hard_core():
    # stripes v20: dart-thrown discs of one radius (4.74) and gap 2.2, 136 of 220 placed
    ex = fidelity_suite().make_exemplar("stripes", rng=20)
    p = prepare(as_selection(ex))
    kn = np.asarray(ex.kind_names)
    xy = np.asarray(ex.xy, float)
    names = list(ex.shapes)
    kind_of = {int(k): int(s) for k, s in zip(p.kind, p.skind)}
    for a in ("dot", "bar"):
        for b in ("dot", "bar"):
            pa, pb = xy[kn == a], xy[kn == b]
            d = np.sort(pdist(pa)) if a == b else np.sort(cdist(pa, pb).ravel())
            # main: 0.95 of the closest approach
            got = p.min_dist[kind_of[names.index(a)], kind_of[names.index(b)]]
            assert 0.98 * d[0] <= got <= d[0], (a, b, got, d[:2])
    # at 3.5x the frame, seeds 1 and 2: density[dot] 0.132 on main (tolerance 0.127;
    # the dots 1.13x the exemplar's density), now 0.071 and 0.077
    x0, y0, x1, y1 = ex.region.bounds
    for seed in (1, 2):
        out = synthesize(ex, Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed, measure=False)
        m = fidelity(ex, out, eq5=False, local=False).metrics["density[dot]"]
        assert m.value < 0.1, (seed, m.value, m.tolerance)


def test_structures_keep_095_of_their_spacing():
    # ring hubs (an anchor kind), cluster discs (a larger size class) and a lattice's
    # elements keep 0.95 of their closest approach: 1.0 of it lost rows (commits
    # d6e3d56, cf08de4; hex lattice 6 of 10 --varied rows at variant seeds 27, 28)
    for name in ("rings", "clusters", "hex_lattice"):
        ex = fidelity_suite().make_exemplar(name, rng=20)
        p = prepare(as_selection(ex))
        raw = closest_approach(p.pos, p.skind, p.source)
        ok = np.isfinite(raw)
        assert np.allclose(p.min_dist[ok], 0.95 * raw[ok]), (name, p.min_dist, raw)
