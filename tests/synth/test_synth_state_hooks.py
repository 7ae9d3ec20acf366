"""The public hooks of a synthesis state that front ends use (issue 15.6): elements,
element keys, birth iterations, the eraser's keep mask and the output's overlap rule."""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

from strew import InputError, Region
from strew.editing import overlap_drops
from strew.metrics import overlaps
from strew.synth import brush, erase, fill, new_state
from strew.synth._exemplars import grid


@pytest.fixture(scope="module")
def filled():
    s = new_state(grid(), Region.rectangle(160, 140), rng=5)
    fill(s)
    return s


def _fresh_filled():
    s = new_state(grid(), Region.rectangle(160, 140), rng=5)
    fill(s)
    return s


def test_elements_are_the_state_in_order(filled):
    s = filled
    arr = s.elements()
    assert len(arr) == s.n > 50
    assert np.array_equal(arr.xy, s.pos)
    assert arr.columns == {} and arr.region is None
    # same poses and kinds as the output, which leaves nothing out here (no voids, no clip)
    out = s.to_arrangement(clip=False, drop_overlaps=False, keep_voids=True)
    assert np.array_equal(out.xy, arr.xy)
    assert np.array_equal(out.kind_names, arr.kind_names)
    assert np.allclose(out.rotation, arr.rotation) and np.allclose(out.scale, arr.scale)
    idx = np.array([7, 3, 3, 0])
    part = s.elements(idx)
    assert np.array_equal(part.xy, s.pos[idx])
    assert np.array_equal(part.kind_names, arr.kind_names[idx])
    assert len(s.elements(np.zeros(0, int))) == 0


def test_elements_include_context_elements():
    s = new_state(grid(), Region.rectangle(100, 100), rng=1)
    s.add(np.array([0, 1]), np.array([[10.0, 10.0], [40.0, 40.0]]), horizon=False, fixed=True)
    arr = s.elements()
    assert len(arr) == 2 and np.array_equal(arr.xy, [[10.0, 10.0], [40.0, 40.0]])
    assert len(s.to_arrangement()) == 0  # the output leaves context out; elements() does not


def test_element_keys_are_distinct_and_survive_removal():
    s = _fresh_filled()
    keys = s.element_keys()
    assert keys.dtype == np.int64 and len(keys) == s.n
    assert len(np.unique(keys)) == s.n
    assert np.array_equal(s.element_keys(np.arange(s.n)[::-1]), keys[::-1])
    gone = np.zeros(s.n, bool)
    gone[::3] = True
    kept = keys[~gone]
    s.remove(gone)
    assert np.array_equal(s.element_keys(), kept)  # indices shift, keys do not
    # a re-assigned element gets a new key, distinct from every other
    before = s.element_keys()
    s.reassign(np.array([0]), s.src[[1]])
    after = s.element_keys()
    assert after[0] != before[0] and np.array_equal(after[1:], before[1:])
    assert len(np.unique(after)) == s.n


def test_born_counts_the_growth_iterations():
    s = new_state(grid(), Region.rectangle(300, 120), rng=3)
    pts = np.c_[np.linspace(20, 280, 40), np.full(40, 60.0)]
    brush(s, pts[:20], 15.0)
    n1, it1 = s.n, s.iterations
    assert n1 > 0 and it1 > 0
    assert s.born.shape == (n1,)
    assert np.all((s.born >= 0) & (s.born <= it1))
    brush(s, pts[20:], 15.0)
    assert s.n > n1
    # elements added by the second segment were born in its iterations, the others before
    new = s.born >= it1
    assert new.sum() > 0
    assert np.all(s.born <= s.iterations)
    assert np.all(s.pos[new, 0] > pts[18, 0] - 40)


def test_eraser_keep_mask_keeps_those_and_erases_the_rest():
    s = _fresh_filled()
    s.brush_points = np.array([[80.0, 70.0], [5.0, 5.0]])
    s.brush_radii = np.array([4.0, 4.0])
    path = np.array([[20.0, 70.0], [140.0, 70.0]])
    line = shapely.LineString(path)
    near = shapely.distance(line, shapely.points(s.pos)) <= 14.0
    keep = np.zeros(s.n, bool)
    keep[np.flatnonzero(near)[::2]] = True  # half the elements near the path are "locked"
    keys = s.element_keys()
    removed = erase(s, path, 14.0, keep=keep)
    assert removed == int((near & ~keep).sum()) > 0
    assert np.array_equal(s.element_keys(), keys[~(near & ~keep)])
    # the rim of the hole is back on the horizon (optimised next), the kept elements not
    held = np.isin(s.element_keys(), keys[keep])
    assert s.horizon[~held].any() and not s.horizon[held].any()
    # brush points are removed as without a mask (the studio's locked eraser skipped this)
    assert s.brush_points.tolist() == [[5.0, 5.0]]
    # free space around the hole lives again: a fill adds elements in it
    n = s.n
    assert fill(s, (80, 70)) > 0
    assert np.any(shapely.distance(line, shapely.points(s.pos[n:])) <= 14.0)


def test_eraser_keep_all_removes_nothing_and_bad_mask_is_named():
    s = _fresh_filled()
    n = s.n
    assert erase(s, np.array([[80.0, 70.0]]), 30.0, keep=np.ones(n, bool)) == 0
    assert s.n == n
    with pytest.raises(InputError, match="keep must be one flag per element"):
        erase(s, np.array([[80.0, 70.0]]), 30.0, keep=np.ones(n + 1, bool))
    # no mask and a mask of all False are the same eraser
    a, b = _fresh_filled(), _fresh_filled()
    path = np.array([[10.0, 10.0], [150.0, 130.0]])
    assert erase(a, path, 9.0) == erase(b, path, 9.0, keep=np.zeros(b.n, bool)) > 0
    assert np.array_equal(a.pos, b.pos)
    assert fill(a, (80, 70)) == fill(b, (80, 70))
    assert np.array_equal(a.pos, b.pos)


def _greedy_drops(pairs: np.ndarray, n: int) -> np.ndarray:
    """The rule to_arrangement applied before it used overlap_drops: pairs in order."""
    dropped = np.zeros(n, bool)
    for i, j in pairs:
        if not dropped[i]:
            dropped[j] = True
    return dropped


@settings(max_examples=60, deadline=None)
@given(st.integers(2, 12).flatmap(lambda n: st.tuples(st.just(n), st.sets(st.tuples(st.integers(0, n - 1), st.integers(0, n - 1)).filter(lambda p: p[0] < p[1]), max_size=20))))
def test_overlap_drops_is_the_output_rule_on_sorted_pairs(case):
    """On pairs sorted as strew.metrics.overlaps returns them, overlap_drops with every
    element new and nothing fixed is the rule to_arrangement used before."""
    n, pairs = case
    p = np.array(sorted(pairs), dtype=np.int64).reshape(-1, 2)
    assert np.array_equal(overlap_drops(p, 0, np.ones(n, bool)), _greedy_drops(p, n))


def test_output_leaves_no_overlaps_when_exemplar_shapes_do_not_overlap(filled):
    s = filled
    if not s.prep.overlap_free:
        pytest.skip("exemplar shapes overlap")
    raw = s.to_arrangement(drop_overlaps=False)
    out = s.to_arrangement()
    assert len(overlaps(out)[0]) == 0
    pairs, _ = overlaps(raw)
    assert len(out) == len(raw) - int(_greedy_drops(pairs, len(raw)).sum())
