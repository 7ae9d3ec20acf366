"""Tiled synth's hand-over of dropped large elements (issue 19 point 4, helper holes19e).

A finished tile hands over the discs of the large elements it dropped near its
rectangle (``meta["synth_holes"]``); the later tile puts a copy of each one's kind at
its centre before it grows (``strew.synth._context.add_holes``), where it collides with
nothing and lies in its region.
"""

from __future__ import annotations

import numpy as np
import shapely

import strew
from strew.synth import synthesize
from strew.synth._api import new_state
from strew.synth._context import add_context

from strew_testing import fidelity_suite


def _setup():
    ex = fidelity_suite().make_exemplar("two_sizes")
    arr = synthesize(ex, strew.Region.rectangle(240.0, 240.0), rng=1, measure=False)
    left = np.asarray(arr.x) < 100.0
    kinds = np.asarray(arr.kinds, dtype=object)[np.asarray(arr.kind, np.int64)]
    r = np.array([float(arr.shapes[k].radius) for k in arr.kinds])[np.asarray(arr.kind, np.int64)]
    # stones of the same run just right of the context's cut: they fit beside it
    right = (np.asarray(arr.x) > 140.0) & (np.asarray(arr.x) < 200.0) & (kinds == "stone")
    holes = [[float(arr.x[i]), float(arr.y[i]), float(r[i]), "stone"] for i in np.flatnonzero(right)]
    return ex, arr, left, holes


def test_holes_get_a_copy_of_their_kind_at_their_centre_unless_it_collides_or_is_outside():
    ex, arr, left, holes = _setup()
    assert len(holes) >= 3
    i = int(np.flatnonzero(left & (np.asarray(arr.x) > 60.0))[0])  # on a context element
    collide = [float(arr.x[i]) + 1.0, float(arr.y[i]), 10.0, "stone"]
    outside = [230.0, 120.0, 10.0, "stone"]  # past the region's right edge
    unknown = [170.0, 230.0, 10.0, "no such kind"]
    context = arr.select(left).with_meta(synth_holes=[*holes, collide, outside, unknown])
    state = new_state(ex, strew.Region(shapely.box(100.0, 0.0, 220.0, 240.0)), rng=1)
    add_context(state, context)
    mine = ~state.fixed
    names = list(state.prep.shapes)
    got = state.pos[mine]
    assert len(got) == len(holes)
    np.testing.assert_allclose(got, np.array([h[:2] for h in holes]))
    assert all(names[k] == "stone" for k in state.prep.kind[state.src[mine]])
    assert state.horizon[mine].all()  # they seed the growth like any horizon element (§5.1)
    # nothing placed collides with the context or with another copy
    for j in np.flatnonzero(mine):
        others = np.ones(state.n, bool)
        others[j] = False
        d = np.hypot(*(state.pos[others] - state.pos[j]).T)
        assert (d >= state.prep.rc[state.src[others]] + state.prep.rc[state.src[j]] - 1e-9).all()


def test_no_holes_no_change():
    ex, arr, left, _ = _setup()
    region = strew.Region(shapely.box(100.0, 0.0, 220.0, 240.0))
    out = []
    for meta in ({}, {"synth_holes": []}):
        state = new_state(ex, region, rng=1)
        add_context(state, arr.select(left).with_meta(**meta))
        out.append((state.n, int((~state.fixed).sum())))
    assert out[0] == out[1] == (out[0][0], 0)
