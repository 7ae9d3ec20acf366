"""Hard-core exemplars are not lattices (issue 14 point 1, held-out exemplars:
``grow_variants.py --varied-variants 13,14``, stripes p2s13 failed nn[dot>dot] on every
seed 1-6 at 79a8da8).

The EDGE set "wide near-vertical bands, long bars" draws dots and bars by dart throwing
at one radius until no more fit. At variant seeds 12 and 13 the nearest-neighbour
distances spread by 5.6 % and 5.9 % of their mean, under ``GAP_LATTICE_CV`` (6 %), and
growth took the exemplar for a lattice: no per-pair outline gap (``_Grower._pair_gaps``)
and no hole fill (``_Grower._irregular``). Such distances have a floor (their nearest
tenth within 1 % of the least) and a tail beyond it; a noisy lattice's spread both ways.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import cKDTree
from strew_testing import fidelity_suite, grow_like_the_audit

from strew.grow import analyze
from strew.grow._growth import GrowParams, _Grower
from strew.metrics import fidelity

make_exemplar = fidelity_suite().make_exemplar

# the audit's edge set "wide near-vertical bands, long bars" (benchmarks/_variants.py EDGE)
WIDE = dict(band=45.0, angle=1.4, dot=2.5, bar=(12.0, 2.5))


def _grower(ex):
    return _Grower(analyze(ex, lattice_repairs=True), GrowParams(count=100), np.random.default_rng(0))


def _spread(ex):
    nn = cKDTree(ex.xy).query(ex.xy, k=2)[0][:, 1]
    return float(nn.std() / nn.mean())


@pytest.mark.parametrize("variant", [12, 13])
def test_saturated_dart_throwing_is_irregular(variant):
    ex = make_exemplar("stripes", rng=variant, **WIDE)
    assert _spread(ex) < 0.06  # the case: under the spread test alone
    g = _grower(ex)
    assert g._irregular()
    assert float(g.pair_gap.max()) > 0.0  # outlines keep the reference's gaps


@pytest.mark.parametrize(
    ("name", "kw", "variant"),
    [
        ("hex_lattice", {}, 7),
        ("bricks", dict(length=12.0, height=10.0, mortar=3.0, noise=0.4), 14),  # noisiest bricks
        ("scales", dict(width=16.0, length=7.0, gap=2.5, noise=0.06), 9),  # noisy flat scales
        ("scales", dict(row_angle=0.6), 13),  # a floor within 1 % of the least distance
        ("rows_noisy", {}, 10),
        ("rows_noisy", dict(tile=0.85, noise=0.03, row_angle=0.4), 8),
    ],
)
def test_lattices_stay_lattice_like(name, kw, variant):
    ex = make_exemplar(name, rng=variant, **kw)
    assert _spread(ex) < 0.06
    g = _grower(ex)
    assert not g._irregular()
    assert float(g.pair_gap.max()) == 0.0


@pytest.mark.slow
def test_wide_bands_dots_keep_their_spacing():
    # nn[dot>dot] on seeds 1-3, the audit's run (3.5x the frame, 10x the count): at
    # 79a8da8 0.0645, 0.067, 0.0759 against 0.05 (0/3, mean 0.069); with the hard-core
    # test 0.0551, 0.0413, 0.0454 (2/3, mean 0.047)
    ex = make_exemplar("stripes", rng=13, **WIDE)
    vals = []
    for seed in (1, 2, 3):
        region, out = grow_like_the_audit(ex, seed)
        assert np.all(region.contains_geometry(out.geometry, tolerance=1e-9))
        m = fidelity(ex, out, eq5=False, local=False).metrics["nn[dot>dot]"]
        vals.append(m.value)
        tol = m.tolerance
    assert float(np.mean(vals)) <= tol, vals
    assert sum(v <= tol for v in vals) >= 2, vals


# helper g43r: the default stripes at variant seed 29 (and the ``--varied`` set
# band=22, angle=0.8 on the same throw) spread by 5.75 %, with the nearest tenth 1.17 %
# over the least distance: under 1.01 (HARD_CORE_FLOOR until then) the throw read as a
# lattice and the dots packed at 0.77 s from their nearest dot at the lowest decile
# (the exemplar's floor 0.95 s): nn[dot>dot] failed seeds 1-4 (0.057-0.063 against 0.05)
@pytest.mark.parametrize("kw", [{}, dict(band=22.0, angle=0.8)])
def test_saturated_throw_with_a_wider_floor_is_irregular(kw):
    ex = make_exemplar("stripes", rng=29, **kw)
    nn = cKDTree(ex.xy).query(ex.xy, k=2)[0][:, 1]
    assert _spread(ex) < 0.06
    assert float(np.quantile(nn, 0.1)) > 1.01 * float(nn.min())  # the case: the floor over 1 %
    g = _grower(ex)
    assert g._irregular()
    assert float(g.pair_gap.max()) > 0.0


@pytest.mark.slow
def test_saturated_throw_dots_keep_their_floor():
    # the dots' nearest dot at the lowest decile, the audit's run at seed 2: 0.81 of the
    # exemplar's least distance on main (9.47 against 11.70), 0.98 with the wider floor;
    # nn[dot>dot] 0.0631 -> passes against 0.05
    ex = make_exemplar("stripes", rng=29)
    dot = ex.kinds.index("dot")
    exd = ex.xy[ex.kind == dot]
    least = float(cKDTree(exd).query(exd, k=2)[0][:, 1].min())
    region, out = grow_like_the_audit(ex, 2)
    assert np.all(region.contains_geometry(out.geometry, tolerance=1e-9))
    od = out.xy[out.kind == dot]
    d = cKDTree(od).query(od, k=2)[0][:, 1]
    assert float(np.quantile(d, 0.1)) >= 0.93 * least
    m = fidelity(ex, out, eq5=False, local=False).metrics["nn[dot>dot]"]
    assert m.value <= m.tolerance, (m.value, m.tolerance)
