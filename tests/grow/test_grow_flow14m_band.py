"""Flow mode: the last pass of the bond network, each bond pulled only into the band
0.9-1.12 mean edges near the sites without six neighbours (issue 14 point 2;
:func:`strew.grow._flow_net.relax_network` with ``band``): its bonds, and a way to grow
without it. Its effect on the bent lattice is tested in ``test_grow_flow_bent_lattice``
(one growth for the three passes).
"""

from __future__ import annotations

import numpy as np

from strew.grow._flow_net import _delaunay_bonds


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
