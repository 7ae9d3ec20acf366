"""Library hooks the studio relies on instead of private state (issue 15.6):
``strew.grow.SprayGrowth.reach`` and the studio's locked-layer eraser through
``strew.synth.erase(..., keep=)``."""

from __future__ import annotations

import numpy as np
import pytest
import shapely

from strew.grow import SprayGrowth, analyze
from strew.grow._exemplars import hex_exemplar, stone_exemplar, tile_exemplar

PATH = np.array([(20.0 + 8.0 * i, 100.0 + 20.0 * np.sin(i / 6)) for i in range(24)])


def _spray(make, jitter_scale=0.0):
    g = SprayGrowth(analyze(make()), radius=25.0, jitter_scale=jitter_scale, rng=2)
    for i in range(0, len(PATH), 4):
        g.add_points(PATH[i : i + 4])
        g.grow()
    return g, g.arrangement()


@pytest.mark.parametrize("make", [hex_exemplar, stone_exemplar, tile_exemplar])
@pytest.mark.parametrize("jitter_scale", [0.0, 0.4])
def test_spray_reach_bounds_every_element_it_places(make, jitter_scale):
    g, out = _spray(make, jitter_scale)
    assert len(out) > 10
    assert isinstance(g.reach, float) and g.reach > 0
    assert np.all(out.radii <= g.reach + 1e-9)
    # every element lies within radius + reach of the stroke (what the studio's obstacle
    # margin assumes)
    d = shapely.distance(shapely.LineString(PATH), shapely.points(out.xy))
    assert np.all(d <= g.radius + g.reach + 1e-9)


def test_spray_reach_is_tight_without_jitter_and_grows_with_it():
    g0, out = _spray(hex_exemplar)
    assert np.isclose(out.radii.max(), g0.reach)  # one kind at scale 1: every element is that wide
    g1 = SprayGrowth(analyze(hex_exemplar()), radius=25.0, jitter_scale=0.5, rng=2)
    assert np.isclose(g1.reach, 1.5 * g0.reach)


def test_locked_eraser_keeps_the_layer_and_the_hole_fills_again(tmp_path):
    """The eraser with a locked layer is synth's eraser (Davison §5.4) with a keep mask:
    locked elements stay, the rest near the path go, and the free space around the hole
    lives again, so a fill puts elements back in it without touching the locked ones."""
    from strew import metrics
    from strew.studio._session import Session

    s = Session(tmp_path, seed=3, size=(300.0, 220.0))
    s.handle({"type": "load_exemplar", "example": "stones.svg"})
    s.handle({"type": "fill", "point": [[150.0, 110.0]]})
    scene = s.scene()
    kinds = sorted(set(scene.kind_names.tolist()))
    assert len(kinds) >= 2
    s.handle({"type": "layers", "locked": [kinds[0]]})
    locked = scene.select(scene.kind_names == kinds[0])
    band = np.array([[20.0, 110.0], [280.0, 110.0]])
    s.handle({"type": "stroke_start", "tool": "erase", "radius": 30.0, "points": band[:1].tolist()})
    s.handle({"type": "stroke_move", "points": band[1:].tolist()})
    s.handle({"type": "stroke_end"})
    after = s.scene()
    d = shapely.distance(shapely.LineString(band), shapely.points(after.xy))
    near = after.select(d <= 30.0)
    assert set(near.kind_names.tolist()) <= {kinds[0]}
    assert int((after.kind_names == kinds[0]).sum()) == len(locked)
    n_band = len(near)
    s.handle({"type": "fill", "point": [[150.0, 110.0]]})
    again = s.scene()
    d2 = shapely.distance(shapely.LineString(band), shapely.points(again.xy))
    assert int((d2 <= 30.0).sum()) > n_band + 5
    kept = again.select(again.kind_names == kinds[0])
    assert {tuple(p) for p in np.round(locked.xy, 6)} <= {tuple(p) for p in np.round(kept.xy, 6)}
    assert len(metrics.overlaps(again)[0]) == 0


def test_saved_palette_keeps_empty_exemplars_selection_and_connectivity(tmp_path):
    """The studio saves and loads its palette through strew.synth.palette_document and
    split_palette_document: an exemplar still empty keeps its name and place."""
    from strew.studio._session import Session
    from strew.synth import load_palette

    s = Session(tmp_path, seed=3, size=(300.0, 220.0))
    s.handle({"type": "load_exemplar", "example": "scales.svg"})
    s.handle({"type": "palette_new", "name": "mine"})
    s.handle({"type": "select", "names": ["scales"]})
    from strew import InputError
    from strew.grow import flip_edge

    ref = s._reference("scales")
    for i, j in sorted({tuple(e) for e in s.palette_message()["exemplars"][0]["edges"]}):
        try:
            flip_edge(ref, i, j)
        except InputError:
            continue
        break
    s.handle({"type": "palette_flip", "exemplar": "scales", "i": i, "j": j})  # edited connectivity
    edges = s.palette["scales"].extra["connectivity"]["edges"]
    assert edges
    s.handle({"type": "save"})
    t = Session(tmp_path)
    t.handle({"type": "load_project"})
    assert list(t.palette) == ["scales", "mine"]
    assert len(t.palette["mine"]) == 0 and t.selection == ["scales"]
    assert np.allclose(t.palette["scales"].xy, s.palette["scales"].xy)
    assert t.palette["scales"].extra["connectivity"]["edges"] == edges
    assert load_palette(tmp_path / "palette.json").names == ("scales",)
