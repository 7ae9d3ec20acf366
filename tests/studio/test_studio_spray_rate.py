"""The studio's spray as one growth along the stroke (Ijiri §3, §5.1): streaming, scene, determinism."""

from __future__ import annotations

import numpy as np
import pytest
import shapely

from strew import metrics
from strew.studio._session import FIRST_SPRAY, Session

PATH = [(80.0 + 20.0 * i, 200.0 + 40.0 * np.sin(i / 6)) for i in range(25)]


def _session(tmp_path, example="stones.svg", seed=3):
    tmp_path.mkdir(parents=True, exist_ok=True)
    s = Session(tmp_path, seed=seed, size=(700.0, 400.0))
    s.handle({"type": "load_exemplar", "example": example})
    return s


def _stroke(s, tool, points, radius, emit=None):
    pts = [list(map(float, p)) for p in points]
    s.handle({"type": "stroke_start", "tool": tool, "radius": radius, "points": pts[:1]}, emit)
    for p in pts[1:]:
        s.handle({"type": "stroke_move", "points": [p]}, emit)
    return s.handle({"type": "stroke_end"}, emit)


def _dist(xy, pts):
    return shapely.distance(shapely.LineString(pts), shapely.points(xy))


@pytest.mark.parametrize("example", ["stones.svg", "scales.svg", "tiles.svg"])
def test_spray_stays_under_the_stroke_without_overlaps(tmp_path, example):
    s = _session(tmp_path, example)
    _stroke(s, "spray", PATH, 60.0)
    scene = s.scene()
    assert len(scene) > 50
    assert np.all(_dist(scene.xy, PATH) <= 60.0 + 1e-6)
    assert s.region.contains(scene.xy).all()
    assert len(metrics.overlaps(scene)[0]) == 0


def test_spray_is_deterministic_for_a_seed(tmp_path):
    a = _session(tmp_path / "a")
    b = _session(tmp_path / "b")
    c = _session(tmp_path / "c", seed=4)
    for s in (a, b, c):
        _stroke(s, "spray", PATH, 50.0)
    assert np.array_equal(a.scene().xy, b.scene().xy)
    assert not np.array_equal(a.scene().xy, c.scene().xy)


def test_spray_over_the_scene_leaves_it_alone_and_fills_around_it(tmp_path):
    s = _session(tmp_path)
    _stroke(s, "spray", [(300.0, 200.0), (320.0, 200.0)], 60.0)
    before = s.scene()
    _stroke(s, "spray", PATH, 60.0)
    after = s.scene()
    assert np.array_equal(after.xy[: len(before)], before.xy)
    assert len(after) > len(before) + 50  # the stroke starts free and crosses the old patch
    assert len(metrics.overlaps(after)[0]) == 0
    # a stroke that starts inside the old patch still grows where the cursor goes on
    s2 = _session(tmp_path / "s2")
    _stroke(s2, "spray", [(100.0, 200.0), (110.0, 200.0)], 60.0)
    n0 = len(s2.scene())
    _stroke(s2, "spray", [(100.0 + 15.0 * i, 200.0) for i in range(25)], 60.0)
    assert len(s2.scene()) > n0 + 50
    assert len(metrics.overlaps(s2.scene())[0]) == 0


def test_spray_streams_a_small_first_chunk_then_the_rest(tmp_path):
    s = _session(tmp_path)
    sent = []
    pts = [[float(x), float(y)] for x, y in PATH]
    out = s.handle({"type": "stroke_start", "tool": "spray", "radius": 120.0, "points": pts[:1]}, sent.append)
    scenes = [m for m in sent if m["type"] == "scene"]
    # the first elements go out before the first point's disc has grown (latency)
    assert scenes and 0 < scenes[0]["n"] <= 2 * FIRST_SPRAY
    final = [m for m in out if m["type"] == "scene"]
    assert final and final[-1]["n"] > scenes[0]["n"]
    # every message only appends (the elements on screen do not move)
    for m in scenes[1:] + final:
        assert m["op"] == "patch" and not m["update"]["index"]
    s.handle({"type": "stroke_end"})


def test_spray_undo_removes_the_whole_stroke(tmp_path):
    s = _session(tmp_path)
    _stroke(s, "spray", PATH, 50.0)
    assert len(s.scene()) > 0
    s.handle({"type": "undo"})
    assert len(s.scene()) == 0
