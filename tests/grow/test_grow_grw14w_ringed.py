"""Issue 14 point 1 on untuned exemplars (helper grw14w): three sizes 400:15:15
(``--harder`` three_sizes h12, exemplar drawn with seed 7).

The exemplar rings every large stone with small ones, snug at its least gap (the gaps
between a large stone's bounding disc and its nearest small one's: min/q10/q30/q50
1.20/1.22/1.25/1.45). The large stones grew from the small stones' rings into a field of
small ones the outline test let come to any gap (output 0.00/0.10/0.41/0.88), and the
audit's rows (3.5x) failed nn[large>small] (0.082-0.106 against 0.058-0.074). Such a kind
now keeps 0.9 of the reference's least disc gap from the smaller kind, both ways
(``DISC_RINGED`` in ``grow/_growth.py``).
"""

from __future__ import annotations

import numpy as np
from strew_testing import disc_gaps, fidelity_suite

from strew import Region
from strew.grow import grow


def test_large_stones_keep_their_ring_gap():
    ex = fidelity_suite().make_exemplar("three_sizes", rng=7, counts=(400, 15, 15))
    radius = {k: float(ex.shapes[k].radius) for k in ex.kinds}
    least = float(disc_gaps(ex, radius, "large", "small").min())
    x0, y0, x1, y1 = ex.region.bounds
    out = grow(ex, region=Region.rectangle(1.5 * (x1 - x0), 1.5 * (y1 - y0)), rng=1)
    gaps = disc_gaps(out, radius, "large", "small")
    assert len(gaps) >= 20
    # lowest decile of the large stones' gaps to their nearest small one (1.5x, seed 1),
    # against 0.8 of the exemplar's least gap (1.20): d6d394e 0.087, fails; now 1.214
    assert float(np.quantile(gaps, 0.1)) >= 0.8 * least
