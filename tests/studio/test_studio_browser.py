"""The studio in a real browser: Playwright drives Debian's chromium headless.

Loads an exemplar and paints a stroke; elements appear along the stroke and not
elsewhere, on screen; erases part of them and undoes; exports SVG and checks the file.
"""

from __future__ import annotations

import os
import xml.etree.ElementTree as ET

import numpy as np
import pytest
import shapely

from strew.studio._background import CHROMIUM, CHROMIUM_ARGS

pytestmark = [
    pytest.mark.browser,
    pytest.mark.skipif(not os.path.exists(CHROMIUM), reason=f"{CHROMIUM} is not installed"),
]


@pytest.fixture(scope="module")
def page(tmp_path_factory):
    pytest.importorskip("fastapi")
    sync_api = pytest.importorskip("playwright.sync_api")
    from strew.studio._background import BackgroundStudio

    project = tmp_path_factory.mktemp("studio_project")
    with BackgroundStudio(project, seed=2) as server:
        with sync_api.sync_playwright() as p:
            browser = p.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
            pg = browser.new_page(viewport={"width": 1200, "height": 760})
            errors: list[str] = []
            pg.on("pageerror", lambda e: errors.append(str(e)))
            pg.goto(server.url)
            pg.wait_for_function("window.studio && window.studio.connected && window.studio.strokes.region.length > 0")
            pg.project = project
            pg.page_errors = errors
            yield pg
            browser.close()


def _screen(page, x, y):
    box = page.locator("#scene").bounding_box()
    sx, sy = page.evaluate(f"window.studio.view.toScreen({x}, {y})")
    return box["x"] + sx, box["y"] + sy


def _drag(page, points, steps=3):
    page.mouse.move(*_screen(page, *points[0]))
    page.mouse.down()
    for p in points[1:]:
        page.mouse.move(*_screen(page, *p), steps=steps)
        page.wait_for_timeout(10)
    page.mouse.up()


def _wait_message(page, prefix, start):
    page.wait_for_function(f"window.studio.messages.slice({start}).some(m => m.startsWith({prefix!r}))", timeout=60000)


def _scene(page):
    d = page.evaluate("(() => { const s = window.studio.scene; return {n: s.n, x: Array.from(s.x.subarray(0, s.n)), y: Array.from(s.y.subarray(0, s.n))}; })()")
    return np.c_[d["x"], d["y"]]


def _ink(page, x0, y0, x1, y1):
    """Fraction of canvas pixels in a world box that differ from the white background."""
    return page.evaluate(
        f"""(() => {{
        const c = document.getElementById('scene'), ctx = c.getContext('2d'), v = window.studio.view;
        const d = window.devicePixelRatio || 1;
        const [a, b] = v.toScreen({x0}, {y0}), [e, f] = v.toScreen({x1}, {y1});
        const img = ctx.getImageData(Math.round(a * d), Math.round(b * d), Math.max(1, Math.round((e - a) * d)), Math.max(1, Math.round((f - b) * d))).data;
        let ink = 0;
        for (let i = 0; i < img.length; i += 4) if (img[i] < 235 || img[i + 1] < 235 || img[i + 2] < 235) ink++;
        return ink / (img.length / 4);
    }})()"""
    )


STROKE = [(150.0 + 25 * i, 300.0) for i in range(13)]  # (150, 300) to (450, 300)
RADIUS = 40.0


