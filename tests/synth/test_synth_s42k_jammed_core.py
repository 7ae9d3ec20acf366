"""Issue 13 point 1 (helper s42k): the hard-core endpoint bound (``_prepare.approach_bound``)
acts only on a scatter jammed at its hard core (``_prepare.JAMMED_CORE``): a saturated
scatter of round stones, whose two closest pairs are close but whose lowest nn decile lies
well above them, keeps 0.95 of its closest approach."""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree
from strew_testing import fidelity_suite

from strew import Region
from strew.metrics import fidelity
from strew.synth import as_selection, prepare, synthesize
from strew.synth._prepare import JAMMED_CORE, approach_bound, closest_approach


def _saturated_stones():
    # --harder stones h3s26 (radius 8, 300 asked for in the frame)
    return fidelity_suite().make_exemplar("stones", rng=26, radius=8.0, count=300)


def _lowest_decile(ex) -> float:
    xy = np.asarray(ex.xy, float)
    d = cKDTree(xy).query(xy, k=2)[0][:, 1]
    return float(np.quantile(d, 0.1) / d.min())


def test_saturated_stones_keep_095_of_their_closest_approach():
    ex = _saturated_stones()
    p = prepare(as_selection(ex))
    raw, second = closest_approach(p.pos, p.skind, p.source, second=True)
    ok = np.isfinite(raw)
    # the two closest pairs lie 2 % apart, so s37k's bound alone would keep 0.98 of x1 ...
    assert (approach_bound(raw[ok], second[ok]) > 0.975 * raw[ok]).all()
    # ... but only a few pairs touch the core: the lowest nn decile is 1.085 x1
    assert _lowest_decile(ex) > JAMMED_CORE
    assert np.allclose(p.min_dist[ok], 0.95 * raw[ok]), (p.min_dist, raw)


def test_jammed_stripes_pass_the_gate():
    ex = fidelity_suite().make_exemplar("stripes", rng=20)
    assert _lowest_decile(ex) <= JAMMED_CORE
    p = prepare(as_selection(ex))
    raw = closest_approach(p.pos, p.skind, p.source)
    ok = np.isfinite(raw)
    assert (p.min_dist[ok] > 0.98 * raw[ok]).all()


def test_saturated_stones_keep_their_nearest_distances():
    # with the bound (0.982 x1) nn[stone>stone] failed at seed 1 (0.0624 against 0.0592)
    ex = _saturated_stones()
    x0, y0, x1, y1 = ex.region.bounds
    out = synthesize(ex, Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=1, measure=False)
    m = fidelity(ex, out, eq5=False, local=False).metrics["nn[stone>stone]"]
    assert m.passed, (m.value, m.tolerance)
