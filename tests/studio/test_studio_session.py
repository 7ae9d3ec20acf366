"""The studio's session: the tools, history, palette editing and project files, without a server."""

from __future__ import annotations

import json

import numpy as np
import pytest
import shapely

from strew import InputError, load
from strew.studio._session import PALETTE_FILE, SCENE_FILE, Session


def _session(tmp_path, example="scales.svg", seed=3, size=(600.0, 400.0)):
    s = Session(tmp_path, seed=seed, size=size)
    s.handle({"type": "load_exemplar", "example": example})
    return s


def _stroke(s, tool, points, radius, **extra):
    pts = [list(map(float, p)) for p in points]
    s.handle({"type": "stroke_start", "tool": tool, "radius": radius, "points": pts[:1], **extra})
    for p in pts[1:]:
        s.handle({"type": "stroke_move", "points": [p]})
    return s.handle({"type": "stroke_end"})


def _dist_to_path(xy, pts):
    return shapely.distance(shapely.LineString(pts), shapely.points(xy))


LINE = [(100.0 + 20 * i, 200.0) for i in range(16)]


def test_brush_elements_follow_the_stroke(tmp_path):
    s = _session(tmp_path)
    _stroke(s, "brush", LINE, 40.0)
    scene = s.scene()
    assert len(scene) >= 20
    # §5.4: synthesis stays within the brush discs
    assert np.all(_dist_to_path(scene.xy, LINE) <= 40.0 + 1e-6)
    # and covers the stroke from start to end
    assert scene.x.min() < 140 and scene.x.max() > 360
    assert s.status_message()["count"] == len(scene)


def test_brush_finishes_the_stroke_when_it_ends(tmp_path, monkeypatch):
    """Segments grow a bounded number of iterations; the rest grows at stroke end, so
    the finished stroke holds as many elements as one grown to the end at every segment."""
    import strew.studio._session as session_module

    def paint(iterations):
        monkeypatch.setattr(session_module, "BRUSH_ITERATIONS", iterations)
        s = _session(tmp_path, example="tiles.svg")
        s.handle({"type": "stroke_start", "tool": "brush", "radius": 100.0, "points": [list(LINE[0])]})
        for p in LINE[1:]:
            s.handle({"type": "stroke_move", "points": [list(p)]})
        return s, bool(s.state.horizon.any()), len(s.state.brush_points), s.handle({"type": "stroke_end"})

    s, growing, left, replies = paint(1)
    assert growing and left > 0  # growth was left for the stroke's end ...
    assert not s.state.horizon.any() and len(s.state.brush_points) == 0  # ... and done there
    assert [m for m in replies if m["type"] == "scene"]  # the finished part is streamed
    assert s.status_message()["count"] == len(s.scene())
    assert np.all(_dist_to_path(s.scene().xy, LINE) <= 100.0 + 1e-6)
    full, *_ = paint(10_000)
    assert len(s.scene()) >= 0.95 * len(full.scene())


def test_brush_output_has_no_overlaps(tmp_path):
    s = _session(tmp_path)
    _stroke(s, "brush", LINE, 50.0)
    geom = s.scene().geometry
    tree = shapely.STRtree(geom)
    a, b = tree.query(geom, predicate="intersects")
    pairs = [(i, j) for i, j in zip(a, b) if i < j]
    overlap = sum(shapely.intersection(geom[i], geom[j]).area for i, j in pairs)
    assert overlap <= 0.02 * sum(g.area for g in geom)


def test_erase_then_undo_and_redo(tmp_path):
    s = _session(tmp_path)
    _stroke(s, "brush", LINE, 40.0)
    before = s._arrays()
    mid = [(250.0, 150.0), (250.0, 250.0)]
    _stroke(s, "erase", mid, 25.0)
    after = s.scene()
    assert len(after) < len(before["k"])
    assert np.all(_dist_to_path(after.xy, mid) > 25.0 - 1e-9)
    s.handle({"type": "undo"})
    restored = s._arrays()
    for c in before:
        assert np.array_equal(before[c], restored[c])
    s.handle({"type": "redo"})
    assert len(s.scene()) == len(after)


def test_undo_with_nothing_to_undo_is_a_message(tmp_path):
    s = Session(tmp_path)
    out = s.handle({"type": "undo"})
    assert out[-1]["message"] == "nothing to undo"


