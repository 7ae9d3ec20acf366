"""Issue 14 point 5: the relaxation's normal equations assembled in a compiled loop
(:mod:`strew.grow._relax_kernels`) are the numpy assembly's, to the last bit, so that
the growth's outputs stay byte-identical."""

from __future__ import annotations

import numpy as np

from strew.grow._relax import DENSE_MAX, relax_positions


def _numpy_system(pos, src, dst, off, free, reg, w):
    """The dense normal equations as relax_positions assembled them with numpy (8224b5f)."""
    nf = int(free.sum())
    col = np.full(len(pos), -1, dtype=np.intp)
    col[free] = np.arange(nf)
    fd, fs = free[dst], free[src]
    cd, cs = col[dst], col[src]
    both = fd & fs
    rows = np.concatenate([cd[fd], cs[fs], cd[both], cs[both], np.arange(nf)])
    cols = np.concatenate([cd[fd], cs[fs], cs[both], cd[both], np.arange(nf)])
    b = reg * pos[free]
    d_only, s_only = fd & ~fs, fs & ~fd
    if w is None:
        vals = np.concatenate([np.ones(int(fd.sum()) + int(fs.sum())), -np.ones(2 * int(both.sum())), np.full(nf, reg)])
        np.add.at(b, cd[fd], off[fd])
        np.add.at(b, cd[d_only], pos[src[d_only]])
        np.add.at(b, cs[fs], -off[fs])
        np.add.at(b, cs[s_only], pos[dst[s_only]])
    else:
        vals = np.concatenate([w[fd], w[fs], -w[both], -w[both], np.full(nf, reg)])
        wc = w[:, None]
        np.add.at(b, cd[fd], (wc * off)[fd])
        np.add.at(b, cd[d_only], (wc * pos[src])[d_only])
        np.add.at(b, cs[fs], -(wc * off)[fs])
        np.add.at(b, cs[s_only], (wc * pos[dst])[s_only])
    return rows, cols, vals, b


def test_dense_normal_equations_are_the_numpy_assembly_bit_for_bit():
    import scipy.sparse as sp
    from scipy.sparse.linalg import spsolve

    from strew.grow._relax_kernels import dense_normal_equations, sparse_normal_equations

    rng = np.random.default_rng(14)
    dense = sparse = 0
    for t in range(100):
        n = int(rng.integers(2, 3 * DENSE_MAX))
        m = int(rng.integers(1, 6 * n))
        pos = rng.normal(size=(n, 2)) * 30.0
        src, dst = rng.integers(0, n, m), rng.integers(0, n, m)  # (repeats and self-terms too)
        off = rng.normal(size=(m, 2))
        free = rng.random(n) < rng.uniform(0.2, 1.0)
        nf = int(free.sum())
        if not nf:
            continue
        w = rng.uniform(0.1, 5.0, m) if t % 2 else None
        rows, cols, vals, b0 = _numpy_system(pos, src, dst, off, free, 1e-9, w)
        args = (pos, src, dst, off, np.ones(m) if w is None else w, free, 1e-9)
        want = pos.copy()
        if nf <= DENSE_MAX:
            dense += 1
            N0 = np.bincount(rows * nf + cols, weights=vals, minlength=nf * nf).reshape(nf, nf)
            N1, b1 = dense_normal_equations(*args)
            assert N1.tobytes() == N0.tobytes() and b1.tobytes() == b0.tobytes()
            want[free] = np.linalg.solve(N0, b0)
        else:
            sparse += 1
            r1, c1, v1, b1 = sparse_normal_equations(*args)
            assert (r1 == rows).all() and (c1 == cols).all() and v1.tobytes() == vals.tobytes() and b1.tobytes() == b0.tobytes()
            want[free] = spsolve(sp.csc_matrix((vals, (rows, cols)), shape=(nf, nf)), b0)
        # and the minimiser: the same solve of the same system
        assert relax_positions(pos, src, dst, off, free, weights=w).tobytes() == want.tobytes()
    assert dense > 20 and sparse > 20


def test_boundary_distance_is_geos_distance_bit_for_bit():
    import shapely

    from strew import Region
    from strew.grow._flow_kernels import boundary_distance

    rng = np.random.default_rng(5)
    holed = shapely.Point(100, 100).buffer(80, 32).difference(shapely.Point(110, 90).buffer(20, 8))
    regions = [Region.rectangle(30 * 12.3, 20 * 12.3), Region(holed)]
    for rg in regions:
        x0, y0, x1, y1 = rg.bounds
        L = 12.3
        pts = np.r_[rng.uniform([x0 - 9, y0 - 9], [x1 + 9, y1 + 9], size=(20000, 2)),
                    # (a quarter-edge grid two edges in: points exactly at the passes' thresholds)
                    np.mgrid[x0 + 2 * L : x1 - 2 * L : 0.25 * L, y0 + 2 * L : y1 - 2 * L : 0.25 * L].reshape(2, -1).T]
        want = rg.distance_to_boundary(pts)
        assert boundary_distance(rg, pts).tobytes() == want.tobytes()
        assert boundary_distance(rg, pts[:0]).shape == (0,)
