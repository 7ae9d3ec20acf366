"""Issue 14 point 1 on wide bands of two kinds of different sizes (helper growvar14).

Wide near-vertical bands of small dots and of long bars: with the default priority of
§5.1 (larger kinds first) the bars grew first and their rings ran into the dots' bands,
which the 1-ring cannot see: the dots' share fell to 0.23-0.31 against 0.45-0.48. Kinds
that lie apart in bands get no default priority (``default_priority``); kinds that mix
(pebbles among stones) keep larger-first.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from strew import Region
from strew.grow import analyze, grow, size_priority
from strew.metrics import fidelity

from strew_testing import fidelity_suite

make_exemplar = fidelity_suite().make_exemplar

# the audit's edge set "wide near-vertical bands, long bars" (benchmarks/_variants.py EDGE)
WIDE = dict(band=45.0, angle=1.4, dot=2.5, bar=(12.0, 2.5))


def test_banded_kinds_get_no_default_priority_mixed_kinds_keep_it():
    from strew.grow._analysis import default_priority

    for v in (7, 12):
        ex = make_exemplar("stripes", rng=v, **WIDE)
        assert size_priority(ex)  # the bars are of a larger size than the dots
        assert default_priority(analyze(ex)) == {}
    for name, kw in (("two_sizes", dict(ratio=0.35, n_large=120, n_small=35)), ("three_sizes", dict(counts=(60, 60, 26)))):
        ex = make_exemplar(name, rng=7, **kw)
        assert default_priority(analyze(ex)) == size_priority(ex) != {}, (name, kw)


@pytest.mark.slow
def test_wide_bands_keep_their_kind_shares():
    ex = make_exemplar("stripes", rng=12, **WIDE)  # a variant the audit does not draw
    x0, y0, x1, y1 = ex.region.bounds
    scale = 3.5
    for _ in range(2):
        region = Region.rectangle(scale * (x1 - x0), scale * (y1 - y0))
        out = grow(ex, region=region, rng=1)
        if len(out) >= 10 * len(ex):
            break
        scale *= 1.05 * math.sqrt(10 * len(ex) / max(len(out), 1))
    assert np.all(region.contains_geometry(out.geometry, tolerance=1e-9))
    rep = fidelity(ex, out, eq5=False, local=False)
    for key in ("fraction[dot]", "density[dot]", "nn[bar>dot]"):
        assert rep.metrics[key].passed, (key, rep.failures)
    assert rep.faithful, rep.failures
