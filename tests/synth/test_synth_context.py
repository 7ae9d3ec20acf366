"""synth's ``context`` is neighbourhood, not only an obstacle (issues 13, 18, 19): a region
grown beside finished elements continues their texture without a seam."""

from __future__ import annotations

import numpy as np
import pytest

from strew import Region
from strew.arrangement import concat
from strew.metrics import fidelity, overlaps
from strew.synth import new_state, synthesize
from strew.synth._context import add_context

from strew_testing import fidelity_suite

suite = fidelity_suite()


def _strip_stats(arr, xa, xb, y0, y1):
    m = (arr.x >= xa) & (arr.x < xb) & (arr.y >= y0) & (arr.y < y1)
    frac = np.bincount(np.asarray(arr.kind)[m], minlength=len(arr.kinds)) / max(int(m.sum()), 1)
    return m.sum() / ((xb - xa) * (y1 - y0)), frac


@pytest.mark.slow
def test_region_grown_against_context_has_no_seam():
    """Stones with pebbles (two sizes): the left half of a finished output is the
    context, the whole rectangle the region (as a tile with its halo, strew.tiles). A
    strip half a frame wide across the seam has the density of the new half's interior
    (within 10 %) and its kind fractions (within 10 % of each, plus 0.02 for the strip's
    own noise: strips of one uninterrupted output differ by up to 0.03); the union is
    faithful, no local window fails, and no new element overlaps the context. With the
    context only an obstacle (the old behaviour), the density ratio was 1.11 and 3 of
    4 local windows failed (nn[stone>pebble])."""
    ex = suite.make_exemplar("two_sizes")
    x0, y0, x1, y1 = ex.region.bounds
    w, h = 3 * (x1 - x0), 3 * (y1 - y0)
    region = Region.rectangle(w, h)
    first = synthesize(ex, region, rng=1, measure=False)
    ctx = first.select(first.x < w / 2)
    new = synthesize(ex, region, rng=101, measure=False, context=ctx)
    both = concat([ctx, new])
    assert len(overlaps(both)[0]) == 0
    band = 0.5 * (x1 - x0)
    d_in, f_in = _strip_stats(new, w / 2 + band, w - band / 2, 0.1 * h, 0.9 * h)
    d_seam, f_seam = _strip_stats(both, w / 2 - band / 2, w / 2 + band / 2, 0.1 * h, 0.9 * h)
    assert abs(d_seam / d_in - 1) < 0.1
    assert np.all(np.abs(f_seam - f_in) <= 0.1 * f_in + 0.02)
    rep = fidelity(ex, both, region, eq5=False)
    assert rep.faithful, rep.failures
    score = np.asarray(rep.local["score"], float)
    assert np.all(score[np.isfinite(score)] <= 1.0)


def test_context_elements_are_neighbours_not_output():
    """Context elements of the selection's kinds join the state as fixed neighbours
    with an exemplar element of their own kind; optimisation does not move them, and
    the result holds only new elements, none overlapping the context."""
    ex = suite.make_exemplar("stones")
    x0, y0, x1, y1 = ex.region.bounds
    w, h = 1.5 * (x1 - x0), y1 - y0
    region = Region.rectangle(w, h)
    first = synthesize(ex, region, rng=3, measure=False)
    ctx = first.select(first.x < 0.75 * (x1 - x0))
    st = new_state(ex, region, rng=4)
    idx = add_context(st, ctx)
    assert len(idx) == len(ctx)
    assert np.all(st.fixed[idx])
    assert np.all(st.kind[idx] == ex.kinds.index("stone"))
    before = st.pos[idx].copy()
    from strew.synth._context import fill_with_context

    fill_with_context(st)
    assert np.array_equal(st.pos[idx], before)  # never moved
    out = st.to_arrangement()
    assert 0 < len(out) <= int((~st.fixed).sum())
    gap = np.hypot(*(out.xy[:, None, :] - ctx.xy[None, :, :]).transpose(2, 0, 1)).min()
    assert gap > 0  # no context element comes back as output
    new = synthesize(ex, region, rng=4, measure=False, context=ctx)
    assert len(overlaps(concat([ctx, new]))[0]) == 0
    # the new elements fill the rest: the right part has the left part's density
    inner = (ctx.y > 0.1 * h) & (ctx.y < 0.9 * h) & (ctx.x > 0.1 * w)
    d_left = inner.sum() / ((0.75 * (x1 - x0) - 0.1 * w) * 0.8 * h)
    inner = (new.y > 0.1 * h) & (new.y < 0.9 * h) & (new.x > 0.75 * (x1 - x0)) & (new.x < 0.9 * w)
    d_right = inner.sum() / ((0.9 * w - 0.75 * (x1 - x0)) * 0.8 * h)
    assert 0.85 < d_right / d_left < 1.15


def test_context_of_unknown_kinds_is_only_an_obstacle():
    """Elements whose kind the selection does not have are not neighbours (nothing to
    match them with); they stay obstacles."""
    ex = suite.make_exemplar("stones")
    other = suite.make_exemplar("bricks")
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(x1 - x0, y1 - y0)
    st = new_state(ex, region, rng=1)
    assert len(add_context(st, other)) == 0
    out = synthesize(ex, region, rng=1, measure=False, context=other.select(other.x < 60))
    assert len(overlaps(concat([other.select(other.x < 60), out]))[0]) == 0
