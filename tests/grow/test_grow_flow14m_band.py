"""Flow mode: the last pass of the bond network, each bond pulled only into the band
0.9-1.12 mean edges near the sites without six neighbours (issue 14 point 2;
:func:`strew.grow._flow_net.relax_network` with ``band``).

The hexagonal lattice grown from the corner (2, 18) spacings of a region 30 x 20
spacings along a field turning 90 degrees (``benchmarks/grow.py --structure
--flow-only``, "flow turning 90 deg, 30x20 spacings, start 2,18 spacings") kept at
61d61c7 0.764 of its interior elements with six neighbours at the spacing (+-15%),
every failing site stretched (fewer than six within 1.15 spacings), the largest group
of failing sites 54. With the band's pass: 0.828, the largest group 19; the same
elements (the pass only moves them), no hole, nothing across the edge, no overlap.
"""

from __future__ import annotations

import numpy as np
import pytest

from strew import Region
from strew.grow._flow_net import _delaunay_bonds
from strew.grow._growth import GrowParams, grow_reference

from test_grow_flow14d_stretch import hex_ref  # noqa: E402, F401 (a fixture)
from test_grow_flow14g_retry import _turning_90  # noqa: E402
from test_grow_flow14k_densify import _defect_groups  # noqa: E402
from test_grow_flow_gaps import SP, _holes, _inside_without_overlap, _shares  # noqa: E402


@pytest.mark.slow
def test_flow_band_pass_lifts_the_stretched_sites_of_the_bent_lattice(hex_ref):
    w = 30 * SP
    region = Region.rectangle(w, 20 * SP)
    kw = dict(region=region, mode="flow", flow=_turning_90(w), start=(2 * SP, 18 * SP))
    out = grow_reference(hex_ref, GrowParams(**kw), rng=1)
    _inside_without_overlap(out, region)
    assert _holes(out.xy, region) == 0
    six, stretched = _shares(out.xy, region)
    _, largest = _defect_groups(out.xy, region)
    assert six >= 0.80  # 0.828 here; 0.764 at 61d61c7
    assert stretched <= 0.20  # 0.17; 0.24 at 61d61c7
    assert largest <= 35  # 19; 54 at 61d61c7
    # the pass moves elements only, within the 10 degree turn from the field (hexagons:
    # modulo 60 degrees) that the passes before keep: none turned past 12 degrees more
    # than the 2 that the passes before leave here
    v = kw["flow"](out.xy)
    d = np.degrees(np.mod(out.rotation - np.arctan2(v[:, 1], v[:, 0]), np.pi / 3))
    assert int((np.minimum(d, 60 - d) > 12.0).sum()) <= 2


def test_delaunay_bonds_are_the_triangles_sides_once_in_order():
    # (the neighbour lists give the same bonds, in the same order, as the simplices'
    # sides made unique: the network's fit and so its output are unchanged)
    from scipy.spatial import Delaunay

    rng = np.random.default_rng(3)
    g = np.mgrid[0:20, 0:14].reshape(2, -1).T.astype(float)
    g[:, 0] += 0.5 * (g[:, 1] % 2)
    g[:, 1] *= np.sqrt(3) / 2
    pts = g + rng.normal(0.0, 0.08, g.shape)
    s = Delaunay(pts).simplices.astype(np.int64)
    e = np.sort(np.r_[s[:, [0, 1]], s[:, [1, 2]], s[:, [0, 2]]], axis=1)
    k = np.unique(e[:, 0] * len(pts) + e[:, 1])
    e = np.c_[k // len(pts), k % len(pts)]
    e = e[np.hypot(*(pts[e[:, 1]] - pts[e[:, 0]]).T) < 1.4]
    assert np.array_equal(_delaunay_bonds(pts, 1.4), e)


def without_band_pass(monkeypatch) -> None:
    """Grow without the band's last pass (the passes before it as they were at 61d61c7,
    byte for byte): for the tests that weigh an earlier pass against its absence (the
    band's pass lifts both outputs, and more where an earlier pass was off: on the 90
    degree field from the centre, 0.904 with the shear retry, 0.921 without)."""
    from strew.grow import _growth

    orig = _growth.relax_network
    monkeypatch.setattr(_growth, "relax_network", lambda g, band=None: 0 if band is not None else orig(g))
