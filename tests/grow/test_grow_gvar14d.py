"""Issue 14 point 1 on untuned exemplars (helper gvar14d): hub-sized holes of clustered
exemplars, and holes of irregular exemplars of one size without voids.

- Clusters far apart (the audit's clusters p2s8: ``cluster_spacing=90``, full rings of
  6-7 dots): the hubs are drawn saturated (no gap a hub fits into at the exemplar's
  least hub distance), and their growth (``strew.grow._clusters``) left hub-sized holes
  (widest whole empty circles of the hubs 105-113 against the exemplar's 66.5 and least
  distance 93.6; empty_circle 0.16-0.28 against 0.14 at 550ea99). ``hub_hole`` and
  ``fill_void_holes`` put a hub at the centre of each.
- Long thin sticks (the audit's sticks p0s7): holes wider than any of the exemplar's
  (empty_circle 0.104-0.113 against 0.1 at 550ea99); ``GrowParams.open_holes`` runs the
  same pass as for voids.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import Delaunay, cKDTree
from strew_testing import fidelity_suite

from strew import Region
from strew._kernels.geometry import circumcircles
from strew.grow import grow
from strew.grow._clusters import hub_hole
from strew.metrics import fidelity, overlaps


def _region(ex, side):
    x0, y0, x1, y1 = ex.region.bounds
    return Region.rectangle(side * (x1 - x0), side * (y1 - y0))


def _whole_circles(p, region):
    """Circumradii of the points' Delaunay triangles whose circle lies inside ``region``."""
    tri = Delaunay(p)
    cen, r, _ = circumcircles(*(p[tri.simplices[:, q]] for q in range(3)))
    inner = region.contains(cen) & (region.distance_to_boundary(cen) >= r)
    return r[inner]


def _fails(rep):
    return [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]


@pytest.mark.slow
def test_far_apart_clusters_leave_no_hub_sized_hole():
    ex = fidelity_suite().make_exemplar("clusters", rng=8, cluster_spacing=90.0, ring_gap=3.0, ring_min=6, ring_max=7)
    hub = int(np.argmax([ex.shapes[k].radius for k in ex.kinds]))
    hx = ex.select(ex.kind == hub)
    lim = hub_hole(hx)
    least = float(cKDTree(hx.xy).query(hx.xy, k=2)[0][:, 1].min())
    # the threshold is the exemplar's: its widest whole hub circle (66.5) and least hub distance (93.6)
    assert lim == max(float(_whole_circles(hx.xy, ex.region).max()), least)
    region = _region(ex, 3.5)
    for seed in (1, 2):
        out = grow(ex, region=region, rng=seed)
        assert len(out) >= 10 * len(ex)
        r = _whole_circles(out.xy[out.kind == hub], region)
        # 550ea99: 10 and 5 circles wider than the threshold, 6 and 2 wider than 1.05 x it
        # (up to 1.12 x); now none
        assert int(np.sum(r > lim)) <= 1, np.sort(r)[-5:]
        rep = fidelity(ex, out, eq5=False, local=False)
        assert rep.faithful, _fails(rep)
        assert len(overlaps(out)[0]) == 0
        assert np.all(region.contains_geometry(out.geometry, tolerance=1e-9))
    again = grow(ex, region=region, rng=2)
    assert np.array_equal(again.xy, out.xy) and np.array_equal(again.kind, out.kind)


@pytest.mark.slow
def test_long_thin_sticks_leave_no_hole_wider_than_the_exemplar_has():
    # the audit's sticks p0s7: 53 sticks 36 x 2; at 550ea99 9 % of the whole empty
    # circles were wider than the exemplar's widest (19.5) and the q95 11 % wider
    # (empty_circle 0.113 and 0.104 against 0.1 on seeds 1 and 2)
    ex = fidelity_suite().make_exemplar("sticks", rng=7, length=36.0, width=2.0, count=80)
    widest = float(_whole_circles(ex.xy, ex.region).max())
    region = _region(ex, 3.5)
    out = grow(ex, region=region, rng=1)
    assert len(out) >= 10 * len(ex)
    r = _whole_circles(out.xy, region)
    # (9.3 % at 550ea99, 6.9 % now: the holes a stick fits into are filled)
    assert float(np.mean(r > widest)) <= 0.08
    rep = fidelity(ex, out, eq5=False, local=False)
    assert rep.faithful, _fails(rep)
    assert len(overlaps(out)[0]) == 0
    assert np.all(region.contains_geometry(out.geometry, tolerance=1e-9))
