"""Rotation mode keeps the bricks' courses in step (issue 14 point 1).

The bricks' centres are nearly cocircular in fours, so the reference's Delaunay rings
(§4) mix horizontal and vertical edges. A ring without the horizontal edges has wide
gaps, and Fig. 6 (c)'s angle check refused a diagonal slot beside a horizontal
neighbour that the ring did not pair; the Fig. 6 (e) extra seed then filled the gap off
the lattice and a seam of courses out of step grew from it (seed 4 on the fidelity
suite's region: Eq. 5 179 against a tolerance of 45.9).
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import cKDTree

from strew import Region
from strew.grow import grow
from strew.metrics import fidelity

from strew_testing import fidelity_suite


def _courses_out_of_step(out, region, course: float) -> tuple[int, int]:
    """Interior bricks without a brick of the other colour one course length away on
    both sides along their own axis (the exemplar has one everywhere), and the count
    of interior bricks."""
    xy = out.xy
    tree = cKDTree(xy)
    inner = np.flatnonzero(region.distance_to_boundary(xy) > 1.5 * course)
    bad = 0
    for i in inner:
        axis = np.array([np.cos(out.rotation[i]), np.sin(out.rotation[i])])
        for side in (1.0, -1.0):
            d, j = tree.query(xy[i] + side * course * axis)
            if d > 0.2 * course or out.kind[j] == out.kind[i]:
                bad += 1
                break
    return bad, len(inner)


@pytest.mark.slow
def test_rotate_bricks_seed_4_has_no_seam():
    ex = fidelity_suite().make_exemplar("bricks")
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0))
    out = grow(ex, region=region, mode="rotate", rng=4)
    assert np.all(region.contains_geometry(out.geometry, tolerance=1e-9))
    # one course: the distance between a brick and the next in its course
    xy = ex.xy
    d, j = cKDTree(xy).query(xy, k=len(xy) if len(xy) < 9 else 9)
    course = float(np.median(np.abs((xy[j] - xy[:, None, :])[..., 0])[(np.abs((xy[j] - xy[:, None, :])[..., 1]) < 2) & (d > 1)]))
    bad, n = _courses_out_of_step(out, region, course)
    # the old code: 32 of 1298 interior bricks out of step along the seam; now 4 (the
    # region's corners)
    assert bad <= 0.01 * n, (bad, n)
    rep = fidelity(ex, out, region, local=False)
    assert rep.metrics["eq5"].passed, rep.metrics["eq5"]
