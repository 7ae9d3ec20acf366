"""Issue 13 point 2 (helper s27p): at 50x the area (rings, seed 5) a corner of the local map
failed orientation.relative: neighbouring rings turned in lockstep. A ring's phase (the angle
of its tiles about its hub modulo the tile step) is that of the exemplar ring its hub was
copied as, and k-coherence copied the few whole exemplar rings next to each other: 10-20% of
neighbouring output hubs were copies of one exemplar hub, their rings in exact step (the
exemplar's own phases are drawn uniformly). A new ring beside a copy of its own exemplar ring
now takes another exemplar ring's slots (``_grow._spread_ring_sources``)."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import cKDTree
from strew_testing import fidelity_suite

from strew import Region
from strew.synth import synthesize

suite = fidelity_suite()


def _lockstep(arr, tiles: int, radius: float) -> tuple[float, int]:
    """Fraction of (hub, one of its 6 nearest hubs) pairs whose rings stand at the same phase
    (within 0.005 of the tile step; phases drawn at random: 1%), and the number of hubs."""
    hub = arr.xy[arr.kind == arr.kinds.index("hub")]
    tile = arr.xy[arr.kind != arr.kinds.index("hub")]
    d, j = cKDTree(hub).query(tile)
    on = np.abs(d - radius) <= 2.0
    ang = np.arctan2(tile[:, 1] - hub[j, 1], tile[:, 0] - hub[j, 0])
    z = np.bincount(j[on], np.cos(tiles * ang[on]), len(hub)) + 1j * np.bincount(j[on], np.sin(tiles * ang[on]), len(hub))
    whole = np.bincount(j[on], minlength=len(hub)) >= 3
    ph = np.angle(z) / tiles
    _, nb = cKDTree(hub).query(hub, 7)
    a, b = np.repeat(np.arange(len(hub)), 6), nb[:, 1:].ravel()
    keep = whole[a] & whole[b]
    diff = np.abs(np.angle(np.exp(1j * tiles * (ph[b] - ph[a])))) / (2 * np.pi)  # in tile steps
    return float(np.mean(diff[keep] < 0.005)), len(hub)


@pytest.mark.parametrize("seed", [1, 3])
def test_neighbouring_rings_do_not_turn_in_lockstep(seed):
    ex = suite.make_exemplar("rings")
    p = ex.meta["params"]
    x0, y0, x1, y1 = ex.region.bounds
    out = synthesize(ex, Region.rectangle(2.5 * (x1 - x0), 2.5 * (y1 - y0)), rng=seed, measure=False)
    ex_frac, _ = _lockstep(ex, int(p["tiles"]), float(p["radius"]))
    frac, n_hub = _lockstep(out, int(p["tiles"]), float(p["radius"]))
    assert n_hub >= 80
    assert ex_frac == 0.0  # the exemplar's rings: no two neighbours in step
    # main: 0.147 (seed 1) and 0.195 (seed 3) of neighbouring pairs in exact step
    assert frac < 0.05, frac
