"""The built-in exemplars draw their points with the library's one Poisson-disk sampler
(issue 15 point 5: ``strew.pack.poisson_disk``, not a dart thrower of their own)."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import cKDTree
from scipy.spatial.distance import cdist, pdist

import strew.pack
from strew.synth._exemplars import apples, stones


def test_exemplars_sample_with_the_shared_sampler(monkeypatch):
    calls = []
    shared = strew.pack.poisson_disk

    def spy(*args, **kwargs):
        calls.append(args[1])
        return shared(*args, **kwargs)

    monkeypatch.setattr(strew.pack, "poisson_disk", spy)
    stones()
    assert calls == [22.0]
    calls.clear()
    apples()
    assert calls[0] == 26.0 and len(calls) >= 2 and set(calls[1:]) == {12.0}


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_apples_keep_their_distances_and_fill_the_gaps_with_voids(seed):
    ex = apples(rng=seed)
    a, v = ex.select(~ex["void"]).xy, ex.select(ex["void"]).xy
    assert len(a) >= 20 and len(v) >= 50
    assert pdist(a).min() >= 26.0 and pdist(v).min() >= 12.0 and cdist(a, v).min() >= 14.0
    assert ex.xy.min() >= 0.0 and ex.xy.max() < 160.0
    # the voids fill the space between apples: where another void would still fit is
    # under 3% of the square (the dart thrower left 0.2-0.5%; one pass alone 4-8%)
    g = np.mgrid[0:160:0.5, 0:160:0.5].reshape(2, -1).T
    free = (cKDTree(a).query(g)[0] >= 14.0) & (cKDTree(v).query(g)[0] >= 12.0)
    assert free.mean() < 0.03
    again = apples(rng=seed)
    assert np.array_equal(again.xy, ex.xy) and np.array_equal(again["void"], ex["void"])


def test_stones_and_pebbles_are_poisson_disk_sets():
    for ex, d in ((stones(1.0), 22.0), (stones(0.25, size=60), 5.5)):
        assert len(ex) > 15 and pdist(ex.xy).min() >= d
        # maximal: no point of the square is farther than 2 d from every stone
        g = np.mgrid[0:120:1.0, 0:120:1.0].reshape(2, -1).T if d == 22.0 else np.mgrid[0:60:0.5, 0:60:0.5].reshape(2, -1).T
        assert cKDTree(ex.xy).query(g)[0].max() < 2 * d
