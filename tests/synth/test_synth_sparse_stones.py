"""Issue 13 point 1: sparse, unsaturated exemplars (stones dart-thrown with room left
between them). Growth filled every gap: the audit's EDGE stones p2 (radius 4, 60 stones,
gap 4) came out 2.8x the exemplar's density at d66b77e. Each output element's
neighbourhood is now kept no fuller than its exemplar element's
(``_grow.neighbour_limits``, extension of §5.1/§5.6)."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import cKDTree

from strew import Region
from strew.metrics import fidelity
from strew.synth import new_state, synthesize
from strew.synth._grow import neighbour_limits

from strew_testing import fidelity_suite

suite = fidelity_suite()

# benchmarks/_variants.py EDGE["stones"][1]
SPARSE = dict(radius=4.0, count=60, gap=4.0)


@pytest.mark.parametrize("seed", [7, 8])
def test_sparse_stones_keep_the_exemplar_density(seed):
    """2.5x the frame's side: the output's stone density is within the judge's
    tolerance of the exemplar's (d66b77e: about 2.5x the density, failing), and the
    output is faithful."""
    ex = suite.make_exemplar("stones", rng=seed, **SPARSE)
    x0, y0, x1, y1 = ex.region.bounds
    out = synthesize(ex, Region.rectangle(2.5 * (x1 - x0), 2.5 * (y1 - y0)), rng=1, measure=False)
    rep = fidelity(ex, out, eq5=False, local=False)
    dens = rep.metrics["density[stone]"]
    assert dens.applicable and dens.passed, (dens.value, dens.tolerance)
    assert rep.faithful, [k for k, m in rep.metrics.items() if m.applicable and not m.passed]


@pytest.mark.slow
def test_limits_are_the_exemplar_counts():
    """A sparse stone whose r-bar disc lies inside the frame may have as many neighbours
    as it has in the exemplar (nearly every one has room left empty near it); a
    saturated one-kind exemplar (hex lattice, bricks: no open circle), one of shrunk
    collision discs (rows of tiles, sticks), one of two size classes (two_sizes) or one
    with voids (sparse_voids) gets no limit."""
    ex = suite.make_exemplar("stones", rng=7, **SPARSE)
    prep = new_state(ex, Region.rectangle(100, 100), rng=1).prep
    lim = neighbour_limits(prep)
    inner = np.concatenate(prep.interior)
    cnt = cKDTree(prep.pos).query_ball_point(prep.pos[inner], prep.rbar[inner], return_length=True) - 1
    has = lim[inner] >= 0
    assert has.mean() > 0.9
    assert np.array_equal(lim[inner][has], cnt[has])
    for name in ("hex_lattice", "bricks", "rows_noisy", "sticks", "two_sizes", "sparse_voids"):
        prep = new_state(suite.make_exemplar(name, rng=1), Region.rectangle(100, 100), rng=1).prep
        assert np.all(neighbour_limits(prep) == -1), name