def test_spray_grows_along_the_path_only(tmp_path):
    s = _session(tmp_path)
    path = [(100.0 + 25 * i, 150.0) for i in range(10)]
    _stroke(s, "spray", path, 35.0)
    scene = s.scene()
    assert len(scene) >= 10
    # Ijiri §3: only seeds within the spray radius grow; an element's centre may sit up to
    # one reference edge beyond the last seed that grew it.
    ref = s._reference(s.selection[0])
    assert np.all(_dist_to_path(scene.xy, path) <= 35.0 + 1.6 * ref.mean_edge)


def test_boundary_stroke_stops_the_spray(tmp_path):
    s = _session(tmp_path)
    wall = [(300.0, 0.0), (300.0, 400.0)]
    _stroke(s, "boundary", wall, 1.0)
    assert len(s.boundary_strokes) == 1
    path = [(150.0 + 10 * i, 200.0) for i in range(12)]  # stays left of the wall
    _stroke(s, "spray", path, 80.0)
    scene = s.scene()
    assert len(scene) > 5
    assert np.all(scene.x < 300.0)


def test_flow_strokes_give_arrows_along_them(tmp_path):
    s = Session(tmp_path)
    out = _stroke(s, "flow", [(50.0, 100.0), (300.0, 100.0), (550.0, 100.0)], 1.0)
    msg = next(m for m in out if m["type"] == "strokes")
    arrows = np.asarray(msg["arrows"])
    assert len(arrows) > 20
    near = np.abs(arrows[:, 1] - 100.0) < 60
    assert np.allclose(np.cos(arrows[near, 2]), 1.0, atol=1e-3)


def test_flow_stroke_of_one_point_is_refused_and_undone(tmp_path):
    s = Session(tmp_path)
    s.handle({"type": "stroke_start", "tool": "flow", "radius": 1, "points": [[5, 5]]})
    with pytest.raises(InputError, match="two distinct points"):
        s.handle({"type": "stroke_end"})
    assert s.flow_strokes == [] and s.undo_stack == [] and s.stroke is None


def test_fill_fills_the_region_and_stays_inside(tmp_path):
    s = _session(tmp_path, size=(200.0, 150.0))
    out = s.handle({"type": "fill", "point": [[100.0, 75.0]]})
    assert "filled" in out[-1]["message"]
    scene = s.scene()
    assert len(scene) >= 15
    inside = s.region.contains(scene.xy)
    assert inside.all()
    # the status bar's readout is the fidelity verdict against the one selected exemplar
    assert s.fidelity is not None and s.fidelity["exemplar"] == "scales"
    assert isinstance(s.fidelity["faithful"], bool) and all(isinstance(f, str) for f in s.fidelity["failures"])
    assert out[-1]["fidelity"] == s.fidelity
    # a second fill finds no room
    n = len(scene)
    s.handle({"type": "fill", "point": [[100.0, 75.0]]})
    assert len(s.scene()) <= n + 2


def test_fill_outside_the_region_is_refused(tmp_path):
    s = _session(tmp_path)
    with pytest.raises(InputError, match="outside the region"):
        s.handle({"type": "fill", "point": [[-50.0, 10.0]]})


def test_region_tool_confines_the_brush(tmp_path):
    s = _session(tmp_path)
    _stroke(s, "region", [(0, 0), (300, 0), (300, 400), (0, 400)], 1.0)
    assert s.region.bounds == (0.0, 0.0, 300.0, 400.0)
    _stroke(s, "brush", [(250.0, 200.0), (350.0, 200.0), (450.0, 200.0)], 40.0)
    scene = s.scene()
    assert len(scene) > 0
    assert np.all(scene.x <= 300.0)


def test_tools_need_a_selection(tmp_path):
    s = Session(tmp_path)
    with pytest.raises(InputError, match="palette: empty"):
        s.handle({"type": "stroke_start", "tool": "brush", "radius": 10, "points": [[1, 1]]})
    s = _session(tmp_path)
    s.handle({"type": "select", "names": []})
    with pytest.raises(InputError, match="selection: empty"):
        s.handle({"type": "stroke_start", "tool": "brush", "radius": 10, "points": [[1, 1]]})
    with pytest.raises(InputError, match="no exemplar"):
        s.handle({"type": "select", "names": ["nope"]})


def test_select_several_exemplars(tmp_path):
    s = _session(tmp_path)
    s.handle({"type": "load_exemplar", "example": "tiles.svg"})
    assert list(s.palette) == ["scales", "tiles"]
    s.handle({"type": "select", "names": ["scales", "tiles"]})
    _stroke(s, "brush", [(100.0 + 40 * i, 200.0) for i in range(10)], 60.0)
    assert s.state.prep.names == ("scales", "tiles")
    assert len(s.scene()) > 0


