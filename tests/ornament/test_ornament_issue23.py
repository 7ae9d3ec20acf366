"""Issue 23: drawn ornaments stay inside their panel (marks are cut at its edge)."""

from __future__ import annotations

import numpy as np
import pytest
import shapely

from strew import Region, metrics
from strew.ornament import grow_elements
from strew.ornament._render import _clip_to_panel

RING = Region(shapely.Point(35, 35).buffer(35, quad_segs=32).difference(shapely.Point(35, 35).buffer(12, quad_segs=16)))


# seed 1960127676: the gallery's willow ring, whose stems stood out of the panel before
@pytest.mark.parametrize(("pattern", "style", "seed"), [("willow", "morris", 1960127676), ("hierarchy", "color", 7), ("flowers", "ink", 7)])
def test_every_mark_lies_inside_a_ring_panel(pattern, style, seed):
    orn = grow_elements(pattern, RING, seeds=[(35, 4)], rng=seed)
    arr = orn.render(style)
    assert len(arr) > 20
    assert len(metrics.outside(arr)) == 0


def test_clip_cuts_a_filled_mark_and_a_stroke_at_the_panel_edge():
    panel = shapely.box(0, 0, 10, 10)
    cover = shapely.buffer(panel, 1e-9)
    square = [np.array([[8.0, 8], [12, 8], [12, 12], [8, 12]])]
    (ring,) = _clip_to_panel(square, True, panel, cover)
    assert shapely.Polygon(ring).area == pytest.approx(4.0)
    line = [np.array([[-5.0, 5], [5, 5]])]
    (cut,) = _clip_to_panel(line, False, panel, cover)
    assert shapely.LineString(cut).length == pytest.approx(5.0)
    inside = [np.array([[1.0, 1], [2, 1], [2, 2]])]
    assert _clip_to_panel(inside, True, panel, cover) is inside
    assert _clip_to_panel([np.array([[20.0, 20], [30, 30]])], False, panel, cover) == []
