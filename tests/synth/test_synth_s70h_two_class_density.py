"""Issue 13 point 1 (helper s70h, after s67h and s69h): for two size classes the larger class
is owed by its count per grown area against the exemplar's density as the fidelity metric
counts it (``_grow._TWO_CLASS_AREA``), and, where it is rare (share under
``_grow._TWO_CLASS_NN_SHARE``), also while the smaller elements stand farther from it than in
the exemplar (``benchmarks/results/s70h_notes.md``).

The share bound (share + ``SHARE_MARGIN`` errors over the whole frame) over-placed stones on
--harder two_sizes h5 at variant seed 38 (density[stone] +0.18, 0/6 seeds faithful) and
under-placed them on h11 at variant seed 37 (-0.14, 0/4): both exemplars are walls whose
pebble band along the frame the metric leaves out.
"""

from __future__ import annotations

import numpy as np
import pytest

from strew import Region
from strew.metrics import fidelity
from strew.synth import _grow as G
from strew.synth import new_state, synthesize

from strew_testing import fidelity_suite

make_exemplar = fidelity_suite().make_exemplar

H5 = dict(ratio=0.6, n_large=25, n_small=250)  # benchmarks/grow_variants.py HARDER two_sizes h5
H11 = dict(ratio=0.65, n_large=30, n_small=150)  # HARDER two_sizes h11


def _synth(ex, seed):
    x0, y0, x1, y1 = ex.region.bounds
    return synthesize(ex, Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed, measure=False)


@pytest.mark.parametrize("params,variant", [(H5, 38), (H11, 37)], ids=["h5s38", "h11s37"])
def test_two_sizes_wall_faithful(params, variant):
    """Fail on main: h5s38 density[stone] 0.18 over (tolerance 0.146), h11s37 0.14 under."""
    ex = make_exemplar("two_sizes", rng=variant, **params)
    rep = fidelity(ex, _synth(ex, 1), eq5=False, local=False)
    assert rep.faithful, [f"{k}={v.value:.3g}/{v.tolerance:.3g}" for k, v in rep.metrics.items() if v.applicable and not v.passed]


P2 = dict(ratio=0.15, n_large=50, n_small=500)  # benchmarks/_variants.py EDGE two_sizes (--varied p2)


def test_rare_larger_class_reads_nn_target():
    """A rare larger class (p2 at variant seed 33: share 0.07) gets the judge's
    nn[pebble>stone] median as a second target; h5 (share 0.3) does not."""
    rare = make_exemplar("two_sizes", rng=33, **P2)
    t = G._two_class_target(new_state(rare, Region.rectangle(300, 300), rng=1).prep)
    assert t is not None and np.isfinite(t[-1]) and t[-1] > 0
    common = make_exemplar("two_sizes", rng=38, **H5)
    t = G._two_class_target(new_state(common, Region.rectangle(300, 300), rng=1).prep)
    assert t is not None and np.isnan(t[-1])


def test_rare_stones_keep_pebbles_near():
    """s69h's density rule alone failed p2s33 on nn[pebble>stone] (0.203 / 0.173): at the
    counted density the pebbles stood too far from the stones (s70h_notes.md)."""
    ex = make_exemplar("two_sizes", rng=33, **P2)
    rep = fidelity(ex, _synth(ex, 1), eq5=False, local=False)
    m = rep.metrics["nn[pebble>stone]"]
    assert m.passed, (m.value, m.tolerance)
