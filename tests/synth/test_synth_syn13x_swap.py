"""Issue 13 point 1 (helper syn13x): kinds of one size class keep their exemplar's mix
away from the frame; an over-dense kind's elements are swapped in place for an
under-dense kind's where it fits (``_swap.fill_swapped``)."""

from __future__ import annotations

import numpy as np
from strew_testing import fidelity_suite

from strew import Region
from strew.synth import synthesize


def _stone_share(arr, margin: float) -> float:
    """Stones among the elements at least ``margin`` inside the frame."""
    xy = np.asarray(arr.xy)
    kn = np.asarray(arr.kind_names)
    x0, y0, x1, y1 = arr.region.bounds
    inn = (xy[:, 0] > x0 + margin) & (xy[:, 0] < x1 - margin) & (xy[:, 1] > y0 + margin) & (xy[:, 1] < y1 - margin)
    return float(np.mean(kn[inn] == "stone"))


def test_one_size_class_keeps_its_mix():
    # two sizes ratio 0.7 (one size class), 40 stones and 100 pebbles asked, variant
    # seed 8 (grow_variants.HARDER["two_sizes"][3]): the generator fits 40 and 32.
    # Copies whose stone overlaps one placed before still bring their pebbles, which
    # take the place. Stone share away from the frame at 2x: exemplar 0.619; 4882d93
    # seeds 1 and 2 0.519 and 0.543 (fails); now 0.586 and 0.591.
    ex = fidelity_suite().make_exemplar("two_sizes", rng=8, ratio=0.7, n_large=40, n_small=100)
    x0, y0, x1, y1 = ex.region.bounds
    margin = 27.0  # two of the largest collision radii
    want = _stone_share(ex, margin)
    out = synthesize(ex, Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0)), rng=1, measure=False)
    got = _stone_share(out, margin)
    assert got >= want - 0.05, (got, want)