def test_palette_editing(tmp_path):
    s = _session(tmp_path)
    ex = s.palette["scales"]
    n = len(ex)
    kind = ex.kinds[0]
    s.handle({"type": "palette_edit", "exemplar": "scales", "op": "place", "kind": kind, "x": 500.0, "y": 500.0})
    assert len(s.palette["scales"]) == n + 1 and s.palette["scales"].x[-1] == 500.0
    s.handle({"type": "palette_edit", "exemplar": "scales", "op": "move", "index": n, "x": 510.0, "y": 490.0})
    assert (s.palette["scales"].x[n], s.palette["scales"].y[n]) == (510.0, 490.0)
    s.handle({"type": "palette_edit", "exemplar": "scales", "op": "radius", "index": 0, "value": 7.5})
    msg = s.palette_message()["exemplars"][0]
    assert msg["radius"][0] == 7.5
    s.handle({"type": "palette_edit", "exemplar": "scales", "op": "delete", "index": n})
    assert len(s.palette["scales"]) == n
    with pytest.raises(InputError, match="index"):
        s.handle({"type": "palette_edit", "exemplar": "scales", "op": "delete", "index": n + 5})
    with pytest.raises(InputError, match="value"):
        s.handle({"type": "palette_edit", "exemplar": "scales", "op": "radius", "index": 0, "value": -1})
    # undo walks back through the edits
    for _ in range(4):
        s.handle({"type": "undo"})
    assert len(s.palette["scales"]) == n and "radius" not in s.palette["scales"]


def test_flip_connectivity_edge(tmp_path):
    s = _session(tmp_path)
    edges = {tuple(e) for e in s.palette_message()["exemplars"][0]["edges"]}
    assert edges
    from strew.grow import flip_edge

    ref = s._reference("scales")
    for i, j in sorted(edges):
        try:
            flip_edge(ref, i, j)
        except InputError:
            continue
        break
    s.handle({"type": "palette_flip", "exemplar": "scales", "i": i, "j": j})
    new = {tuple(e) for e in s.palette_message()["exemplars"][0]["edges"]}
    assert (i, j) not in new and len(new) == len(edges)
    assert s.palette["scales"].extra["connectivity"]["edges"]


def test_paint_into_the_palette_and_back(tmp_path):
    s = _session(tmp_path)
    s.handle({"type": "palette_new", "name": "mine"})
    assert len(s.palette["mine"]) == 0
    s.handle({"type": "stroke_start", "tool": "brush", "radius": 40.0, "points": [[0.0, 0.0]], "target": "palette", "exemplar": "mine"})
    sizes = []
    for x in (40.0, 80.0, 120.0, 160.0):
        out = s.handle({"type": "stroke_move", "points": [[x, 0.0]]})
        sizes.append(next(m for m in out if m["type"] == "palette")["exemplars"][-1]["n"])
    s.handle({"type": "stroke_end"})
    assert sizes[0] > 0 and sizes[-1] > sizes[0]  # the palette panel follows the stroke
    assert len(s.palette["mine"]) >= sizes[-1] >= 4
    ex = s.palette["mine"]
    assert np.all(shapely.distance(shapely.LineString([(0, 0), (160, 0)]), shapely.points(ex.xy)) <= 40.0 + 1e-6)
    s.handle({"type": "undo"})
    assert len(s.palette["mine"]) == 0
    # the scene can become an exemplar too
    _stroke(s, "brush", LINE, 40.0)
    s.handle({"type": "palette_from_scene", "name": "painted"})
    assert len(s.palette["painted"]) == len(s.scene())


def test_save_and_load_project(tmp_path):
    s = _session(tmp_path)
    s.handle({"type": "load_exemplar", "example": "tiles.svg"})
    s.handle({"type": "select", "names": ["tiles"]})
    _stroke(s, "flow", [(10.0, 10.0), (200.0, 50.0)], 1.0)
    _stroke(s, "brush", LINE, 40.0)
    s.handle({"type": "save"})
    assert (tmp_path / PALETTE_FILE).is_file() and (tmp_path / SCENE_FILE).is_file()
    scene = load(tmp_path / SCENE_FILE)
    assert len(scene) == len(s.scene())
    t = Session(tmp_path)
    t.handle({"type": "load_project"})
    assert list(t.palette) == ["scales", "tiles"] and t.selection == ["tiles"]
    assert len(t.scene()) == len(s.scene())
    assert np.allclose(t.scene().xy, s.scene().xy)
    assert len(t.flow_strokes) == 1 and t.flow is not None
    # the palette document is one synth can read
    from strew.synth import load_palette

    assert set(load_palette(tmp_path / PALETTE_FILE).names) == {"scales", "tiles"}


