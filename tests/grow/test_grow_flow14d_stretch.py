"""Flow mode: where the bent lattice is stretched, an element goes in and the stretch
becomes a dislocation (issue 14 point 2; :mod:`strew.grow._flow_stretch`).

The hexagonal lattice grown from the corner at the centre of curvature of a
quarter-circle field (``benchmarks/grow.py --structure --flow-only``, "start 2,2
spacings"): at 550ea99, 0.806 of the interior elements kept six neighbours at the
spacing (+-15%) and 52 interior sites were stretched (a gap, no crowding). With the
insertions (and the relaxation of their windows): 0.880 and 28, no hole, nothing
across the edge.
"""

from __future__ import annotations

import hashlib

import numpy as np
import pytest
from scipy.spatial import cKDTree

from strew import Region
from strew.grow import analyze
from strew.grow._growth import GrowParams, grow_reference

from strew_testing import fidelity_suite

from test_grow_flow_gaps import SP, _inside_without_overlap, _quarter_circles, _shares  # noqa: E402


def _widest_gap(xy: np.ndarray, region: Region) -> float:
    """The largest distance, in spacings, from a point over 2 spacings inside the region
    to its nearest centre (a hole: over 0.75)."""
    x0, y0, x1, y1 = region.bounds
    g = np.mgrid[x0 + 2 * SP : x1 - 2 * SP : 3.0, y0 + 2 * SP : y1 - 2 * SP : 3.0].reshape(2, -1).T
    return float(cKDTree(xy).query(g)[0].max() / SP)


def _digest(out) -> str:
    return hashlib.sha256(np.ascontiguousarray(np.c_[out.xy, out.rotation]).tobytes()).hexdigest()


@pytest.fixture(scope="module")
def hex_ref():
    return analyze(fidelity_suite().make_exemplar("hex_lattice", nx=8, ny=8))


@pytest.mark.slow
def test_flow_stretched_lattice_gets_elements_and_keeps_its_six_neighbours(hex_ref):
    a = 30 * SP
    field = _quarter_circles(a)
    region = Region.rectangle(a, a)
    kw = dict(region=region, mode="flow", flow=field, start=(2 * SP, 2 * SP))
    out = grow_reference(hex_ref, GrowParams(**kw), rng=1)
    _inside_without_overlap(out, region)
    six, stretched = _shares(out.xy, region)
    assert six >= 0.85  # 0.880 here; 0.806 at 550ea99
    assert stretched <= 0.15  # 0.120 here; 0.194 at 550ea99
    assert _widest_gap(out.xy, region) < 0.75  # no hole
    off = grow_reference(hex_ref, GrowParams(**kw, flow_stretch_min=None), rng=1)
    six_off, stretched_off = _shares(off.xy, region)
    assert six_off < six - 0.04 and stretched_off > stretched + 0.04
    assert len(out) > len(off)


@pytest.mark.parametrize("mode", ["fixed", "rotate"])
def test_flow_stretch_option_leaves_the_other_modes_alone(hex_ref, mode):
    assert_flow_option_leaves_mode_alone(hex_ref, mode, "flow_stretch_min")


def assert_flow_option_leaves_mode_alone(hex_ref, mode: str, option: str) -> None:
    """A flow-only pass switched off (``option=None``) changes no byte of ``mode``'s output."""
    kw = dict(region=Region.rectangle(16 * SP, 12 * SP), mode=mode)
    on = grow_reference(hex_ref, GrowParams(**kw), rng=3)
    off = grow_reference(hex_ref, GrowParams(**kw, **{option: None}), rng=3)
    assert len(on) > 100
    assert _digest(on) == _digest(off)
