"""strew.pack with several concave kinds (issue 21, points 1 and 2): the gap-fitting kind
choice places at least naive's count while keeping the requested proportions, the
largest-first scale choice covers more, and shapes large against the region finish with
bounded work."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

from strew import Region, load_shapes
from strew.metrics import coverage, outside, overlaps
from strew.pack import pack
from strew.pack._draw import _kind_order

SHAPES = Path(__file__).resolve().parents[2] / "examples" / "shapes"
L_SHAPE = Region(shapely.Polygon([(0, 0), (400, 0), (400, 200), (200, 200), (200, 400), (0, 400)]))


@pytest.fixture(scope="module")
def concave3():
    """The three concave kinds of examples/shapes (a star, a tree, an elongated blade)."""
    out = {}
    for name in ("concave", "tree", "elongated"):
        out.update(load_shapes(SHAPES / f"{name}.svg"))
    return out


def _valid(arr, region):
    assert len(overlaps(arr)[0]) == 0
    assert len(outside(arr, region, tolerance=1e-9)) == 0


def _shares(arr, kinds) -> np.ndarray:
    counts = arr.counts()
    return np.array([counts.get(k, 0) for k in kinds]) / len(arr)


# Two random processes compared over paired seeds, not one: their counts spread about
# +-8 elements from seed to seed, so a single seed's order is luck (seed 17 placed 208
# against naive's 214 on both Poisson-disk streams, seed 1 does since issue 15 point 5).
# The mean must lead by 5 elements, which the paper's cycle (194 on average, issue 21)
# misses by 13 and the current fill-gap (about 215 against 202 over seeds 1-20) meets.
SEEDS_VS_NAIVE = range(1, 9)


@pytest.mark.slow
def test_fill_gap_places_more_than_naive_on_average_in_the_l_shape(concave3):
    # issue 21: with the paper's cycle, fill-gap placed fewer than naive dart throwing here
    fg, nv = [], []
    for seed in SEEDS_VS_NAIVE:
        a = pack(concave3, L_SHAPE, scale=(0.25, 0.25), rng=seed)
        b = pack(concave3, L_SHAPE, scale=(0.25, 0.25), method="naive", rng=seed)
        _valid(a, L_SHAPE)
        assert a.meta["pack"]["trials"] < b.meta["pack"]["trials"] / 10
        fg.append(len(a))
        nv.append(len(b))
    assert np.mean(fg) >= np.mean(nv) + 5, (fg, nv)


@pytest.mark.parametrize("weights", [None, {"concave": 2.0, "tree": 1.0, "elongated": 1.0}])
def test_gap_fitting_kinds_keep_the_requested_proportions(concave3, weights):
    arr = pack(concave3, L_SHAPE, scale=(0.2, 0.2), weights=weights, rng=3)
    assert len(arr) > 150  # enough elements for shares to mean something
    w = np.ones(3) if weights is None else np.array([weights[k] for k in concave3])
    target = w / w.sum()
    shares = _shares(arr, list(concave3))
    assert np.all(np.abs(shares - target) <= 0.05 + 1e-12), shares
    # the paper's cycle would hold them equal; the fit lets the kinds that fit run ahead
    assert arr.meta["pack"]["kind_choice"] == "fit"


def test_gap_fitting_kinds_beat_the_cycle_on_a_concave_mix(concave3):
    fit = pack(concave3, L_SHAPE, scale=(0.25, 0.25), rng=4)
    cyc = pack(concave3, L_SHAPE, scale=(0.25, 0.25), kind_choice="cycle", rng=4)
    assert len(fit) > len(cyc)


def test_largest_first_scales_cover_more_and_stay_in_range(concave3):
    rnd = pack(concave3, L_SHAPE, scale=(0.12, 0.24), rng=5)
    big = pack(concave3, L_SHAPE, scale=(0.12, 0.24), scale_choice="fit", rng=5)
    _valid(big, L_SHAPE)
    assert np.all((big.scale >= 0.12) & (big.scale <= 0.24))
    assert coverage(big) > 1.1 * coverage(rnd)
    assert np.median(big.scale) > np.median(rnd.scale)


@pytest.mark.parametrize("scale", [1.0, 2.0])
def test_shapes_large_against_the_region_finish_with_bounded_work(concave3, scale):
    # issue 21 point 2: at scale 1 a handful of elements fit; the run must not spin
    import warnings

    from strew._feedback import ResultWarning

    with warnings.catch_warnings(record=True) as said:
        warnings.simplefilter("always", ResultWarning)
        arr = pack(concave3, L_SHAPE, scale=(scale, scale), rng=6)
        nv = pack(concave3, L_SHAPE, scale=(scale, scale), method="naive", rng=6)
    # a handful of large shapes: the run says why and suggests a scale (issue 22 point 3)
    large = [w for w in said if "large against the region" in str(w.message)]
    assert len(large) == (len(arr) < 10) + (len(nv) < 10)
    _valid(arr, L_SHAPE)
    info = arr.meta["pack"]
    assert info["stopped"] == "200 consecutive cancellations"
    # each trial tries at most 48 poses of each of the three kinds
    assert info["poses"] <= 3 * 48 * info["trials"]
    assert info["trials"] < 1000
    assert len(arr) >= len(nv)


@settings(max_examples=200, deadline=None)
@given(
    w=st.lists(st.floats(0.0, 1.0), min_size=1, max_size=5).filter(lambda w: sum(w) > 0.05),
    counts=st.lists(st.integers(0, 300), min_size=5, max_size=5),
    tol=st.floats(0.005, 0.2),
)
def test_kind_order_allows_a_kind_only_within_its_share_and_ranks_by_deficit(w, counts, tol):
    target = np.asarray(w) / sum(w)
    k = len(target)
    cnt = np.asarray(counts[:k], dtype=np.int64)
    n = int(cnt.sum())
    order = np.zeros(k, dtype=np.int64)
    m = _kind_order(target, tol, cnt, n, order)
    chosen = order[:m]
    assert len(set(chosen.tolist())) == m
    for j in chosen:
        assert target[j] > 0
        assert cnt[j] + 1 <= max(np.ceil(target[j] * (n + 1) - 1e-9), (target[j] + tol) * (n + 1))
    deficit = target[chosen] * (n + 1) - cnt[chosen]
    assert np.all(np.diff(deficit) <= 1e-12)
    # the kind furthest behind is always allowed, so a candidate always has a kind to try
    if np.all(cnt[target > 0] <= np.ceil(target[target > 0] * n)):
        assert m >= 1
