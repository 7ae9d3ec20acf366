"""The studio's readouts and behaviour in a real browser (issue 22 points 5 and 6).

Playwright drives Debian's chromium headless: the preloaded palette paints at the first
stroke; the status bar's count, elements/s, fidelity verdict and zoom are right; the
help overlay lists every tool; a new region offers to clip; boundary strokes hold; the
brush density thins; the layers panel hides, locks and reorders. Then one screenshot per
tool, with a fixed seed and viewport, is compared with the baselines in
``tests/data/studio_baselines`` (``STREW_UPDATE_BASELINES=1`` rewrites them).
"""

from __future__ import annotations

import json
import os
import re
from pathlib import Path

import numpy as np
import pytest
import shapely

from strew import load, metrics
from strew.studio._background import CHROMIUM, CHROMIUM_ARGS

from test_studio_browser import _drag, _ink, _screen, _wait_message  # noqa: E402

pytestmark = [
    pytest.mark.browser,
    pytest.mark.skipif(not os.path.exists(CHROMIUM), reason=f"{CHROMIUM} is not installed"),
]

BASELINES = Path(__file__).resolve().parents[1] / "data" / "studio_baselines"
#: Mean absolute difference (0-255, over RGB) a screenshot may have from its baseline.
TOLERANCE = 2.0
VIEWPORT = {"width": 1000, "height": 640}


@pytest.fixture(scope="module")
def browser():
    pytest.importorskip("fastapi")
    sync_api = pytest.importorskip("playwright.sync_api")
    with sync_api.sync_playwright() as pw:
        b = pw.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        yield b
        b.close()


def _open(browser, tmp_path_factory, seed):
    """A fresh studio (its own server and project folder) in a new page; returns (page, close)."""
    from strew.studio._background import BackgroundStudio

    project = tmp_path_factory.mktemp("studio_readouts")
    server = BackgroundStudio(project, seed=seed)
    pg = browser.new_page(viewport=VIEWPORT, device_scale_factor=1)
    errors: list[str] = []
    pg.on("pageerror", lambda e: errors.append(str(e)))
    pg.goto(server.url)
    pg.wait_for_function("window.studio && window.studio.connected && window.studio.strokes.region.length > 0")
    pg.project, pg.page_errors, pg.server = project, errors, server

    def close():
        pg.close()
        server.stop()

    return pg, close


@pytest.fixture(scope="module")
def page(browser, tmp_path_factory):
    pg, close = _open(browser, tmp_path_factory, seed=4)
    yield pg
    close()


def _request(page, msg):
    return page.evaluate(f"window.studio.request({json.dumps(msg)})")


def _saved(page):
    _request(page, {"type": "save"})
    return load(page.project / "scene.json")


def _status(page):
    return page.evaluate("window.studio.status")


