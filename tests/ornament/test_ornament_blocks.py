"""The block bookkeeping of ornament's largest-empty-circle engine (issue 19.6).

Blocks are rescanned only where a change reaches (a dirty list, flagged from the waves'
changed cells, the skip discs and the exclude list), and the largest block from a
tournament tree. These tests check the result is what a full rescan gives, and that the
wave is the FIFO brushfire it always was.
"""

from __future__ import annotations

from collections import deque

import numpy as np
import pytest

from strew import Region
from strew._progress import Reporter
from strew.ornament import load_pattern
from strew.ornament._engine import _Grower
from strew.ornament._raster import BLOCK, lower_wave, scan_blocks, tree_build


def _full_rescan(g: _Grower) -> tuple[np.ndarray, np.ndarray, np.ndarray, int]:
    """Every block scanned afresh, on copies: (best_val, best_idx, bmax, root block)."""
    br, bc = g.dirty.shape
    dirty = np.ones((br, bc), bool)
    dlist = np.arange(br * bc, dtype=np.int64)
    dcount = np.array([br * bc], np.int64)
    bv, bi, bm, tree = g.best_val.copy(), g.best_idx.copy(), g.bmax.copy(), g.tree.copy()
    k = scan_blocks(g.dist_all, g.dist_el, g.covered, g.skip, dirty, dlist, dcount, bv, bi, bm, tree, g.adj_tol, g.ex, g.n_ex, g.x0, g.y0, g.h)
    return bv, bi, bm, int(k)


@pytest.mark.parametrize(
    "name, region, periodic",
    [
        ("dots", Region.rectangle(60, 45), None),
        ("flowers", Region.rectangle(70, 70), None),  # failures: exclude points come and go
        ("dots", Region.rectangle(50, 40), (0.0, 0.0, 50.0, 40.0)),  # torus: images, capped waves
    ],
)
def test_blocks_kept_equal_a_full_rescan(monkeypatch, name, region, periodic):
    checks = []
    try_ = _Grower._try

    def checked(self, goal, cand, shift=None):
        # _try runs right after a scan found this circle: no block may be pending, and
        # every block must hold what scanning it afresh gives
        if len(checks) % 3 == 0:
            assert self.dcount[0] == 0 and not self.dirty.any()
            bv, bi, bm, k = _full_rescan(self)
            np.testing.assert_array_equal(self.best_val, bv)
            np.testing.assert_array_equal(self.best_idx, bi)
            np.testing.assert_array_equal(self.bmax, bm)
            assert self.tree[1] == k == int(np.argmax(self.best_val))
        checks.append(self.n_ex)
        return try_(self, goal, cand, shift)

    monkeypatch.setattr(_Grower, "_try", checked)
    pat = load_pattern(name)
    seeds = np.array([[region.bounds[2] / 2, region.bounds[3] / 2]])
    g = _Grower(pat, region, seeds, np.random.default_rng(3), None, pat.min_radius, None, None, 400, Reporter(), periodic=periodic)
    g.run()
    assert len(checks) > 30
    if name == "flowers":
        assert g.stats["failures"] > 0 and max(checks) > 0  # the exclude list was exercised


def _brushfire(dist, near, sources, cap, cap_tol, use_cap):
    """The FIFO brushfire of lower_wave, in plain Python (the reference)."""
    rows, cols = dist.shape
    q = deque()
    inq = set()
    for s in sources:
        i, j = divmod(int(s), cols)
        if dist[i, j] > 0.0:
            dist[i, j] = 0.0
            near[i, j] = s
            if s not in inq:
                inq.add(s)
                q.append(s)
    while q:
        p = q.popleft()
        inq.discard(p)
        pi, pj = divmod(p, cols)
        qi, qj = divmod(int(near[pi, pj]), cols)
        for di in (-1, 0, 1):
            for dj in (-1, 0, 1):
                ni, nj = pi + di, pj + dj
                if not (0 <= ni < rows and 0 <= nj < cols):
                    continue
                d = float(np.sqrt(float((ni - qi) ** 2 + (nj - qj) ** 2)))
                if d < dist[ni, nj] - 1e-9:
                    if use_cap and d > cap[ni, nj] + cap_tol:
                        continue
                    dist[ni, nj] = d
                    near[ni, nj] = near[pi, pj]
                    c = ni * cols + nj
                    if c not in inq:
                        inq.add(c)
                        q.append(c)


def test_lower_wave_is_the_brushfire_and_flags_every_reached_block():
    rng = np.random.default_rng(5)
    rows, cols = 45, 70
    br, bc = -(-rows // BLOCK), -(-cols // BLOCK)
    fields = {"all": [np.full((rows, cols), np.inf), np.full((rows, cols), -1, np.int64)]}
    fields["el"] = [np.full((rows, cols), np.inf), np.full((rows, cols), -1, np.int64)]
    ref = {k: [a.copy() for a in v] for k, v in fields.items()}
    skip = np.zeros((rows, cols), bool)
    ring = np.empty(rows * cols, np.int64)
    inq = np.zeros(rows * cols, bool)
    for step in range(25):
        # a small blob of obstacle cells somewhere
        ci, cj = rng.integers(rows), rng.integers(cols)
        ii, jj = np.mgrid[max(0, ci - 2) : ci + 3, max(0, cj - 2) : cj + 3]
        keep = (ii < rows) & (jj < cols) & (rng.random(ii.shape) < 0.7)
        src = np.unique((ii[keep] * cols + jj[keep]).astype(np.int64))
        for key, nbr, use_cap in (("all", True, False), ("el", False, True)):
            dist, near = fields[key]
            before = dist.copy()
            dirty = np.zeros((br, bc), bool)
            dlist = np.empty(br * bc, np.int64)
            dcount = np.zeros(1, np.int64)
            cap = fields["all"][0]
            lower_wave(dist, near, skip, src, dirty, dlist, dcount, nbr, cap, 3.0, use_cap, ring, inq)
            _brushfire(ref[key][0], ref[key][1], src, ref["all"][0], 3.0, use_cap)
            np.testing.assert_array_equal(dist, ref[key][0])
            np.testing.assert_array_equal(near, ref[key][1])
            assert not inq.any()
            # the list holds the flagged blocks, once each
            listed = dlist[: dcount[0]]
            assert len(set(listed.tolist())) == len(listed)
            assert set(listed.tolist()) == set(np.flatnonzero(dirty).tolist())
            # every changed cell's block is flagged, and for dist_all its neighbours' too
            changed = np.argwhere(dist != before)
            for i, j in changed:
                r = 1 if nbr else 0
                for a in range(max(0, i - r), min(rows, i + r + 1)):
                    for b in range(max(0, j - r), min(cols, j + r + 1)):
                        assert dirty[a // BLOCK, b // BLOCK]


def test_tree_root_is_numpy_argmax_with_ties():
    rng = np.random.default_rng(0)
    for shape in [(1, 1), (3, 5), (7, 9), (16, 16)]:
        vals = rng.integers(-1, 4, size=shape).astype(float)  # many ties
        tree = np.empty(2 << max(0, int(vals.size - 1).bit_length()), np.int64)
        tree_build(tree, vals)
        assert tree[1] == int(np.argmax(vals))