def test_paint_erase_undo_export(page):
    assert page.evaluate("window.studio.scene.n") == 0
    # load an exemplar into the palette through the panel
    page.select_option("#files", "example:scales.svg")
    page.click("#load-exemplar")
    page.wait_for_function("window.studio.palette.exemplars.some(e => e.name === 'scales' && e.selected)")
    page.evaluate(f"(() => {{ const r = document.getElementById('radius'); r.value = {RADIUS}; r.dispatchEvent(new Event('input')); }})()")

    # paint a stroke with the generative brush
    page.click("#tools button[data-tool=brush]")
    start = len(page.evaluate("window.studio.messages"))
    _drag(page, STROKE)
    _wait_message(page, "brush:", start)
    page.wait_for_timeout(100)
    xy = _scene(page)
    assert len(xy) >= 15
    line = shapely.LineString(STROKE)
    d = shapely.distance(line, shapely.points(xy))
    assert np.all(d <= RADIUS + 1.0), "an element appeared away from the stroke"
    assert xy[:, 0].min() < 200 and xy[:, 0].max() > 400, "elements do not follow the whole stroke"
    # on screen: ink along the stroke, none elsewhere in the region
    assert _ink(page, 160, 285, 440, 315) > 0.2
    assert _ink(page, 100, 60, 700, 200) == 0.0
    assert _ink(page, 100, 400, 700, 560) == 0.0
    # the status bar counts them
    assert page.inner_text("#st-count") == f"{len(xy)} elements"
    assert page.evaluate("window.studio.stats.firstFrame !== null && window.studio.stats.rate > 0")

    # erase part of them
    before = xy.copy()
    page.evaluate("(() => { const r = document.getElementById('radius'); r.value = 25; r.dispatchEvent(new Event('input')); })()")
    page.click("#tools button[data-tool=erase]")
    start = len(page.evaluate("window.studio.messages"))
    cut = [(300.0, 230.0), (300.0, 300.0), (300.0, 370.0)]
    _drag(page, cut)
    _wait_message(page, "erase:", start)
    page.wait_for_function(f"window.studio.scene.n < {len(before)}")
    after = _scene(page)
    # the pointer's path reaches the server through screen pixels: allow one unit either way
    d_before = shapely.distance(shapely.LineString(cut), shapely.points(before))
    assert (d_before < 24.0).sum() >= 3
    kept = {tuple(p) for p in after.round(3)}
    for p, d in zip(before.round(3), d_before):
        if d < 24.0:
            assert tuple(p) not in kept, "an element under the eraser survived"
        elif d > 26.0:
            assert tuple(p) in kept, "an element away from the eraser vanished"
    assert len(after) == len(kept) and kept <= {tuple(p) for p in before.round(3)}
    assert _ink(page, 294, 285, 306, 315) == 0.0

    # undo brings them back, exactly
    start = len(page.evaluate("window.studio.messages"))
    page.click("#undo")
    _wait_message(page, "undone", start)
    restored = _scene(page)
    assert np.allclose(restored, before)
    assert _ink(page, 294, 285, 306, 315) > 0.0

    # pan (the drawn layer moves at once, and is redrawn once the pan rests) and zoom
    page.click("#tools button[data-tool=pan]")
    box = page.locator("#scene").bounding_box()
    cx, cy = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    zoom = page.evaluate("window.studio.view.zoom")
    page.mouse.move(cx, cy)
    page.mouse.down()
    page.mouse.move(cx + 120, cy + 40, steps=4)
    assert _ink(page, 160, 285, 440, 315) > 0.2
    page.mouse.up()
    page.wait_for_timeout(300)
    assert _ink(page, 160, 285, 440, 315) > 0.2 and _ink(page, 100, 60, 700, 200) == 0.0
    page.mouse.move(*_screen(page, 300, 300))
    page.mouse.wheel(0, -400)
    page.wait_for_function(f"window.studio.view.zoom > {zoom} * 1.2")
    page.wait_for_timeout(100)
    assert _ink(page, 200, 285, 400, 315) > 0.2 and _ink(page, 200, 200, 400, 240) == 0.0
    page.click("#fit")

    # export SVG into the project folder
    page.fill("#export-name", "painted.svg")
    page.click("#export")
    page.wait_for_function("window.studio.lastExport && window.studio.lastExport.path === 'painted.svg'")
    svg = page.project / "painted.svg"
    root = ET.parse(svg).getroot()
    assert root.tag.endswith("svg")
    uses = [e for e in root.iter() if e.tag.endswith("use")]
    assert len(uses) == len(before)
    assert page.page_errors == []


def _palette_click(page, x, y):
    box = page.locator("#palette-canvas").bounding_box()
    sx, sy = page.evaluate(f"window.studio.paletteEditor.view.toScreen({x}, {y})")
    page.mouse.click(box["x"] + sx, box["y"] + sy)


def _exemplar(page, name):
    return page.evaluate(f"window.studio.palette.exemplars.find(e => e.name === {name!r})")


def _wait_reply(page, count_before):
    """Wait until the server answered (a message or an error) after an action."""
    page.wait_for_function(
        f"window.studio.messages.length + window.studio.errors.length > {count_before}", timeout=60000
    )


def _replies(page):
    return page.evaluate("window.studio.messages.length + window.studio.errors.length")