def test_first_stroke_count_rate_fidelity_zoom_and_help(page):
    # the example palette is there at first start: no click before the first stroke
    page.wait_for_function("window.studio.palette.selection.length === 1")
    assert page.evaluate("window.studio.palette.selection") == ["scales"]
    start = len(page.evaluate("window.studio.messages"))
    _drag(page, [(100.0 + 30 * i, 120.0) for i in range(10)])
    _wait_message(page, "brush:", start)
    page.wait_for_function("window.studio.pending.size === 0")
    n = page.evaluate("window.studio.scene.n")
    assert n > 5
    assert page.inner_text("#st-count") == f"{n} elements" == f"{metrics.visible_count(_saved(page))} elements"

    # a fill: the count never goes back, equals the saved scene's, and el/s is this fill's
    page.evaluate("window.studio.counts.length = 0")
    page.click("#tools button[data-tool=fill]")
    start = len(page.evaluate("window.studio.messages"))
    page.mouse.click(*_screen(page, 400.0, 400.0))
    _wait_message(page, "filled:", start)
    page.wait_for_function("window.studio.pending.size === 0")
    msg = [m for m in page.evaluate("window.studio.messages") if m.startswith("filled:")][-1]
    added, secs = re.match(r"filled: (\d+) elements in ([\d.]+) s", msg).groups()
    counts = page.evaluate("window.studio.counts")
    back = sum(a - b for a, b in zip(counts, counts[1:]) if b < a)
    assert back <= max(2, 0.01 * counts[-1]), f"the count went back by {back} during the fill"  # see test_studio_readouts
    total = n + int(added)
    assert counts[-1] == total == page.evaluate("window.studio.scene.n") == metrics.visible_count(_saved(page))
    assert page.inner_text("#st-count") == f"{total} elements"
    rate = int(page.inner_text("#st-rate").split()[0])
    assert rate == pytest.approx(int(added) / float(secs), rel=0.05, abs=2)

    # the fidelity verdict of that fill, as strew.metrics.fidelity gives it
    fid = _status(page)["fidelity"]
    assert fid is not None and fid["exemplar"] == "scales"
    text = page.inner_text("#st-fid")
    if fid["faithful"]:
        assert text == "faithful to scales"
    else:
        assert text.startswith("not faithful to scales: ") and fid["failures"][0] in text
    assert "neighbourhood distance" not in page.inner_text("#status")

    # zoom level
    zoom = page.evaluate("window.studio.view.zoom")
    shown = float(re.match(r"zoom ([\d.]+)%", page.inner_text("#st-zoom")).group(1))
    assert shown == pytest.approx(zoom * 100, rel=0.01)
    page.mouse.move(*_screen(page, 400.0, 300.0))
    page.mouse.wheel(0, -300)
    page.wait_for_function(f"window.studio.view.zoom > {zoom} * 1.2")
    page.wait_for_timeout(50)
    shown = float(re.match(r"zoom ([\d.]+)%", page.inner_text("#st-zoom")).group(1))
    assert shown == pytest.approx(page.evaluate("window.studio.view.zoom") * 100, rel=0.01)
    page.click("#fit")

    # help overlay on '?': every tool and its key
    assert page.is_hidden("#help")
    page.locator("#scene").focus()
    page.keyboard.press("?")
    assert page.is_visible("#help")
    help_text = page.inner_text("#help")
    for b in page.query_selector_all("#tools button"):
        assert b.inner_text() in help_text
    for key in ("B", "S", "F", "E", "W", "O", "R", "Space", "Ctrl+Z", "?"):
        assert re.search(rf"(^|\s){re.escape(key)}\s", help_text), key
    page.keyboard.press("Escape")
    assert page.is_hidden("#help")
    page.click("#help-button")
    assert page.is_visible("#help")
    page.keyboard.press("Escape")
    assert page.is_hidden("#help")
    assert page.page_errors == []


