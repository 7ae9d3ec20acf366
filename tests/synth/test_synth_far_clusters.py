"""Issue 13 point 1: clusters far apart in a small frame. The large class's r-bar
(LARGE_RING times its spacing, the §4.1 extension of ``_palette.element_parameters``)
is capped at the depth of its deepest member, so that a disc has a whole (interior)
neighbourhood to copy disc-to-disc steps from; without the cap no disc was interior
and synthesis stopped after the first cluster (8 elements)."""

from __future__ import annotations

import numpy as np
import pytest
import shapely

from strew import Region
from strew.metrics import fidelity
from strew.synth import new_state, synthesize
from strew.synth._palette import LARGE_RING, average_spacing, element_parameters
from strew.synth._prepare import size_classes

from strew_testing import fidelity_suite

suite = fidelity_suite()

# the audit's edge sets (benchmarks/_variants.py EDGE["clusters"][0] and [2])
FAR = dict(cluster_spacing=90.0, ring_gap=3.0, ring_min=6, ring_max=7)
GRIT = dict(large=12.0, small=2.0, ring_gap=0.5, ring_min=7, ring_max=9, cluster_spacing=70.0)


def _discs(ex):
    r, rbar = element_parameters(ex)
    big = size_classes(r) == size_classes(r).max()
    return r, rbar, big


@pytest.mark.parametrize("params, seed", [(FAR, 7), (FAR, 8), (GRIT, 8)])
def test_large_class_has_an_interior_member(params, seed):
    """Some disc's neighbourhood lies wholly in the exemplar's domain, and it still
    reaches past the disc's own ring to the next disc (r-bar plus the pairing margin
    2 r_max at least the discs' nearest-disc distance)."""
    ex = suite.make_exemplar("clusters", rng=seed, **params)
    r, rbar, big = _discs(ex)
    prep = new_state(ex, Region.rectangle(100, 100), rng=1).prep
    inner = np.concatenate(prep.interior)
    assert big[inner].any()
    d = shapely.distance(prep.domains[0].exterior, shapely.points(ex.xy))
    assert np.all(rbar[big] <= d[big].max() + 1e-9)
    nearest = min(np.hypot(*(ex.xy[big] - ex.xy[j]).T)[np.flatnonzero(big) != j].min() for j in np.flatnonzero(big))
    assert rbar[big].max() + 2 * r.max() >= nearest


def test_disc_steps_surround_the_interior_discs():
    """FAR at seed 8: the one disc with a whole neighbourhood shows its three disc
    steps within a cone; the next deepest discs join the candidates until the steps
    leave no quarter of directions empty, and no shallower disc joins."""
    from strew.synth._prepare import SURROUND_DEPTH, SURROUND_GAP

    ex = suite.make_exemplar("clusters", rng=8, **FAR)
    prep = new_state(ex, Region.rectangle(100, 100), rng=1).prep
    big = np.flatnonzero(prep.size_class == prep.size_class.max())
    inner = big[np.isin(big, np.concatenate(prep.interior))]
    d = shapely.distance(prep.domains[0].exterior, shapely.points(prep.pos))
    assert len(inner) > 1 and np.all(d[inner] >= SURROUND_DEPTH * prep.rbar[inner])
    steps = np.concatenate([prep.nb_off[prep.nb_ptr[e] : prep.nb_ptr[e + 1]][prep.size_class[prep.nb_idx[prep.nb_ptr[e] : prep.nb_ptr[e + 1]]] == 1] for e in inner])
    ang = np.sort(np.arctan2(steps[:, 1], steps[:, 0]))
    assert np.diff(np.r_[ang, ang[0] + 2 * np.pi]).max() < SURROUND_GAP


def test_default_clusters_keep_the_uncapped_radius():
    """The suite's clusters exemplar (discs deep enough inside): r-bar stays LARGE_RING
    times the discs' spacing."""
    ex = suite.make_exemplar("clusters", rng=1)
    _, rbar, big = _discs(ex)
    assert np.allclose(rbar[big], LARGE_RING * average_spacing(ex.xy[big]))


@pytest.mark.parametrize("params, seed", [(FAR, 7), (FAR, 8), (GRIT, 8)])
def test_far_apart_clusters_fill_the_region(params, seed):
    """Twice the frame's side: the output holds the exemplar's density of elements
    (within 15 %) and is faithful; before the cap it held one cluster (8 elements).
    FAR at seed 8 needs the surrounding steps as well (_prepare._surround_steps):
    with its one interior disc it grew a one-sided lattice over part of the region."""
    ex = suite.make_exemplar("clusters", rng=seed, **params)
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0))
    out = synthesize(ex, region, rng=1, measure=False)
    ratio = (len(out) / region.area) / (len(ex) / ex.region.area)
    assert 0.85 <= ratio <= 1.15, (len(out), ratio)
    rep = fidelity(ex, out, region, eq5=False)
    assert rep.faithful, rep.failures