def test_export_formats(tmp_path):
    s = _session(tmp_path)
    _stroke(s, "brush", LINE, 40.0)
    n = len(s.scene())
    for name in ("out.svg", "out.png", "out.json"):
        out = s.handle({"type": "export", "path": name})
        assert out[0] == {"type": "exported", "path": name, "count": n}
    assert (tmp_path / "out.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert len(load(tmp_path / "out.json")) == n
    assert json.loads((tmp_path / "out.json").read_text())["meta"]["method"] == "studio"


def test_same_seed_same_scene(tmp_path):
    def run():
        s = _session(tmp_path, seed=11)
        _stroke(s, "brush", LINE, 40.0)
        _stroke(s, "spray", [(100.0, 320.0), (200.0, 320.0)], 30.0)
        return s._arrays()

    a, b = run(), run()
    for c in a:
        assert np.array_equal(a[c], b[c])


def test_scene_messages_patch_and_replace(tmp_path):
    s = _session(tmp_path)
    first = s.scene_message(full=True)
    assert first["op"] == "replace" and first["n"] == 0
    _stroke(s, "brush", LINE, 40.0)
    # the browser's copy, rebuilt from the stream, equals the scene
    s2 = _session(tmp_path)
    got = {c: [] for c in "kxyrs"}
    msgs = []
    s2.scene_message(full=True)
    s2._emit = msgs.append
    pts = [list(p) for p in LINE]
    msgs += s2.handle({"type": "stroke_start", "tool": "brush", "radius": 40.0, "points": pts[:1]}, msgs.append)
    for p in pts[1:]:
        msgs += s2.handle({"type": "stroke_move", "points": [p]}, msgs.append)
    for m in msgs:
        if m["type"] != "scene":
            continue
        if m["op"] == "replace":
            got = {c: list(m[c]) for c in "kxyrs"}
        else:
            for a, i in enumerate(m["update"]["index"]):
                for c in "kxyrs":
                    got[c][i] = m["update"][c][a]
            for c in "kxyrs":
                got[c] += m["append"][c]
    want = s2._arrays()
    for c in "kxyrs":
        assert np.allclose(got[c], want[c])


def test_streamed_columns_equal_the_scene(tmp_path):
    s = _session(tmp_path)
    _stroke(s, "spray", [(100.0, 100.0), (200.0, 100.0)], 30.0)
    s.handle({"type": "load_exemplar", "example": "tiles.svg"})
    s.handle({"type": "select", "names": ["tiles", "scales"]})
    _stroke(s, "brush", LINE, 40.0)
    assert len(s.fixed) and s.state.n
    fast, slow = s._arrays(), s._columns_of(s.scene())
    for c in slow:
        assert np.array_equal(fast[c], slow[c])


def test_stop_cancels_a_fill(tmp_path):
    s = _session(tmp_path, size=(1500.0, 1000.0))

    def stop_at_once(msg):
        s.cancel.set()

    out = s.handle({"type": "fill", "point": [[750.0, 500.0]]}, stop_at_once)
    assert out[-1]["message"].startswith("fill stopped")
    stopped = len(s.scene())
    s.handle({"type": "undo"})
    s.handle({"type": "fill", "point": [[750.0, 500.0]]})
    assert len(s.scene()) > 2 * stopped


def test_failed_stroke_leaves_no_trace(tmp_path):
    s = Session(tmp_path)
    s.handle({"type": "load_exemplar", "example": "scales.svg"})
    s.handle({"type": "palette_new", "name": "few"})
    kind = s.kinds[0]
    for x, y in ((0, 0), (30, 0), (0, 30)):
        s.handle({"type": "palette_edit", "exemplar": "few", "op": "place", "kind": kind, "x": x, "y": y})
    s.handle({"type": "select", "names": ["few"]})
    depth = len(s.undo_stack)
    with pytest.raises(InputError, match="at least four elements"):
        s.handle({"type": "stroke_start", "tool": "spray", "radius": 40, "points": [[100, 100]]})
    assert len(s.undo_stack) == depth and s.stroke is None and len(s.scene()) == 0


def test_boundary_strokes_confine_the_filler_and_the_brush(tmp_path):
    s = _session(tmp_path, size=(400.0, 300.0))
    _stroke(s, "boundary", [(200.0, -10.0), (200.0, 310.0)], 1.0)
    s.handle({"type": "fill", "point": [[100.0, 150.0]]})
    scene = s.scene()
    assert len(scene) >= 10
    assert np.all(scene.x < 200.0)
    assert scene.x.max() > 150.0  # it did fill up to the wall
    n = len(scene)
    # a brush stroke that starts on the right stays on the right
    _stroke(s, "brush", [(300.0, 150.0), (250.0, 150.0), (150.0, 150.0)], 40.0)
    new = s.scene().select(np.arange(len(s.scene())) >= n) if len(s.scene()) > n else None
    assert new is not None and len(new) > 0
    assert np.all(new.x > 200.0)


def test_session_refuses_unknown_types_itself(tmp_path):
    s = Session(tmp_path)
    for t in ("__init__", "_on_hello", "handle", None):
        with pytest.raises(InputError, match="message.type"):
            s.handle({"type": t})


def test_spray_in_flow_mode_follows_the_field(tmp_path):
    s = _session(tmp_path)
    s.handle({"type": "settings", "grow_mode": "flow"})
    with pytest.raises(InputError, match="flow strokes first"):
        s.handle({"type": "stroke_start", "tool": "spray", "radius": 30, "points": [[100, 100]]})
    _stroke(s, "flow", [(0.0, 0.0), (0.0, 400.0)], 1.0)  # straight down: angle pi/2
    _stroke(s, "spray", [(300.0, 100.0), (300.0, 250.0)], 40.0)
    scene = s.scene()
    assert len(scene) >= 5
    ex = s.palette["scales"]
    # §5.3 flow mode: the reference's x axis turns to the flow direction (+pi/2 here)
    base = float(np.median(ex.rotation))
    assert np.allclose(np.mod(scene.rotation - base - np.pi / 2 + np.pi, 2 * np.pi) - np.pi, 0.0, atol=0.35)


def test_spray_jitter_varies_scale_and_rotation(tmp_path):
    s = _session(tmp_path)
    s.handle({"type": "settings", "jitter_scale": 0.3, "jitter_rotation": 20})
    _stroke(s, "spray", [(200.0, 200.0), (300.0, 200.0)], 40.0)
    scene = s.scene()
    assert len(scene) >= 5
    base = s.palette["scales"]
    assert np.ptp(scene.scale) > 0.05 and np.all(np.abs(scene.scale / np.median(base.scale) - 1) <= 0.3 + 1e-9)
    assert np.ptp(scene.rotation) > 0.05 and np.all(np.abs(scene.rotation) <= np.deg2rad(20) + 1e-9)
    with pytest.raises(InputError, match="jitter_scale"):
        s.handle({"type": "settings", "jitter_scale": 1.5})


def test_void_elements_are_hidden_and_not_counted(tmp_path):
    from strew import Arrangement, Shape, save

    g = np.mgrid[0:7, 0:7].reshape(2, -1).T * 12.0
    void = (np.arange(len(g)) % 3) == 0
    ex = Arrangement({"dot": Shape.circle(4.0)}, [0] * len(g), g[:, 0], g[:, 1], columns={"void": void})
    save(ex, tmp_path / "voids.json")
    s = Session(tmp_path, seed=1)
    s.handle({"type": "load_exemplar", "path": "voids.json"})
    _stroke(s, "brush", LINE, 40.0)
    assert s.state.n > len(s.scene()) > 10  # some synthesized elements are voids (§5.6)
    assert s.status_message()["count"] == len(s.scene()) == len(s._arrays()["k"])


def test_filler_stops_at_the_scene_limit(tmp_path, monkeypatch):
    import strew.studio._session as session_module

    monkeypatch.setattr(session_module, "MAX_SCENE", 150)
    s = _session(tmp_path, size=(900.0, 700.0))
    replies = s.handle({"type": "fill", "point": [[450.0, 350.0]]})
    assert len(s.scene()) <= 150
    assert "limit" in replies[-1]["message"]
    with pytest.raises(InputError, match="over 150 elements"):
        s.handle({"type": "fill", "point": [[450.0, 350.0]]})
