"""Issue 13 point 1 (helper s25r): large rings of many tiles (fourteen, radius 20, hubs 52
apart; ``benchmarks/synth_variants.py --varied-variants 16`` rings p2s16). Each hub's
lattice basis (``_grow.anchor_lattice``) was its own shortest offsets to other hubs, the
least of six jittered ones, about 1.1 % short of the lattice's spacing; carried from hub
to hub it shrank the output's hub lattice (inner hubs' six nearest 51.58 apart, the
generator's 51.98) and failed g[tile,hub] and regularity. The basis is now the mean of the
exemplar's hub offsets along it (``_grow._mean_basis``)."""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree
from strew_testing import fidelity_suite

from strew import Region
from strew.synth import synthesize
from strew.synth._api import as_selection
from strew.synth._grow import anchor_lattice
from strew.synth._prepare import prepare

suite = fidelity_suite()

LARGE_RINGS = dict(tiles=14, radius=20.0, hub=8.0, spacing=52.0)


def _mean_offset(hub):
    """Mean length of the offsets between neighbouring hubs (within 1.3 nearest spacings)."""
    tree = cKDTree(hub)
    med = float(np.median(tree.query(hub, 2)[0][:, 1]))
    ln = [np.hypot(*(hub[b] - hub[a])) for a, nb in enumerate(tree.query_ball_point(hub, 1.3 * med)) for b in nb if b != a]
    return float(np.mean(ln))


def test_lattice_basis_is_the_exemplars_mean_hub_offset():
    for rng, kw in ((16, LARGE_RINGS), (15, LARGE_RINGS), (7, {})):
        ex = suite.make_exemplar("rings", rng=rng, **kw)
        on, basis, spacing = anchor_lattice(prepare(as_selection(ex, None)))
        assert on.sum() >= 12
        mean = _mean_offset(ex.xy[ex.kind == ex.kinds.index("hub")])
        ln = np.hypot(basis[on][:, 0], basis[on][:, 1])  # (m, 2): both basis offsets
        # the lattice's own spacing, not the least of each hub's offsets (0.985-0.99 of it)
        assert np.all(np.abs(ln.mean(axis=0) / mean - 1.0) < 0.003)
        cos = np.sum(basis[on][:, :, 0] * basis[on][:, :, 1], axis=1) / (ln[:, 0] * ln[:, 1])
        assert np.all(np.abs(np.abs(cos) - 0.5) < 0.05)  # still two lattice directions


def test_large_rings_keep_the_hub_spacing():
    ex = suite.make_exemplar("rings", rng=16, **LARGE_RINGS)
    x0, y0, x1, y1 = ex.region.bounds
    out = synthesize(ex, Region.rectangle(2.5 * (x1 - x0), 2.5 * (y1 - y0)), rng=1)
    hub = out.xy[out.kind == out.kinds.index("hub")]
    w, h = out.region.bounds[2:]
    inner = (hub[:, 0] > 60) & (hub[:, 0] < w - 60) & (hub[:, 1] > 60) & (hub[:, 1] < h - 60)
    assert inner.sum() >= 30
    d = cKDTree(hub).query(hub[inner], 7)[0][:, 1:]
    # the generator's inner hubs stand 51.98 apart (six nearest, median); main's 51.58
    mean = _mean_offset(ex.xy[ex.kind == ex.kinds.index("hub")])
    assert abs(float(np.median(d)) / mean - 1.0) < 0.004