def test_clip_boundary_density_and_layers(page):
    _request(page, {"type": "clear", "what": "scene"})
    _request(page, {"type": "region", "size": [600, 400]})
    page.click("#fit")
    # a second exemplar brings more kinds (layers); the selection stays
    _request(page, {"type": "load_exemplar", "example": "stones.svg"})
    assert page.evaluate("window.studio.palette.selection") == ["scales"]
    # a boundary stroke, then a fill on its left: nothing crosses, nothing overhangs
    page.click("#tools button[data-tool=boundary]")
    wall = [(250.0, 0.0), (260.0, 200.0), (250.0, 400.0)]
    _drag(page, wall)
    page.wait_for_function("window.studio.strokes.boundary.length === 1")
    drawn = np.asarray(page.evaluate("window.studio.strokes.boundary[0]"))
    page.click("#tools button[data-tool=fill]")
    start = len(page.evaluate("window.studio.messages"))
    page.mouse.click(*_screen(page, 120.0, 200.0))
    _wait_message(page, "filled:", start)
    page.wait_for_function("window.studio.pending.size === 0")
    scene = _saved(page)
    assert len(scene) > 30
    assert not shapely.intersects(scene.geometry, shapely.LineString(drawn)).any()
    assert scene.region.contains_geometry(scene.geometry, tolerance=1e-6).all()
    assert page.is_hidden("#clip")

    # a smaller region: the status bar offers to clip what lies outside
    page.click("#tools button[data-tool=region]")
    _drag(page, [(0.0, 0.0), (150.0, 0.0), (150.0, 200.0), (0.0, 200.0)])
    page.wait_for_function("!document.getElementById('clip').hidden")
    outside = _status(page)["outside"]
    assert page.inner_text("#clip") == f"Clip {outside} outside"
    before = page.evaluate("window.studio.scene.n")
    page.click("#clip")
    page.wait_for_function("document.getElementById('clip').hidden")
    page.wait_for_function(f"window.studio.scene.n === {before - outside}")
    scene = _saved(page)
    assert scene.region.contains_geometry(scene.geometry, tolerance=1e-6).all()
    assert page.inner_text("#st-count") == f"{metrics.visible_count(scene)} elements"
    _request(page, {"type": "region", "size": [600, 400]})
    _request(page, {"type": "clear", "what": "boundary"})

    # brush density: the slider reaches the server and thins the stroke
    def stroke(y):
        start = len(page.evaluate("window.studio.messages"))
        page.click("#tools button[data-tool=brush]")
        n0 = page.evaluate("window.studio.scene.n")
        _drag(page, [(300.0 + 30 * i, y) for i in range(9)])
        _wait_message(page, "brush:", start)
        page.wait_for_function("window.studio.pending.size === 0")
        return page.evaluate("window.studio.scene.n") - n0

    full = stroke(240.0)
    page.evaluate("(() => { const d = document.getElementById('density'); d.value = 0.3; d.dispatchEvent(new Event('input')); d.dispatchEvent(new Event('change')); })()")
    page.wait_for_function("window.studio.pending.size === 0")
    assert page.inner_text("#density-out") == "30%"
    page.wait_for_timeout(100)
    assert page.server.app.state.session.brush_density == pytest.approx(0.3)
    thin = stroke(340.0)
    assert full > 10 and thin < 0.7 * full

    # a pen's pressure scales the density (synthetic pen events, as a tablet sends them)
    page.evaluate("(() => { const d = document.getElementById('density'); d.value = 1; d.dispatchEvent(new Event('input')); d.dispatchEvent(new Event('change')); })()")
    page.wait_for_function("window.studio.pending.size === 0")
    n0 = page.evaluate("window.studio.scene.n")
    start = len(page.evaluate("window.studio.messages"))
    screen = [list(_screen(page, 300.0 + 30 * i, 140.0)) for i in range(9)]
    page.evaluate(
        """async (pts) => {
        const c = document.getElementById('scene');
        const ev = (type, p) => c.dispatchEvent(new PointerEvent(type, {clientX: p[0], clientY: p[1], button: 0, buttons: 1, pointerId: 7, pointerType: 'pen', pressure: 0.3, bubbles: true}));
        ev('pointerdown', pts[0]);
        for (const p of pts.slice(1)) { await new Promise(r => requestAnimationFrame(r)); ev('pointermove', p); }
        ev('pointerup', pts[pts.length - 1]);
    }""",
        screen,
    )
    _wait_message(page, "brush:", start)
    page.wait_for_function("window.studio.pending.size === 0")
    pen = page.evaluate("window.studio.scene.n") - n0
    assert 0 < pen < 0.7 * full

    # layers: one per kind, hide (nothing drawn), lock (the eraser keeps it), reorder
    page.wait_for_function("window.studio.layers.length > 0")
    names = [e.get_attribute("data-name") for e in page.query_selector_all("#layers li")]
    assert names == [ly["name"] for ly in page.evaluate("window.studio.layers")]
    present = sorted(set(_saved(page).kind_names.tolist()))
    assert set(present) <= set(names)
    assert _ink(page, 300, 225, 540, 255) > 0.05
    for name in present:
        page.click(f"#layers li[data-name='{name}'] input.show")
        page.wait_for_function(f"window.studio.layers.find(l => l.name === {name!r}).hidden")
    page.wait_for_timeout(100)
    assert _ink(page, 300, 225, 540, 255) == 0.0
    for name in present:
        page.click(f"#layers li[data-name='{name}'] input.show")
        page.wait_for_function(f"!window.studio.layers.find(l => l.name === {name!r}).hidden")
    page.wait_for_timeout(100)
    assert _ink(page, 300, 225, 540, 255) > 0.05
    locked = present[0]
    page.click(f"#layers li[data-name='{locked}'] input.lock")
    page.wait_for_function(f"window.studio.layers.find(l => l.name === {locked!r}).locked")
    keep = int((_saved(page).kind_names == locked).sum())
    page.click("#tools button[data-tool=erase]")
    page.evaluate("(() => { const r = document.getElementById('radius'); r.value = 300; r.dispatchEvent(new Event('input')); })()")
    start = len(page.evaluate("window.studio.messages"))
    _drag(page, [(50.0, 200.0), (300.0, 200.0), (550.0, 200.0)])
    _wait_message(page, "erase:", start)
    left = _saved(page)
    assert set(left.kind_names.tolist()) <= {locked} and int((left.kind_names == locked).sum()) == keep
    assert len(names) >= 2
    first = names[0]
    page.click(f"#layers li[data-name='{first}'] button.down")
    page.wait_for_function(f"window.studio.layers[1] && window.studio.layers[1].name === {first!r}")
    assert page.server.app.state.session.layers["order"][1] == first
    assert page.page_errors == []


