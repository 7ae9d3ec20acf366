"""Issue 13 point 1, size mixes whose smallest kind leaves room empty (helper sizes13).

Several-size exemplars whose smallest elements are a minority, with room for more of
them between the larger ones (two sizes with 35 pebbles among 41-44 stones, three sizes
60/60/26, three sizes' default variant 2), came out with the smallest class packed:
pebbles 1.6-1.67x the exemplar's density, small stones 1.13-1.64x (7c83aee,
``benchmarks/synth_variants.py --varied``). Their open free-space share
(``_grow.open_free_space``, 0.007-0.023) lies under the neighbour limits' gate; the
room measure ``_prepare.open_room_share`` (0.49-0.94 against at most 0.36 for every
passing two- or three-size exemplar) now opens it (extension of §5.1)."""

from __future__ import annotations

import numpy as np
import pytest

from strew import Region
from strew.metrics import fidelity
from strew.synth import new_state, synthesize

from strew_testing import fidelity_suite

suite = fidelity_suite()

# benchmarks/_variants.py EDGE sets: pebbles a minority; small stones no longer the majority
PEBBLES_FEW = ("two_sizes", 8, dict(ratio=0.35, n_large=120, n_small=35))
SMALL_FEW = ("three_sizes", 7, dict(counts=(60, 60, 26)))


def _run(name: str, variant: int, kw: dict, seed: int = 1):
    ex = suite.make_exemplar(name, rng=variant, **kw)
    x0, y0, x1, y1 = ex.region.bounds
    out = synthesize(ex, Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed, measure=False)
    return ex, out, fidelity(ex, out, eq5=False, local=False)


@pytest.mark.slow
@pytest.mark.parametrize("case", [PEBBLES_FEW, SMALL_FEW], ids=["two_sizes_pebbles_few", "three_sizes_small_few"])
def test_minority_smallest_class_is_not_packed(case):
    """Faithful at 3.5x the frame, and the smallest kind's density within the judge's
    tolerance (7c83aee: density[pebble] 1.12 against 0.855; three sizes failed
    fraction[medium] 0.126 against 0.093 with small stones at 1.64x)."""
    name, variant, kw = case
    ex, out, rep = _run(name, variant, kw)
    small = ex.kinds[int(np.argmin([ex.shapes[k].radius for k in ex.kinds]))]
    dens = rep.metrics[f"density[{small}]"]
    assert dens.applicable and dens.passed, (dens.value, dens.tolerance)
    assert rep.faithful, [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]


def test_open_room_share_gates_the_limits():
    """The measured property: both minority exemplars have room for at least OPEN_ROOM
    of their smallest class more and get neighbour limits; the suite's two and three
    sizes (saturated gaps) have less and get none; a one-kind exemplar gets 0."""
    from strew.synth import _grow as G
    from strew.synth._prepare import OPEN_ROOM, open_room_share

    for name, variant, kw in (PEBBLES_FEW, SMALL_FEW):
        prep = new_state(suite.make_exemplar(name, rng=variant, **kw), Region.rectangle(100, 100), rng=1).prep
        assert G.open_free_space(prep)[0] < G.OPEN_SIZES[0], name  # under the old gate
        assert open_room_share(prep)[0] >= OPEN_ROOM, name
        assert (G.neighbour_limits(prep) >= 0).mean() > 0.8, name
    for name in ("two_sizes", "three_sizes"):
        prep = new_state(suite.make_exemplar(name), Region.rectangle(100, 100), rng=1).prep
        assert 0 < open_room_share(prep)[0] < OPEN_ROOM, name
        assert np.all(G.neighbour_limits(prep) == -1), name
    prep = new_state(suite.make_exemplar("stones"), Region.rectangle(100, 100), rng=1).prep
    assert open_room_share(prep)[0] == 0.0
