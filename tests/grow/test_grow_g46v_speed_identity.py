"""Issue 14 point 5 (helper g46v): the placement loop's speed-ups leave every byte alone.

``_Place.place`` takes each neighbour's angle about the new element once per placement,
and ``place``, ``_fit_position`` and ``_ring_edges`` call ``GrowIndex.crosses_plane``
directly in the plane and skip ``crosses_boundary`` where there is no boundary stroke.
The outputs must be the ones the loops gave before (digests of positions and outlines
recorded on main 76c5b94, pinned and unpinned alike on the CI machine): in the plane,
with a boundary stroke (the boundary branch), and on the torus (the generic branch).
"""

from __future__ import annotations

import hashlib

import numpy as np
import pytest
import shapely

from strew import Region
from strew.grow import analyze, grow
from strew.grow._exemplars import hex_exemplar, stone_exemplar


def _digest(out) -> str:
    h = hashlib.sha256()
    h.update(np.ascontiguousarray(out.xy, dtype=float).tobytes())
    h.update(b"".join(shapely.to_wkb(np.asarray(out.geometry))))
    return h.hexdigest()[:16]


@pytest.fixture(scope="module")
def refs():
    return analyze(hex_exemplar()), analyze(stone_exemplar())


def test_plane_stones_relaxed_unchanged(refs):
    _, stones = refs
    out = grow(stones, count=400, rng=3, relax=True)
    assert (len(out), _digest(out)) == (400, "7de7f49b97715641")


def test_boundary_stroke_unchanged(refs):
    hexr, _ = refs
    sp = hexr.mean_edge
    out = grow(hexr, rng=3, relax=True, region=Region.rectangle(12 * sp, 8 * sp),
               boundary=[np.c_[np.linspace(1, 11, 5) * sp, np.linspace(1, 3, 5) * sp]])
    assert (len(out), _digest(out)) == (94, "848212e971697958")


def test_torus_unchanged(refs):
    hexr, stones = refs
    sp = hexr.mean_edge
    out = grow(stones, rng=3, relax=True, region=Region.rectangle(8 * sp, 8 * sp), periodic=True)
    assert (len(out), _digest(out)) == (43, "13ebb651a52aea2d")
