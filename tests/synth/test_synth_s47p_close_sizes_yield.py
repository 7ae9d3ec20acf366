"""Issue 13 point 1 (helper s47p): in exemplars of three size classes or more, the
smallest class yields (``_grow._split_conflicts``) only to a class at least
``_grow.YIELD_STEP`` times its bounding radius (``_grow._yields_below``). Three sizes
1 : 1.6 : 2.6 (``benchmarks/_variants.py`` three_sizes EDGE p2, the audit's ``p2s34``):
on main every disagreement between neighbouring copies went to the medium stones, and
growth left the small ones at 0.74 of their density (nn[small>small] failing at 6/6
seeds of the audit)."""

from __future__ import annotations

import numpy as np
import pytest
from strew_testing import fidelity_suite

import strew.synth._grow as G
from strew import Region
from strew.metrics import fidelity
from strew.synth import synthesize
from strew.synth._api import new_state


def _p2(v: int):
    return fidelity_suite().make_exemplar("three_sizes", rng=v, ratios=(1.0, 1.6, 2.6), counts=(150, 90, 40))


def test_close_small_stones_do_not_yield_to_the_medium_ones():
    prep = new_state(_p2(34)).prep
    # small (class 0) no longer yields to medium (1.5x its radius), still to large (2.5x)
    assert G._yields_below(prep).tolist() == [1, 1, 2]
    # the default three sizes (1 : 2 : 4) keep the plain rule
    prep = new_state(fidelity_suite().make_exemplar("three_sizes", rng=34)).prep
    assert G._yields_below(prep).tolist() == [0, 1, 2]


@pytest.mark.slow
def test_close_sizes_keep_their_small_stones_apart_as_the_exemplar():
    ex = _p2(34)
    x0, y0, x1, y1 = ex.region.bounds
    out = synthesize(ex, Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=1, measure=False)
    rep = fidelity(ex, out, eq5=False, local=False)
    m = rep.metrics["nn[small>small]"]
    # main (993742e): 0.130 against the tolerance 0.119 (the audit's row, seed 1)
    assert m.passed and m.value < 0.11, (m.value, m.tolerance)
    small, medium = (int(np.count_nonzero(np.asarray(out.kind) == out.kinds.index(k))) for k in ("small", "medium"))
    # main: 1,401 small against 1,190 medium (1.18), this change 1,482 : 1,144 (1.30); the exemplar 150 : 90
    assert small > 1.24 * medium, (small, medium)
