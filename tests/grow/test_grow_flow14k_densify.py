"""Flow mode: the stretched band's missing elements put in, the network fitted around
each (issue 14 point 2; :mod:`strew.grow._flow_densify`): the option leaves the other
modes alone, and the defect groups' measure. Its effect on the bent lattice is tested in
``test_grow_flow_bent_lattice`` (one growth for the three passes).
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree

from strew import Region

from test_grow_flow14d_stretch import assert_flow_option_leaves_mode_alone, hex_ref  # noqa: F401 (a fixture)
from test_grow_flow_gaps import SP  # noqa: E402


def _defect_groups(xy: np.ndarray, region: Region) -> tuple[float, int]:
    """Of the interior sites failing the six-neighbour test, grouped by links within
    1.15 spacings: the share in groups of at most two and the largest group's size
    (``isolated_defect_share`` and ``largest_defect_group`` of benchmarks/grow.py)."""
    tree = cKDTree(xy)
    inner = np.flatnonzero(region.distance_to_boundary(xy) > 2 * SP)
    hi = np.asarray(tree.query_ball_point(xy[inner], 1.15 * SP, return_length=True)) - 1
    lo = np.asarray(tree.query_ball_point(xy[inner], 0.85 * SP, return_length=True)) - 1
    bad = xy[inner[~((hi == 6) & (lo == 0))]]
    if len(bad) == 0:
        return 1.0, 0
    t = cKDTree(bad)
    lab = connected_components(t.sparse_distance_matrix(t, 1.15 * SP), directed=False)[1]
    size = np.bincount(lab)
    return float((size[lab] <= 2).mean()), int(size.max())


@pytest.mark.parametrize("mode", ["fixed", "rotate"])
def test_flow_densify_leaves_the_other_modes_alone(hex_ref, mode):
    assert_flow_option_leaves_mode_alone(hex_ref, mode, "flow_densify_rounds")
