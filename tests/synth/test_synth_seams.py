"""Issue 13 points 1-2 for rings: on a large canvas rings keep their hubs and tiles far
from the first seed, and an untuned variant (other radius and spacing) is faithful.

Before the local map's window tolerance took the exemplar's own window-to-window noise
(``strew._fidelity._window_noise``), a fresh 52x draw of the rings generator itself
failed half of its windows on ``density[hub]``, so the first test asserts the defect the
failing windows showed: rings without a hub, whose empty centres (radius about 14, the
exemplar's largest empty circle is 9) failed the windows' largest empty circle. With
that rule fresh draws pass every window, and the last test asks it of synth.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import cKDTree

from strew import Region
from strew.metrics import fidelity
from strew.synth import synthesize

from strew_testing import fidelity_suite


def test_rings_on_a_large_canvas_keep_hub_and_tiles():
    """20x the exemplar's area: every interior tile has a hub within its ring's reach,
    and most interior rings have all 10 tiles, as every ring of the exemplar has.

    Before tiles leaned on their hub (``_prepare.parents`` with anchors), seeds 1-3 left
    33-84 interior tiles more than 18 from any hub (3-8 hubless rings). Before a ring kept
    one phase (``_grow._snap_to_anchor_rings``), its tiles came from copies of exemplar
    rings of other phases and kept a gap where no tile fitted: 0.63-0.68 of the rings
    were whole at seeds 1-3, 0.89-0.90 after."""
    ex = fidelity_suite().make_exemplar("rings")
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(4.5 * (x1 - x0), 4.5 * (y1 - y0))
    out = synthesize(ex, region, rng=1, measure=False)
    hub = out.kind == out.kinds.index("hub")
    assert hub.sum() > 150  # about 20 x the exemplar's 16 hubs
    # the hubs are the exemplar's share of the elements (16 of 177)
    assert abs(hub.mean() - 16 / 177) < 0.01
    size = np.array(region.bounds[2:])
    inner = np.all((out.xy > 40.0) & (out.xy < size - 40.0), axis=1)
    # ring radius 15 (tiles' centres), the tile's half length 3: a tile of a ring with
    # a hub is never further than 18 from it
    d, _ = cKDTree(out.xy[hub]).query(out.xy[~hub & inner])
    assert np.sum(d > 18.0) == 0, np.sort(d)[-5:]
    count = np.array([len(v) for v in cKDTree(out.xy[~hub]).query_ball_point(out.xy[hub & inner], 18.0)])
    assert np.mean(count == 10) >= 0.85, np.bincount(count)
    assert np.all(count <= 10)


def test_untuned_rings_variant_is_faithful():
    """Rings of radius 12 at spacing 34 drawn at seed 8 (``synth_variants.py``'s
    ``VARIED``, nobody tuned on it), 12x the frame's area: faithful, regularity
    included. Before tiles leaned on their hub and each ring kept one phase, both seeds
    failed regularity (0.15 and 0.12 against 0.06: rings with gaps and stray tiles)."""
    ex = fidelity_suite().make_exemplar("rings", rng=8, radius=12.0, spacing=34.0)
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0))
    out = synthesize(ex, region, rng=2, measure=False)
    rep = fidelity(ex, out, region, eq5=False, local=False)
    assert rep.faithful, rep.failures


@pytest.mark.slow
def test_rings_without_seams_at_12x():
    """No failing window of the local fidelity map at 12x the exemplar's area, and every
    interior ring whole (``_grow._complete_anchor_rings``). Before, about 1 interior ring
    in 10 kept 9 tiles: its tiles had drifted round the ring under the horizon
    optimisation, or a facing tile of a ring too close blocked the slot, and the hole
    beside it failed the windows' largest empty circle (seeds 1-3 at 12x: whole rings
    0.85-0.92, failing windows 0.13-0.37, worst 1.10-1.80; at 50x seed 1: 0.20 of windows,
    worst 1.93; after: 0, worst 0.94). About 6 s."""
    ex = fidelity_suite().make_exemplar("rings")
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0))
    out = synthesize(ex, region, rng=1, measure=False)
    rep = fidelity(ex, out, region, eq5=False)
    assert rep.faithful, rep.failures
    score = np.asarray(rep.local["score"], float)
    assert np.isfinite(score).sum() >= 20
    assert rep.local["worst"]["score"] <= 1.0, rep.local["worst"]
    hub = out.kind == out.kinds.index("hub")
    size = np.array(region.bounds[2:])
    inner = np.all((out.xy > 40.0) & (out.xy < size - 40.0), axis=1)
    count = np.array([len(v) for v in cKDTree(out.xy[~hub]).query_ball_point(out.xy[hub & inner], 18.0)])
    assert np.mean(count == 10) >= 0.97, np.bincount(count)
    assert np.all(count <= 10)


@pytest.mark.parametrize("cap", [40, 157])
def test_completed_rings_keep_max_elements(cap):
    """Completing rings at the end of a growth (``_grow._complete_anchor_rings``) adds
    no element beyond ``grow``'s ``max_elements``, and no two elements closer than
    their collision bound."""
    from strew.synth import grow, new_state, seed_patch

    ex = fidelity_suite().make_exemplar("rings")
    st = new_state(ex, Region.rectangle(300, 260), rng=4)
    seed_patch(st, (150.0, 130.0))
    grow(st, max_elements=cap)
    assert st.n <= cap
    prep = st.prep
    src = st.src
    d = np.hypot(*(st.pos[:, None, :] - st.pos[None, :, :]).transpose(2, 0, 1))
    lim = np.maximum(prep.rc[src][:, None] + prep.rc[src][None, :], prep.min_dist[prep.skind[src]][:, prep.skind[src]])
    np.fill_diagonal(d, np.inf)
    assert np.all(d >= lim - 1e-6)
