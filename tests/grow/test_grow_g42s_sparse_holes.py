"""Issue 14 point 1: an unsaturated exemplar's wide holes come back (helper g42s).

Sparse small stones dart-thrown to a fixed count (``_variants.EDGE`` stones p2: radius
4, gap 4, 60 stones in 200 x 200) leave holes where nothing landed. The growth reaches
every place (a slot in the empty part of one ring is another ring's to fill), so even
keeping the reference's nearest distances (:mod:`strew.grow._spacing`, ``KEEP_SHARE``)
the result came out more even than the exemplar: its whole empty circles' q95 was
0.82-0.88 of the exemplar's on draws 23-30 (the generator's own: 0.95-1.05), and
p2s29/p2s30 failed empty_circle at seeds 1-6. After the growth, elements are taken out
(:func:`strew.grow._spacing.thin_to_holes`) until as large a share of the result's
whole circles is wider than the exemplar's upper decile as the exemplar's.
"""

from __future__ import annotations

import numpy as np
from strew_testing import fidelity_suite

from strew import Region
from strew.grow import grow
from strew.metrics import summary

make_exemplar = fidelity_suite().make_exemplar


def _circles(pts, region):
    # the whole empty circles, as the fidelity judge's empty_circle measures them
    from scipy.spatial import Delaunay

    tri = Delaunay(pts)
    a, b, c = (pts[tri.simplices[:, q]] for q in range(3))
    d = 2.0 * (a[:, 0] * (b[:, 1] - c[:, 1]) + b[:, 0] * (c[:, 1] - a[:, 1]) + c[:, 0] * (a[:, 1] - b[:, 1]))
    ok = np.abs(d) > 1e-12
    a, b, c, d = a[ok], b[ok], c[ok], d[ok]
    sa, sb, sc = (np.sum(v * v, axis=1) for v in (a, b, c))
    cen = np.c_[(sa * (b[:, 1] - c[:, 1]) + sb * (c[:, 1] - a[:, 1]) + sc * (a[:, 1] - b[:, 1])) / d,
                (sa * (c[:, 0] - b[:, 0]) + sb * (a[:, 0] - c[:, 0]) + sc * (b[:, 0] - a[:, 0])) / d]
    rr = np.hypot(cen[:, 0] - a[:, 0], cen[:, 1] - a[:, 1])
    inner = region.contains(cen) & (region.distance_to_boundary(cen) >= rr)
    return cen[inner], rr[inner]


def test_sparse_stones_keep_the_exemplars_wide_holes():
    ex = make_exemplar("stones", rng=28, radius=4.0, count=60, gap=4.0)
    _, rex = _circles(np.asarray(ex.xy, dtype=float), ex.region)
    lo = float(np.quantile(rex, 0.9))  # strew.grow._spacing.HOLE_QUANTILE
    for seed in (1, 2):
        out = grow(ex, region=Region.rectangle(400.0, 400.0), rng=seed)
        assert summary(out)["overlap_pairs"] == 0
        _, r = _circles(np.asarray(out.xy, dtype=float), out.region)
        # the exemplar's share by construction (0.1); without the pass 0.044 and 0.035
        assert float(np.mean(r > lo)) >= 0.09, float(np.mean(r > lo))
        # q95 of the whole circles: 0.850 and 0.854 of the exemplar's without the pass
        assert float(np.quantile(r, 0.95) / np.quantile(rex, 0.95)) >= 0.9
        # thinned, not emptied: still near the exemplar's density (1.05 here)
        ratio = (len(out) / 400.0**2) / (len(ex) / 200.0**2)
        assert 0.9 <= ratio <= 1.15, ratio


def test_sparse_stones_thinning_is_deterministic():
    ex = make_exemplar("stones", rng=28, radius=4.0, count=60, gap=4.0)
    a = grow(ex, region=Region.rectangle(400.0, 400.0), rng=3)
    b = grow(ex, region=Region.rectangle(400.0, 400.0), rng=3)
    assert len(a) == len(b) and np.array_equal(np.asarray(a.xy), np.asarray(b.xy))