# ---------------------------------------------------------------------------- screenshots
def _shot(page):
    """The scene canvas as an (h, w, 3) uint8 array, averaged down 4x4 (small baselines)."""
    import io

    from PIL import Image

    page.evaluate("new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)))")
    png = page.locator("#scene").screenshot()
    img = np.asarray(Image.open(io.BytesIO(png)).convert("RGB"), dtype=float)
    h, w = (img.shape[0] // 4) * 4, (img.shape[1] // 4) * 4
    return img[:h, :w].reshape(h // 4, 4, w // 4, 4, 3).mean(axis=(1, 3)).round().astype(np.uint8)


def _stroke(page, tool, points, radius=40.0):
    pts = [list(map(float, p)) for p in points]
    assert _request(page, {"type": "stroke_start", "tool": tool, "radius": radius, "points": pts[:1]})["type"] == "done"
    for p in pts[1:]:
        assert _request(page, {"type": "stroke_move", "points": [p]})["type"] == "done"
    assert _request(page, {"type": "stroke_end"})["type"] == "done"


# each tool in turn on one session (fixed seed), driven by messages sent one at a time,
# so that the server sees the same segments on every run
STEPS = [
    ("brush", lambda pg: _stroke(pg, "brush", [(80.0 + 30 * i, 100.0) for i in range(9)])),
    ("spray", lambda pg: _stroke(pg, "spray", [(80.0 + 30 * i, 230.0) for i in range(9)])),
    ("boundary", lambda pg: _stroke(pg, "boundary", [(500.0, 0.0), (520.0, 300.0), (500.0, 600.0)], 5.0)),
    ("fill", lambda pg: _request(pg, {"type": "fill", "point": [[650.0, 300.0]]})),
    ("erase", lambda pg: _stroke(pg, "erase", [(560.0, 100.0), (760.0, 500.0)], 40.0)),
    ("flow", lambda pg: _stroke(pg, "flow", [(100.0, 450.0), (250.0, 520.0), (420.0, 450.0)], 5.0)),
    ("region", lambda pg: _stroke(pg, "region", [(20.0, 20.0), (780.0, 40.0), (760.0, 580.0), (40.0, 560.0)], 5.0)),
    ("pan", lambda pg: _pan(pg, 80, 40)),
]


def _pan(page, dx, dy):
    """The pan tool: drag the view by (dx, dy) screen pixels and let the layer redraw."""
    page.click("#tools button[data-tool=pan]")
    box = page.locator("#scene").bounding_box()
    x, y = box["x"] + 200, box["y"] + 200
    page.mouse.move(x, y)
    page.mouse.down()
    page.mouse.move(x + dx, y + dy, steps=4)
    page.mouse.up()
    page.mouse.move(box["x"] + box["width"] + 50, y)  # off the canvas: no brush outline
    page.wait_for_timeout(300)  # the layer is redrawn once the pan rests (120 ms)


@pytest.mark.slow
def test_screenshot_per_tool_matches_its_baseline(browser, tmp_path_factory):
    from PIL import Image

    update = os.environ.get("STREW_UPDATE_BASELINES") == "1"
    pg, close = _open(browser, tmp_path_factory, seed=7)
    try:
        pg.wait_for_function("window.studio.palette.selection.length === 1")
        pg.click("#fit")
        shots = {"empty": _shot(pg)}
        for tool, act in STEPS:
            act(pg)
            pg.wait_for_function("window.studio.pending.size === 0")
            shots[tool] = _shot(pg)
        assert pg.page_errors == []
    finally:
        close()
    names = ["empty"] + [t for t, _ in STEPS]
    # every tool changes the picture by more than the tolerance, so the comparison can fail
    for a, b in zip(names, names[1:]):
        assert np.abs(shots[a].astype(float) - shots[b]).mean() > TOLERANCE / 4, f"{b} left the picture as {a} had it"
    if update:
        BASELINES.mkdir(parents=True, exist_ok=True)
        for name in names:
            Image.fromarray(shots[name]).save(BASELINES / f"{name}.png", optimize=True)
    for name in names:
        path = BASELINES / f"{name}.png"
        assert path.exists(), f"no baseline {path.name}; run with STREW_UPDATE_BASELINES=1"
        base = np.asarray(Image.open(path).convert("RGB"), dtype=float)
        assert base.shape == shots[name].shape, f"{name}: screenshot {shots[name].shape} against baseline {base.shape}"
        diff = np.abs(base - shots[name]).mean()
        print(f"{name}: mean abs difference {diff:.3f}")
        assert diff < TOLERANCE, f"{name}: mean abs pixel difference {diff:.2f} from its baseline (tolerance {TOLERANCE})"
