"""Flow mode on a field that turns 90 degrees across the region (issue 14 point 2).

A guard of what holds today, not the issue's target: the target (90% of interior
elements with six neighbours, lattice within about 12/18 degrees of the field) is not
met; today 0.835 of them keep six neighbours, the rest sit in strained blocks. Nothing
crosses the region's edge, no hole opens, each element's frame stays within the 10
degree turn allowed at its seed, and the lattice's bond directions follow the field
(median 11.8, 90th percentile 17.8 degrees off).
"""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree

from strew import Region
from strew.grow import grow

from strew_testing import fidelity_suite

SP = 12.0  # the hexagonal exemplar's spacing


def _field(w: float):
    def field(p):
        a = np.radians(90.0) * np.clip(np.asarray(p)[:, 0] / w, 0, 1)
        return np.c_[np.cos(a), np.sin(a)]

    return field


def _bond_misalignment(ex, xy, idx, flow) -> np.ndarray:
    """Degrees between each element's six-fold bond direction (circular mean over its
    neighbours within 1.15 spacing) and the exemplar's, less the field's angle there,
    wrapped to +-30 (benchmarks/grow.py --structure, field_misalignment)."""

    def phase(pts, which):
        t = cKDTree(pts)
        out = []
        for i in which:
            d = pts[[j for j in t.query_ball_point(pts[i], 1.15 * SP) if j != i]] - pts[i]
            out.append(np.exp(6j * np.arctan2(d[:, 1], d[:, 0])).sum())
        return np.angle(np.asarray(out)) / 6

    e_in = np.flatnonzero(ex.region.distance_to_boundary(ex.xy) > 1.5 * SP)
    phi0 = np.angle(np.exp(6j * phase(ex.xy, e_in)).sum()) / 6
    v = np.asarray(flow(xy[idx]), dtype=float)
    d = phase(xy, idx) - phi0 - np.arctan2(v[:, 1], v[:, 0])
    return np.abs(np.degrees((d + np.pi / 6) % (np.pi / 3) - np.pi / 6))


def test_flow_turning_ninety_degrees_keeps_inside_without_holes_and_follows_the_field():
    ex = fidelity_suite().make_exemplar("hex_lattice", nx=8, ny=8)
    w, h = 30 * SP, 20 * SP
    region = Region.rectangle(w, h)
    field = _field(w)
    out = grow(ex, region=region, mode="flow", flow=field, rng=1)
    assert np.all(region.contains_geometry(out.geometry, tolerance=1e-9))
    xy = out.xy
    tree = cKDTree(xy)
    # no hole: every interior point lies within 0.75 spacing of a centre (a perfect
    # lattice: 0.58)
    g = np.mgrid[2 * SP : w - 2 * SP : 3.0, 2 * SP : h - 2 * SP : 3.0].reshape(2, -1).T
    assert tree.query(g)[0].max() < 0.75 * SP
    inner = np.flatnonzero(region.distance_to_boundary(xy) > 2 * SP)
    hi = np.array([len(tree.query_ball_point(xy[i], 1.15 * SP)) - 1 for i in inner])
    lo = np.array([len(tree.query_ball_point(xy[i], 0.85 * SP)) - 1 for i in inner])
    assert ((hi == 6) & (lo == 0)).mean() >= 0.8
    # each element's frame: within the 10 degree turn allowed at its seed (hexagons:
    # modulo 60 degrees; relaxation moves, it does not turn)
    v = field(xy)
    d = np.degrees(np.mod(out.rotation - np.arctan2(v[:, 1], v[:, 0]), np.pi / 3))
    assert np.minimum(d, 60 - d).max() <= 12.0
    # the lattice itself (its bond directions) lags the field by at most about 18 degrees
    m = _bond_misalignment(ex, xy, inner, field)
    assert np.median(m) <= 12.5 and np.quantile(m, 0.9) <= 18.5, (np.median(m), np.quantile(m, 0.9))
