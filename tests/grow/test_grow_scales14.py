"""Issue 14 point 1/3 on untuned 'scales' variants (helper scales14).

Two causes of drifting rows, both in the analysis (§4), not in matching or relaxation:

- a staggered lattice whose two cell diagonals are about as long gave both diagonal
  directions the same support in ``regularize_triangles``; the first found won. With the
  longer diagonal in the rings, growth compressed the shorter, unconnected pair and the
  regularity fell by 0.10-0.17 (tolerance 0.05). The shorter direction is now taken.
- at the edge of a small noisy hexagonal lattice, elements missing one outer neighbour
  kept a fan closed by a near-skewed triangle and counted as interior; their rings sheared
  the rows (regularity 0.097). Rings with a gap far wider than the exemplar's are left out.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from strew import Region
from strew.grow import analyze, grow
from strew.metrics import fidelity

from strew_testing import fidelity_suite

make_exemplar = fidelity_suite().make_exemplar

# benchmarks/_variants.py EDGE sets of 'scales': p2 (cells near squares) and p3 (6 rows of 6)
SQUARE_CELLS = dict(width=16.0, length=7.0, gap=2.5, noise=0.06)
SMALL = dict(rows=6, per_row=6)


def _grow(ex, seed, scale=3.5):
    x0, y0, x1, y1 = ex.region.bounds
    return grow(ex, region=Region.rectangle(scale * (x1 - x0), scale * (y1 - y0)), mode="fixed", rng=seed)


def _diagonal_lengths(ref):
    """Lengths of the edges that are not along the +-45/135 degree rows of scales: the
    cell diagonals the regularization chose."""
    xy = ref.xy
    d = xy[ref.edges[:, 1]] - xy[ref.edges[:, 0]]
    ang = np.degrees(np.mod(np.arctan2(d[:, 1], d[:, 0]), np.pi))
    axis = np.minimum(np.minimum(ang, 180 - ang), np.abs(ang - 90)) < 20
    return np.hypot(*d[axis].T), np.where(np.minimum(ang[axis], 180 - ang[axis]) < 20, 0, 90)


def test_tied_lattice_directions_keep_the_shorter_diagonal():
    for v in (7, 8):
        ex = make_exemplar("scales", rng=v, **SQUARE_CELLS)
        lengths, dirs = _diagonal_lengths(analyze(ex, lattice_repairs=True))
        # mostly one direction (a few boundary cells keep theirs), the shorter of the two
        main = 0 if (dirs == 0).sum() > (dirs == 90).sum() else 90
        assert (dirs == main).mean() > 0.8, v
        lengths = lengths[dirs == main]
        other = 90 - main
        xy = ex.xy
        # the other direction's pairs: nearest elements along it
        u = np.array([math.cos(math.radians(other)), math.sin(math.radians(other))])
        rel = xy[None, :, :] - xy[:, None, :]
        along = rel @ u
        across = np.abs(rel @ np.array([-u[1], u[0]]))
        cand = np.where((along > 1.0) & (across < 0.25 * along), np.hypot(rel[..., 0], rel[..., 1]), np.inf).min(axis=1)
        assert np.median(lengths) < np.median(cand[np.isfinite(cand)]), v


def test_gapped_edge_rings_are_not_references():
    # off by default (flow mode, the clusters' hubs): the edge rings are there
    ex = make_exemplar("scales", rng=8, **SMALL)
    assert analyze(ex).interior.sum() > analyze(ex, lattice_repairs=True).interior.sum()
    for v in (7, 8):
        ex = make_exemplar("scales", rng=v, **SMALL)
        ref = analyze(ex, lattice_repairs=True)
        xy = ref.xy
        widest = []
        for i in ref.reference_ids:
            d = xy[ref.rings[i]] - xy[i]
            a = np.sort(np.arctan2(d[:, 1], d[:, 0]))
            widest.append(np.diff(np.r_[a, a[0] + 2 * np.pi]).max())
        # a hexagonal lattice: every reference ring's gaps are near 60 degrees
        assert np.degrees(max(widest)) < 90, v


@pytest.mark.slow
@pytest.mark.parametrize(("kw", "seed"), [(SQUARE_CELLS, 1), (SQUARE_CELLS, 2), (SMALL, 2)])
def test_scales_variants_keep_their_regularity(kw, seed):
    ex = make_exemplar("scales", rng=8, **kw)
    out = _grow(ex, seed)
    assert len(out) >= 10 * len(ex)
    rep = fidelity(ex, out, eq5=False, local=False)
    m = rep.metrics["regularity"]
    assert m.applicable and m.passed, (m.value, m.tolerance)
    assert rep.faithful, [k for k, r in rep.metrics.items() if r.applicable and not r.passed]
