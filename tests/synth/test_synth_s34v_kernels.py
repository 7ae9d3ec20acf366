"""The numba kernels that replaced array code on synth's hot path (helper s34v) give what
the code they replaced defines: DBSCAN's labels (``_kernels.dbscan_labels`` against the
pairs' definition, the k-d tree's answer where a border point lies between clusters) and
the optimisation's own-jitter prediction vectors (``_kernels.own_jitter``)."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

from strew.synth import _kernels as K
from strew.synth._prepare import _dbscan_kdtree, dbscan


def _reference(points, eps, min_samples):
    """DBSCAN from all pairs: labels (border points of one cluster) and whether some
    border point touches cores of two clusters."""
    n = len(points)
    d2 = ((points[:, None, :] - points[None, :, :]) ** 2).sum(-1)
    near = (d2 <= eps * eps) & ~np.eye(n, dtype=bool)
    core = near.sum(1) + 1 >= min_samples
    cc = near & core[:, None] & core[None, :]
    i, j = np.nonzero(cc)
    _, comp = connected_components(coo_matrix((np.ones(len(i)), (i, j)), shape=(n, n)), directed=False)
    labels = np.full(n, -1, np.int64)
    ids = np.flatnonzero(core)
    _, labels[ids] = np.unique(comp[ids], return_inverse=True)
    ambiguous = False
    for b in np.flatnonzero(~core):
        got = np.unique(labels[near[b] & core])
        if len(got):
            labels[b] = got[0]
            ambiguous |= len(got) > 1
    return labels, ambiguous


@pytest.mark.parametrize("seed", range(6))
def test_dbscan_labels_follow_the_pairs(seed):
    rng = np.random.default_rng(seed)
    for _ in range(20):
        n = int(rng.integers(1, 120))
        pts = rng.random((n, 2)) * rng.uniform(1.0, 12.0)
        if rng.random() < 0.5:  # duplicates and distances of exactly eps
            pts = np.round(pts * 2.0) / 2.0
        pts[:, 0] += 1000.0 * rng.integers(0, 3, n)  # far groups, as prepare spreads them
        eps = float(rng.choice([0.5, 1.0, 1.5]))
        ms = int(rng.integers(1, 6))
        want, amb = _reference(pts, eps, ms)
        got, got_amb = K.dbscan_labels(pts, eps, ms)
        assert got_amb == amb
        if not amb:
            np.testing.assert_array_equal(got, want)
        np.testing.assert_array_equal(dbscan(pts, eps, ms), _dbscan_kdtree(pts, eps, ms))


def test_dbscan_border_between_two_clusters_keeps_the_kd_tree_answer():
    left = [(0.0, 0.0), (-0.1, 0.0), (-0.2, 0.0), (-0.3, 0.0)]
    right = [(2.0, 0.0), (2.1, 0.0), (2.2, 0.0), (2.3, 0.0)]
    pts = np.array(left + [(1.0, 0.0)] + right)
    _labels, ambiguous = K.dbscan_labels(pts, 1.0, 4)
    assert ambiguous
    got = dbscan(pts, 1.0, 4)
    np.testing.assert_array_equal(got, _dbscan_kdtree(pts, 1.0, 4))
    assert list(got[:4]) == [0] * 4 and list(got[5:]) == [1] * 4 and got[4] in (0, 1)


def _own_jitter_arrays(h, center, hp, off, src, source, nb_ptr, nb_idx, nb_off, jit, pos, bound, spacing, seam_offset):
    """The array code ``_optimize._own_jitter`` ran before the kernel (main at bae7e74)."""
    owner = np.repeat(np.arange(len(nb_ptr) - 1), np.diff(nb_ptr))
    e2 = np.full(len(center), -1, np.int64)
    for t in range(len(center)):
        rows = np.flatnonzero((owner == center[t]) & np.all(nb_off == off[t], axis=1))
        if len(rows):
            e2[t] = nb_idx[rows[0]]
    ok = (e2 >= 0) & (source[src[hp]] == source[center]) & (source[src[h]] == source[center])
    out = off.copy()
    a, b = src[h[ok]], src[hp[ok]]
    own = jit[b] - jit[a]
    seam = np.hypot(*((pos[b] - pos[a]) - off[ok]).T) > seam_offset * spacing[a]
    if seam.any():
        cap = bound[a[seam]]
        m = np.hypot(own[seam, 0], own[seam, 1])
        own[seam] *= (np.minimum(m, cap) / np.maximum(m, 1e-300))[:, None]
    out[ok] += own - (jit[e2[ok]] - jit[center[ok]])
    return out


@pytest.mark.parametrize("seed", range(3))
def test_own_jitter_kernel_matches_the_array_code(seed):
    rng = np.random.default_rng(seed)
    ne, no, c = 30, 40, 400
    pos = rng.random((ne, 2)) * 10.0
    source = rng.integers(0, 2, ne).astype(np.int64)
    lens = rng.integers(0, 6, ne)
    nb_ptr = np.r_[0, np.cumsum(lens)].astype(np.int64)
    nb_idx = rng.integers(0, ne, nb_ptr[-1]).astype(np.int64)
    nb_off = pos[nb_idx] - pos[np.repeat(np.arange(ne), lens)]
    jit = rng.normal(0.0, 0.3, (ne, 2))
    bound = rng.uniform(0.05, 0.5, ne)
    spacing = rng.uniform(0.5, 2.0, ne)
    src = rng.integers(0, ne, no).astype(np.int64)
    h = rng.integers(0, no, c).astype(np.int64)
    hp = rng.integers(0, no, c).astype(np.int64)
    center = rng.integers(0, ne, c).astype(np.int64)
    off = rng.normal(0.0, 3.0, (c, 2))
    has = np.flatnonzero(lens[center] > 0)
    pick = has[rng.random(len(has)) < 0.8]  # most pairs are a copy of one of n(center)'s offsets
    row = nb_ptr[center[pick]] + rng.integers(0, 6, len(pick)) % lens[center[pick]]
    off[pick] = nb_off[row]
    args = (h, center, hp, off, src, source, nb_ptr, nb_idx, nb_off, jit, pos, bound, spacing, 0.5)
    got = K.own_jitter(*args)
    want = _own_jitter_arrays(*args)
    assert np.array_equal(got, want)
    assert not np.array_equal(got, off)  # the test reaches the trade of jitters


def test_rectangle_contains_by_comparisons_is_geos_answer():
    """``Region.contains`` of an axis-aligned rectangle compares coordinates (synth's
    ``in_domain`` asks it every iteration): the same answer as GEOS's, boundary
    excluded, for points on, just inside and just outside every edge."""
    import shapely

    from strew import Region

    rng = np.random.default_rng(3)
    for _ in range(20):
        w, h = rng.uniform(0.1, 500.0, 2)
        x0, y0 = rng.uniform(-100.0, 100.0, 2)
        r = Region.rectangle(w, h, x0, y0)
        assert r._axis_box is not None
        b = r.bounds
        xs = np.r_[rng.uniform(b[0] - 1, b[2] + 1, 40), [b[0], b[2], (b[0] + b[2]) / 2]]
        ys = np.r_[rng.uniform(b[1] - 1, b[3] + 1, 40), [b[1], b[3], (b[1] + b[3]) / 2]]
        xs = np.r_[xs, np.nextafter(b[0], [-np.inf, np.inf]), np.nextafter(b[2], [-np.inf, np.inf])]
        ys = np.r_[ys, np.nextafter(b[1], [-np.inf, np.inf]), np.nextafter(b[3], [-np.inf, np.inf])]
        X, Y = np.meshgrid(xs, ys)
        pts = np.c_[X.ravel(), Y.ravel()]
        np.testing.assert_array_equal(r.contains(pts), shapely.contains_xy(r.prepared, pts[:, 0], pts[:, 1]))
    tilted = Region(shapely.Polygon([(0, 0), (4, 1), (3, 5), (-1, 4)]))
    assert tilted._axis_box is None
    assert tilted.contains([[1.5, 2.5], [4, 4]]).tolist() == [True, False]