def test_palette_panel_edit_flip_select_and_flow_arrows(page):
    for name in ("scales", "tiles"):
        if _exemplar(page, name) is None:
            page.select_option("#files", f"example:{name}.svg")
            page.click("#load-exemplar")
            page.wait_for_function(f"window.studio.palette.exemplars.some(e => e.name === {name!r})")
    page.click("#exemplars li[data-name=tiles]")
    page.wait_for_function("window.studio.paletteEditor.active === 'tiles'")
    ex = _exemplar(page, "tiles")
    n = ex["n"]
    assert ex["edges"], "connectivity edges are shown"

    # place an element by hand, then delete it
    page.click("#edit-tools button[data-etool=place]")
    x0, y0, x1, y1 = min(ex["x"]), min(ex["y"]), max(ex["x"]), max(ex["y"])
    spot = (x0 - 8.0, y0 - 8.0)  # just outside the exemplar's corner, still on the canvas
    c = _replies(page)
    _palette_click(page, *spot)
    _wait_reply(page, c)
    ex = _exemplar(page, "tiles")
    assert ex["n"] == n + 1 and abs(ex["x"][-1] - spot[0]) < 2 and abs(ex["y"][-1] - spot[1]) < 2
    page.click("#edit-tools button[data-etool=delete]")
    c = _replies(page)
    _palette_click(page, ex["x"][-1], ex["y"][-1])
    _wait_reply(page, c)
    assert _exemplar(page, "tiles")["n"] == n

    # flip a connectivity edge by clicking it (Ijiri Fig. 3); hull edges cannot flip
    page.click("#edit-tools button[data-etool=flip]")
    ex = _exemplar(page, "tiles")
    before = {tuple(e) for e in ex["edges"]}
    flipped = False
    for i, j in sorted(before)[:40]:
        mx, my = (ex["x"][i] + ex["x"][j]) / 2, (ex["y"][i] + ex["y"][j]) / 2
        c = _replies(page)
        _palette_click(page, mx, my)
        _wait_reply(page, c)
        now = {tuple(e) for e in _exemplar(page, "tiles")["edges"]}
        if now != before:
            assert len(now) == len(before) and (i, j) not in now
            flipped = True
            break
    assert flipped

    # select two exemplars with the check boxes
    for name in ("scales", "tiles"):
        if not _exemplar(page, name)["selected"]:
            page.click(f"#exemplars li[data-name={name}] input")
            page.wait_for_function(f"window.studio.palette.selection.includes({name!r})")
    assert sorted(page.evaluate("window.studio.palette.selection")) == ["scales", "tiles"]

    # paint the selected textures into a new, empty exemplar (Davison §5.5)
    page.click("#new-exemplar")
    page.wait_for_function("window.studio.palette.exemplars.some(e => e.name === 'exemplar' && e.n === 0)")
    page.click("#exemplars li[data-name=exemplar]")
    page.wait_for_function("window.studio.paletteEditor.active === 'exemplar'")
    page.evaluate("(() => { const r = document.getElementById('radius'); r.value = 30; r.dispatchEvent(new Event('input')); })()")
    page.click("#edit-tools button[data-etool=paint]")
    box = page.locator("#palette-canvas").bounding_box()
    c = len(page.evaluate("window.studio.messages"))
    page.mouse.move(box["x"] + 40, box["y"] + 130)
    page.mouse.down()
    for k in range(1, 9):
        page.mouse.move(box["x"] + 40 + 27 * k, box["y"] + 130)
        page.wait_for_timeout(15)
    page.mouse.up()
    page.wait_for_function(f"window.studio.messages.slice({c}).some(m => m.startsWith('painted'))", timeout=60000)
    assert _exemplar(page, "exemplar")["n"] >= 4

    # a flow stroke shows the field as arrows along it
    page.click("#fit")
    page.click("#tools button[data-tool=flow]")
    _drag(page, [(100.0, 500.0), (400.0, 500.0), (700.0, 500.0)])
    page.wait_for_function("window.studio.strokes.arrows.length > 0")
    arrows = np.asarray(page.evaluate("window.studio.strokes.arrows"))
    near = np.abs(arrows[:, 1] - 500.0) < 40
    assert near.any() and np.allclose(np.cos(arrows[near, 2]), 1.0, atol=0.05)
    assert page.page_errors == []
