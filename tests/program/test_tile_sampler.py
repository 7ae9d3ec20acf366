"""The tiled world's Poisson-disk sites (issue 19.1) come from pack's one compiled sampler
(issue 15 point 5): ``strew.pack.poisson_disk(..., context=...)``, called field cell by
field cell with the lower-phase neighbours' sites as context (Wei 2008's phases).

The union of the cells' sets must be one Poisson-disk set of the plane: no two sites
closer than the radius, near maximal everywhere (along the cells' borders too, where a
sampler that did not grow from the context would leave a seam of gaps), and the same
whatever order the cells are drawn in (so whatever the tiles and workers).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial import cKDTree
from scipy.spatial.distance import pdist

from strew._errors import InputError
from strew.pack import poisson_disk
from strew.program import _world
from strew.program._sampling import DISK_PACKING

NAME = "uniform_partition"


def _field(density: float, key: int, i0: int, j0: int, n: int) -> tuple[np.ndarray, float, float]:
    """The field's sites over n x n cells from cell (i0, j0), drawn afresh; (sites, r, cell side)."""
    _world._CACHE.clear()
    c = _world.FIELD_CELL / math.sqrt(density)
    bounds = (i0 * c, j0 * c, (i0 + n) * c, (j0 + n) * c)
    pts = _world.field_sites(NAME, density, key, bounds)
    _world._CACHE.clear()
    return pts, math.sqrt(DISK_PACKING / density), c


def _gaps(pts: np.ndarray, r: float, probes: np.ndarray) -> tuple[float, float]:
    """(fraction of probes farther than r from every site: room for one more, the largest
    such distance in units of r)."""
    d, _ = cKDTree(pts).query(probes)
    return float((d > r).mean()), float(d.max() / r)


@pytest.mark.slow
@settings(max_examples=12, deadline=None)
@given(
    density=st.floats(1e-3, 1e2),
    key=st.integers(0, 2**31 - 1),
    i0=st.integers(-1000, 1000),
    j0=st.integers(-1000, 1000),
)
def test_field_union_is_a_maximal_poisson_disk_set(density: float, key: int, i0: int, j0: int) -> None:
    n = 4
    pts, r, c = _field(density, key, i0, j0, n)
    x0, y0 = i0 * c, j0 * c
    # no two sites closer than r, across the cells' borders too (1e-9: the sampler works
    # in cell coordinates, these are world coordinates)
    assert pdist(pts).min() >= r * (1 - 1e-9)
    # near maximal away from the window's edges (cells outside it are not drawn) ...
    rng = np.random.default_rng(key)
    lo, hi = np.array([x0, y0]) + 2 * r, np.array([x0, y0]) + n * c - 2 * r
    free, worst = _gaps(pts, r, rng.uniform(lo, hi, size=(40_000, 2)))
    assert free < 0.01, free  # Bridson leaves ~0.1% of the area with room for one more
    assert worst < 1.5, worst
    # ... and in strips of width r along the inner cell borders, where a tile meets its
    # finished neighbours
    lines = x0 + c * np.arange(1, n)
    t = rng.uniform(lo[1], hi[1], size=20_000)
    off = rng.uniform(-r, r, size=20_000)
    k = rng.integers(len(lines), size=20_000)
    vert = np.c_[lines[k] + off, t]
    horiz = np.c_[t - y0 + x0, (y0 + c * np.arange(1, n))[k] + off]
    free_b, worst_b = _gaps(pts, r, np.r_[vert, horiz])
    assert free_b < 0.01, free_b
    assert worst_b < 1.5, worst_b
    # the density of a Bridson set (points per r^2, DISK_PACKING = 0.62 measured)
    inner = np.all((pts >= lo) & (pts < hi), axis=1).sum()
    assert 0.55 < inner * r * r / np.prod(hi - lo) < 0.69


def test_field_cells_do_not_depend_on_drawing_order() -> None:
    density, key = 0.37, 11
    c = _world.FIELD_CELL / math.sqrt(density)
    _world._CACHE.clear()
    whole = _world.field_sites(NAME, density, key, (0.0, 0.0, 4 * c, 4 * c))
    _world._CACHE.clear()
    # the far corner first: its lower-phase neighbours are drawn on demand
    _world.field_sites(NAME, density, key, (3 * c, 3 * c, 4 * c, 4 * c))
    again = _world.field_sites(NAME, density, key, (0.0, 0.0, 4 * c, 4 * c))
    _world._CACHE.clear()
    assert len(whole) > 500
    assert whole.tobytes() == again.tobytes()


def test_poisson_disk_context_joins_a_neighbour() -> None:
    r = 0.05
    left = poisson_disk((1.0, 1.0), r, rng=3)
    right = poisson_disk((1.0, 0.0, 2.0, 1.0), r, rng=4, context=left)
    assert right[:, 0].min() >= 1.0 and right[:, 0].max() < 2.0
    assert right[:, 1].min() >= 0.0 and right[:, 1].max() < 1.0
    both = np.r_[left, right]
    assert pdist(both).min() >= r * (1 - 1e-9)
    # the new set reaches the shared border: no seam of gaps along x = 1
    rng = np.random.default_rng(0)
    probes = np.c_[rng.uniform(1 - r, 1 + r, 5000), rng.uniform(2 * r, 1 - 2 * r, 5000)]
    free, worst = _gaps(both, r, probes)
    assert free < 0.01 and worst < 1.5
    # same inputs, same bytes
    again = poisson_disk((1.0, 0.0, 2.0, 1.0), r, rng=4, context=left)
    assert right.tobytes() == again.tobytes()


def test_poisson_disk_context_inside_the_region_and_far_away() -> None:
    r = 0.1
    ctx = np.array([[0.5, 0.5], [0.2, 0.8], [50.0, 50.0]])
    pts = poisson_disk((1.0, 1.0), r, rng=0, context=ctx)
    assert cKDTree(ctx).query(pts)[0].min() >= r
    assert pdist(pts).min() >= r
    # a context that covers the region leaves nothing to add
    full = poisson_disk((1.0, 1.0), r, rng=1)
    assert len(poisson_disk((1.0, 1.0), r, rng=2, context=full)) == 0


def test_poisson_disk_context_refusals() -> None:
    with pytest.raises(InputError, match="context"):
        poisson_disk((1.0, 1.0), 0.1, rng=0, context=np.array([[0.5, 0.5], [0.51, 0.5]]))
    with pytest.raises(InputError, match="context"):
        poisson_disk((1.0, 1.0), 0.1, rng=0, context=np.array([[0.5, np.nan]]))
    with pytest.raises(InputError, match="context"):
        poisson_disk((1.0, 1.0), 0.1, rng=0, periodic=True, context=np.zeros((1, 2)))
    with pytest.raises(InputError, match="context"):
        poisson_disk((1.0, 1.0), lambda p: np.full(len(p), 0.1), rng=0, context=np.zeros((1, 2)))
    with pytest.raises(InputError, match="region"):
        poisson_disk((1.0, 1.0, 0.5, 2.0), 0.1, rng=0)
