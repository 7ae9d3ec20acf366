"""Issue 13 point 1 (helper s65c, after s64c's diagnosis, benchmarks/results/s64c_notes.md):
growth puts no more dots on an output disc's ring than the exemplar's disc it copies holds
(``_grow._ring_full``, ``_prepare.ring_caps``). Before, neighbouring copies laid dots of
other exemplar rings onto a ring already there: ``synth_variants.py --varied`` clusters
p4s38 (big discs, tight rings of 7-9 grit dots) held rings of 10-13 dots and failed
nn[dot>dot] on seeds 1-6."""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree
from strew_testing import fidelity_suite

from strew import Region
from strew.metrics import fidelity
from strew.synth import new_state, synthesize

suite = fidelity_suite()

# benchmarks/_variants.py EDGE["clusters"][2] (label p4 of --varied), variant seed 38
P4 = {"large": 12.0, "small": 2.0, "ring_gap": 0.5, "ring_min": 7, "ring_max": 9, "cluster_spacing": 70.0}


def _rings(arr, radius=None):
    """(discs,) int dots whose nearest disc lies within 1.25 ring radii, and the ring
    radius (the median distance of a dot to its nearest disc unless given)."""
    k = np.asarray(arr.kind_names)
    disc, dot = arr.xy[k == "disc"], arr.xy[k == "dot"]
    d, j = cKDTree(disc).query(dot)
    radius = float(np.median(d)) if radius is None else radius
    return np.bincount(j[d <= 1.25 * radius], minlength=len(disc)), radius


def test_ring_caps_are_the_exemplars_rings():
    """The dots are capped (one distance to their disc), each at 1.5 times that
    distance; a disc's cap is its own ring where the frame leaves the ring whole and
    the exemplar's largest ring where the frame cuts it; exemplars of loose pebbles
    (two and three sizes, a few of whose small stones touch a boulder) have nothing
    capped."""
    from strew.synth._prepare import ring_caps

    ex = suite.make_exemplar("clusters", rng=38, **P4)
    prep = new_state(ex, Region.rectangle(100, 100), rng=1).prep
    capped, reach, cap = ring_caps(prep)
    disc_k = prep.kind[np.flatnonzero(prep.size_class == prep.size_class.max())[0]]
    dot_k = prep.kind[np.flatnonzero(prep.size_class == prep.size_class.min())[0]]
    disc, dot = prep.kind == disc_k, prep.kind == dot_k
    assert capped[prep.parent >= 0].all() and not capped[disc].any()
    assert capped[dot].sum() >= 0.9 * dot.sum()  # the dots of rings the frame crops have no parent
    d = np.hypot(*(prep.pos[capped] - prep.pos[prep.parent[capped]]).T)
    assert np.allclose(reach[capped], 1.5 * d) and np.all(reach[~capped] == 0)
    # rings counted geometrically on the exemplar (not through Prepared.parent)
    counts, radius = _rings(ex)
    assert counts.max() == 9
    x0, y0, x1, y1 = ex.region.bounds
    p = prep.pos[disc]
    edge = np.minimum.reduce([p[:, 0] - x0, x1 - p[:, 0], p[:, 1] - y0, y1 - p[:, 1]])
    whole = edge > 1.25 * radius + 2.0 * float(prep.rc[dot].max())
    cut = edge < radius
    assert whole.sum() >= 5 and cut.sum() >= 2
    dd, jj = cKDTree(p).query(prep.pos[dot])
    own = np.bincount(jj[dd <= 1.25 * radius], minlength=len(p))
    assert np.array_equal(cap[np.flatnonzero(disc)[whole], dot_k], own[whole])
    assert np.all(cap[np.flatnonzero(disc)[cut], dot_k] == counts.max())
    # three sizes p0s30 (VARIED[0], variant seed 30): 9 small stones touching boulders
    # keep one distance (cv 0.042), but they are 9 of 140 small stones: not a ring
    for cls, kw, v in (("two_sizes", {}, 1), ("three_sizes", {}, 1), ("three_sizes", {"ratios": (1.0, 2.5, 5.0), "counts": (140, 50, 18)}, 30)):
        other = new_state(suite.make_exemplar(cls, rng=v, **kw), Region.rectangle(100, 100), rng=1).prep
        assert not ring_caps(other)[0].any()


def test_p4s38_rings_hold_no_more_dots_than_the_exemplars_largest():
    """3 times the frame's side, seed 1 (s1 of the audit's row, at 3.5x, fails on
    main with nn[dot>dot] 0.126 against 0.067): at most 10 % of the output's discs hold
    more dots on their ring than the generator's largest ring (``ring_max`` 9, the
    exemplar's largest too), at most 4 % more than one over it, and nn[dot>dot] passes.
    The slack: copies placed in the same growing step do not see one another
    (``_grow._ring_full``). Pinned, 3x, synth seeds 1-12 (helper s67c,
    benchmarks/results/s67c_rings_out_*_3x.txt): the cap leaves 5.0-10.2 % of rings over 9
    and 0-1.8 % (0-2 of 110-123) over 10; main 22-47 % and 6.6-27 % (seeds 1-4). s65c's
    bound on the largest ring (<= 12) is not asserted: the cap's largest ring is 10-12
    over those seeds, main's 12-13, so it had no margin and hardly tells the trees apart."""
    ex = suite.make_exemplar("clusters", rng=38, **P4)
    x0, y0, x1, y1 = ex.region.bounds
    out = synthesize(ex, Region.rectangle(3.0 * (x1 - x0), 3.0 * (y1 - y0)), rng=1, measure=False)
    largest, radius = _rings(ex)
    assert largest.max() == P4["ring_max"]
    counts, _ = _rings(out, radius)
    assert (counts > P4["ring_max"]).mean() <= 0.10
    assert (counts > P4["ring_max"] + 1).mean() <= 0.04
    rep = fidelity(ex, out, eq5=False, local=False)
    assert rep.metrics["nn[dot>dot]"].passed
