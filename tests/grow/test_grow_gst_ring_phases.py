"""Neighbouring rings face each other as the exemplar's do (issue 14 point 1, held-out
exemplars: ``grow_variants.py --variants 13,14``, the default rings at variant seed 14
failed orientation.relative on every seed at 79a8da8).

Clustered exemplars grow their hubs alone and copy a whole reference cluster around each
(:mod:`strew.grow._clusters`). Drawn at random, neighbouring rings were paired as any two
of the exemplar's: at variant 14 its rings' phases are bunched, random pairs differ little,
and the exemplar's adjacent rings differ more. Each ring is now chosen against its placed
neighbours' (:func:`strew.grow._clusters.ring_phases`).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from strew_testing import fidelity_suite, grow_like_the_audit

from strew.grow._clusters import satellite_structure
from strew.metrics import fidelity

make_exemplar = fidelity_suite().make_exemplar


def test_rings_have_phases_clusters_do_not():
    from strew.grow._clusters import ring_phases

    ex = make_exemplar("rings", rng=14)
    rp = ring_phases(ex, satellite_structure(ex))
    assert rp is not None
    assert math.isclose(rp.period, 2 * math.pi / 10)
    assert np.all((rp.adjacent >= 0) & (rp.adjacent <= 0.5 * rp.period + 1e-12))
    assert len(rp.adjacent) >= 20  # 16 hubs on a hexagonal lattice
    # the exemplar's adjacent rings differ more than random pairs of its whole rings
    whole = rp.phase[satellite_structure(ex).complete]
    d = np.abs(whole[:, None] - whole[None, :]) % rp.period
    d = np.minimum(d, rp.period - d)[np.triu_indices(len(whole), 1)]
    assert float(np.median(rp.adjacent)) > float(np.median(d))
    # rings of 4-6 dots around discs (counts differ): no phase rule
    for v in (1, 7):
        cl = make_exemplar("clusters", rng=v)
        assert ring_phases(cl, satellite_structure(cl)) is None


def test_uneven_rings_have_no_phase():
    from strew.grow._clusters import ring_phases

    ex = make_exemplar("rings", rng=14)
    sat = satellite_structure(ex)
    i = int(np.flatnonzero(sat.complete)[0])
    m = sat.members[i]
    hub = ex.xy[sat.hubs[i]]
    # one tile of a whole ring moved a third of the way to its neighbour's bearing
    a = np.arctan2(*(ex.xy[m[0]] - hub)[::-1]) + (2 * math.pi / 10) / 3
    r = float(np.hypot(*(ex.xy[m[0]] - hub)))
    x = ex.x.copy()
    y = ex.y.copy()
    x[m[0]], y[m[0]] = hub[0] + r * math.cos(a), hub[1] + r * math.sin(a)
    assert ring_phases(ex, sat) is not None
    assert ring_phases(ex.replace(x=x, y=y), sat) is None


@pytest.mark.slow
def test_default_rings_v14_relative_orientation():
    # orientation.relative at seeds 1-6, the audit's run (3.5x the frame): at 79a8da8
    # 0.140, 0.137, 0.134, 0.139, 0.134, 0.138 against 0.0963 (0/6, mean 0.137); with
    # the phase rule 0.0887, 0.100, 0.0913, 0.0999, 0.0961, 0.0928 (4/6, mean 0.0948)
    ex = make_exemplar("rings", rng=14)
    vals = []
    for seed in range(1, 7):
        _, out = grow_like_the_audit(ex, seed)
        m = fidelity(ex, out, eq5=False, local=False).metrics["orientation.relative"]
        vals.append(m.value)
        tol = m.tolerance
    assert float(np.mean(vals)) <= tol, vals
