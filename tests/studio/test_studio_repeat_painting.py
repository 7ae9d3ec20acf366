"""Painting in the studio's repeat view gives a seamless tile (issue 18 point 4): brush,
spray, filler and eraser work on the torus of the tile, so that 3 x 3 copies of the
exported tile do not overlap and its edge strips are as dense as its interior."""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest

import strew
from strew import _periodic as P
from strew import metrics
from strew.studio._session import Session

EXEMPLAR = Path(__file__).resolve().parents[2] / "examples" / "synth" / "pebbles.json"
W = H = 140.0
RADIUS = 20.0


def _session(tmp_path: Path, seed: int = 1) -> Session:
    shutil.copy(EXEMPLAR, tmp_path / "pebbles.json")
    s = Session(tmp_path, seed=seed, size=(W, H))
    s.handle({"type": "load_exemplar", "path": "pebbles.json"})
    s.handle({"type": "settings", "repeat": True})
    return s


def _stroke(s: Session, tool: str, points: np.ndarray, radius: float) -> None:
    pts = [list(map(float, p)) for p in points]
    s.handle({"type": "stroke_start", "tool": tool, "radius": radius, "points": pts[:1]})
    for k in range(1, len(pts), 8):
        s.handle({"type": "stroke_move", "points": pts[k:k + 8]})
    s.handle({"type": "stroke_end"})


def _rows(s: Session, tool: str) -> None:
    """Strokes across the tile and 20 past both side edges, rows 1.2 radii apart."""
    xs = np.arange(-20.0, W + 20.0, 8.0)
    for y in np.arange(0.5 * RADIUS, H, 1.2 * RADIUS):
        _stroke(s, tool, np.c_[xs, np.full(len(xs), y)], RADIUS)


def _exported(s: Session, tmp_path: Path):
    s.handle({"type": "export", "path": "tile.json"})
    tile = strew.load(tmp_path / "tile.json")
    assert P.frame(tile) == (0.0, 0.0, W, H)
    assert len(tile) == s._scene_count() > 100
    assert np.all((tile.x >= 0) & (tile.x < W) & (tile.y >= 0) & (tile.y < H))
    assert len(metrics.overlaps(P.tiled_copies(tile))[0]) == 0
    return tile


@pytest.mark.parametrize("tool", [pytest.param("brush", marks=pytest.mark.slow), "spray"])  # brush: about 10 s
def test_painting_the_whole_tile_in_the_repeat_view_leaves_no_seam(tmp_path, tool):
    s = _session(tmp_path)
    _rows(s, tool)
    tile = _exported(s, tmp_path)
    rep = metrics.repeat_report(tile)
    assert rep["overlaps"]["across"] == 0
    assert rep["density"]["ratio"] >= 0.85, rep["density"]
    # elements cross the tile's edges (they wrap in at the opposite ones)
    assert np.sum(metrics.outside(tile.replace(meta={}), strew.Region.rectangle(W, H))) > 0


def test_a_fill_clicked_on_a_copy_fills_the_tile_and_the_eraser_wraps(tmp_path):
    s = _session(tmp_path, seed=2)
    s.handle({"type": "fill", "point": [[W + 30.0, -20.0]]})  # the copy right of and above the tile
    tile = _exported(s, tmp_path)
    assert metrics.repeat_report(tile)["density"]["ratio"] >= 0.85
    # an eraser stroke in the copy to the left erases across the right edge
    _stroke(s, "erase", np.array([[-10.0, 40.0], [-10.0, 100.0]]), 15.0)
    sc = s.scene()
    d = np.hypot(P.wrap_delta(sc.x + 10.0, W), np.clip(sc.y, 40.0, 100.0) - sc.y)
    assert np.all(d > 15.0) and np.sum(sc.x > W - 30) > 0


def test_a_tile_too_small_for_the_texture_is_refused(tmp_path):
    shutil.copy(EXEMPLAR, tmp_path / "pebbles.json")
    s = Session(tmp_path, seed=1, size=(35.0, 35.0))
    s.handle({"type": "load_exemplar", "path": "pebbles.json"})
    s.handle({"type": "fill", "point": [[17.0, 17.0]]})
    with pytest.raises(strew.InputError, match="too small"):
        s.handle({"type": "settings", "repeat": True})
    assert s.status_message()["repeat"] is None and s.state.tile is None
