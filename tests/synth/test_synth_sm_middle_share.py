"""Issue 13 point 1 (helper sm): a rare middle size class takes its exemplar's share, not
the share plus the exemplar's sampling error.

A middle class displaces young smaller elements while ``_grow.owed_classes`` says the output
owes it; with a margin of two standard errors (half the share of a class of 15 among 430)
and the union of a step's overlapping copies offering it places, the medium stones of
three sizes 400:15:15 (--harder h12) grew to the bound: 1.4-1.5x their share, failing
density[medium] on the held-out draws h12s11 and h12s12 at every seed 1-6."""

from __future__ import annotations

import numpy as np
import pytest
from strew_testing import fidelity_suite

from strew import Region
from strew.synth import synthesize


@pytest.mark.slow
@pytest.mark.parametrize("variant", [9, 11, 12])
def test_rare_middle_class_keeps_its_share(variant):
    # 2x the exemplar's side, seed 1; each kind's share of the output over its share of the
    # exemplar. 9877c79: medium 1.369 / 1.403 / 1.478 (variant 9 / 11 / 12; seed 2 1.29 /
    # 1.22 / 1.51); with MIDDLE_RARE (no margin for a rare middle class): 1.007 / 1.021 / 1.057 (seed 2 1.05 / 0.97 / 1.08)
    ex = fidelity_suite().make_exemplar("three_sizes", rng=variant, counts=(400, 15, 15))
    x0, y0, x1, y1 = ex.region.bounds
    out = synthesize(ex, Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0)), rng=1, measure=False)
    assert list(out.kinds) == list(ex.kinds)
    ratio = (np.bincount(out.kind, minlength=3) / len(out)) / (np.bincount(ex.kind, minlength=3) / len(ex))
    assert 0.85 <= ratio[1] <= 1.2, ratio
    assert ratio[0] >= 0.95 and ratio[2] >= 0.9, ratio
