"""The studio's repeat view (issue 18 point 4), without a browser: strokes wrap across the
tile's edges, exports are repeat tiles, a region that is not a rectangle is refused."""

from __future__ import annotations

import numpy as np
import pytest

import strew
from strew import InputError
from strew import _periodic as P
from strew.studio._session import Session


def _session(tmp_path, size=(600.0, 400.0)):
    s = Session(tmp_path, seed=3, size=size)
    s.handle({"type": "load_exemplar", "example": "scales.svg"})
    return s


def _stroke(s, tool, points, radius):
    pts = [list(map(float, p)) for p in points]
    s.handle({"type": "stroke_start", "tool": tool, "radius": radius, "points": pts[:1]})
    for p in pts[1:]:
        s.handle({"type": "stroke_move", "points": [p]})
    return s.handle({"type": "stroke_end"})


def test_wrap_runs_split_at_the_edges(tmp_path):
    s = Session(tmp_path, size=(100.0, 100.0))
    s.handle({"type": "settings", "repeat": True})
    seg = np.array([[80.0, 10.0], [95.0, 10.0], [105.0, 10.0], [130.0, 10.0], [130.0, 50.0], [130.0, 90.0], [130.0, 110.0]])
    runs = s._wrap_runs(seg)
    # leaves at x = 100, comes back at x = 0; leaves at y = 100, comes back at y = 0
    assert [r.tolist() for r in runs] == [[[80, 10], [95, 10], [105, 10]], [[-5, 10], [5, 10], [30, 10], [30, 50], [30, 90], [30, 110]], [[30, -10], [30, 10]]]
    # every run lies in the tile but for the step across an edge
    for r in runs:
        inside = (r[:, 0] >= 0) & (r[:, 0] < 100) & (r[:, 1] >= 0) & (r[:, 1] < 100)
        assert inside[1:-1].all()
    # with a radius, copies one tile away that reach in follow
    near = s._wrap_runs(np.array([[95.0, 25.0], [96.0, 25.0]]), radius=10.0)
    assert len(near) == 2 and np.allclose(near[1], near[0] - [100, 0])
    s.handle({"type": "settings", "repeat": False})
    assert len(s._wrap_runs(seg)) == 1


def test_a_brush_stroke_across_the_edge_paints_both_sides_and_exports_a_tile(tmp_path):
    s = _session(tmp_path)
    status = s.handle({"type": "settings", "repeat": True})[-1]
    assert status["repeat"] == [0.0, 0.0, 600.0, 400.0]
    _stroke(s, "brush", [(450.0 + 25 * i, 200.0) for i in range(11)], 40.0)  # to x = 700: 100 past the edge
    sc = s.scene()
    assert np.sum(sc.x < 120) >= 5 and np.sum(sc.x > 480) >= 5  # continued at the left edge
    assert np.all((sc.x >= 0) & (sc.x < 600))
    # erasing across the left edge from the right copy removes the wrapped part
    _stroke(s, "erase", [(580.0, 200.0), (700.0, 200.0)], 60.0)
    assert np.sum(s.scene().x < 90) == 0
    s.handle({"type": "export", "path": "tile.json"})
    tile = strew.load(tmp_path / "tile.json")
    assert P.frame(tile) == (0.0, 0.0, 600.0, 400.0) and len(tile) == len(s.scene())


def test_repeat_needs_a_rectangle(tmp_path):
    s = Session(tmp_path, size=(100.0, 100.0))
    s.handle({"type": "region", "points": [[0, 0], [100, 0], [50, 90]]})
    with pytest.raises(InputError, match="rectangular region"):
        s.handle({"type": "settings", "repeat": True})
    with pytest.raises(InputError, match="true or false"):
        s.handle({"type": "settings", "repeat": "yes"})
    assert s.status_message()["repeat"] is None


def test_a_spray_stroke_across_the_edge_grows_on_both_sides(tmp_path):
    s = _session(tmp_path)
    s.handle({"type": "settings", "repeat": True})
    _stroke(s, "spray", [(500.0 + 20 * i, 150.0 + 5 * i) for i in range(12)], 40.0)  # to x = 720
    sc = s.scene()
    assert np.sum(sc.x < 100) >= 5 and np.sum(sc.x > 480) >= 5
    assert np.all((sc.x >= 0) & (sc.x < 600))
