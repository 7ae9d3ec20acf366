"""SVG import in bulk (issue 17.3): the kind candidates found on a grid of all objects'
invariants at once are those of the one-by-one test, object by object."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from strew.io import _svg_import as imp


def _rows(rng: np.random.Generator, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Invariant rows of ``n`` objects in a few families of near-copies (so that many pairs
    lie near the tests' thresholds), some lines, some without a signature."""
    fam = rng.integers(0, max(1, n // 4), n)
    base = rng.uniform(0, 1.5, (n + 1, imp._KMAX - 1))[fam]
    mags = base * rng.uniform(0.97, 1.03, base.shape) + rng.uniform(-0.012, 0.012, base.shape)
    mags = np.abs(mags)
    size = rng.uniform(1, 10, n)
    scale = rng.uniform(0.5, 2, n)
    radius = size**0.5 * rng.uniform(0.98, 1.02, n) * scale
    gyration = 0.5 * size**0.5 * rng.uniform(0.98, 1.02, n) * scale
    tol = rng.uniform(1e-4, 1e-2, n)
    area = np.where(rng.random(n) < 0.8, 1.0, -1.0)
    rows = np.c_[size * scale**2, radius, gyration, tol, area, mags]
    valid = rng.random(n) < 0.95
    rows[~valid] = imp._invariants(None)
    return rows, valid


class _Sig:
    """The parts of a signature :func:`_candidates` reads."""

    def __init__(self, row: np.ndarray) -> None:
        self.size, self.radius, self.gyration, self.tolerance = (float(v) for v in row[:4])
        self.is_area = bool(row[4] == 1.0)


@settings(max_examples=40, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), n=st.integers(0, 120))
def test_candidate_pairs_are_the_one_by_one_candidates(seed, n):
    rows, valid = _rows(np.random.default_rng(seed), n)
    found = imp._candidate_pairs(rows, valid)
    assert found is not None
    start, earlier = found
    assert len(start) == n + 1 and start[0] == 0 and start[-1] == len(earlier)
    for j in range(n):
        got = earlier[start[j] : start[j + 1]].tolist()
        if not valid[j]:
            assert got == []
            continue
        kinds = [i for i in range(j) if valid[i]]  # the earlier objects, as kinds
        sig = _Sig(rows[j])
        want = [kinds[k] for k in imp._candidates(rows[kinds].reshape(len(kinds), rows.shape[1]), sig, rows[j].tolist())]
        assert got == want, j


def test_candidate_pairs_leave_non_finite_invariants_to_the_one_by_one_test():
    rows, valid = _rows(np.random.default_rng(1), 10)
    valid[:] = True
    rows[3, 7] = np.inf
    assert imp._candidate_pairs(rows, valid) is None
