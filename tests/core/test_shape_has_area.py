"""``Shape.has_area`` answers what ``not Shape.area_geometry.is_empty`` answers (the SVG
writer asks it for every part of every element; the shortcut must never disagree), and the
ornament renderer's bounding-box shortcut leaves the drawing as the exact clip does."""

from __future__ import annotations

import numpy as np
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

from strew import Shape
from strew.ornament._render import _clip_to_panel

coord = st.integers(-6, 6).map(float)  # a coarse grid: rings that repeat, cancel, touch and cross
ring = st.lists(st.tuples(coord, coord), min_size=1, max_size=6)
path = st.tuples(ring, st.booleans())


@settings(max_examples=150, deadline=None)
@given(st.lists(path, min_size=0, max_size=4), st.booleans())
def test_has_area_agrees_with_the_even_odd_area(paths, twice):
    rings = [{"points": np.array(p, dtype=float), "closed": c} for p, c in paths]
    if twice and rings:
        rings.append(dict(rings[0]))  # the same ring again: the even-odd area may cancel
    shape = Shape(tuple(rings)) if rings else Shape(())
    fresh = Shape(tuple(rings)) if rings else Shape(())
    assert shape.has_area == (not fresh.area_geometry.is_empty)


def test_has_area_of_rings_that_cancel_is_false():
    sq = np.array([[0, 0], [2, 0], [2, 2], [0, 2]], dtype=float)
    assert not Shape((sq, sq.copy())).has_area
    assert Shape((sq, sq * 0.5 + 0.5)).has_area  # a square with a hole
    bow = np.array([[0, 0], [2, 2], [2, 0], [0, 2]], dtype=float)  # invalid: falls back to the exact area
    assert Shape((bow,)).has_area


@settings(max_examples=100, deadline=None)
@given(st.lists(ring, min_size=1, max_size=3), st.booleans())
def test_clip_shortcut_gives_the_exact_clip(paths, closed):
    # the ring panel of the gallery (a panel with a hole), a mark anywhere around it
    panel = shapely.Point(0, 0).buffer(5, quad_segs=8).difference(shapely.Point(0, 0).buffer(2, quad_segs=4))
    cover = shapely.buffer(panel, 1e-7)
    shapely.prepare(cover)
    arrs = [np.array(p, dtype=float) for p in paths]
    got = _clip_to_panel(arrs, closed, panel, cover)
    # the exact answer: the mark's geometry covered by the panel's cover keeps the paths
    if closed:
        from strew.shape import Path, paths_to_polygon

        geom = paths_to_polygon(Path(q, True) for q in arrs)
    else:
        geom = shapely.MultiLineString([q for q in arrs if len(q) >= 2])
    if geom.is_empty or shapely.covers(cover, geom):
        assert got is arrs
    else:
        assert got is not arrs
