"""Repeat tiles in a real browser (issue 18): the studio's repeat view shows the canvas
tiled 3 x 3 and a stroke across the edge continues at the opposite edge; a ``<pattern>``
page opens in Chromium without a seam. Playwright drives Debian's chromium headless."""

from __future__ import annotations

import io
import os

import numpy as np
import pytest

from strew import Arrangement, Shape
from strew import _periodic as P
from strew.io.svg import to_svg
from strew.studio._background import CHROMIUM, CHROMIUM_ARGS

pytestmark = [
    pytest.mark.browser,
    pytest.mark.skipif(not os.path.exists(CHROMIUM), reason=f"{CHROMIUM} is not installed"),
]


@pytest.fixture(scope="module")
def browser():
    sync_api = pytest.importorskip("playwright.sync_api")
    with sync_api.sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        yield b
        b.close()


def _png(data):
    from PIL import Image

    return np.asarray(Image.open(io.BytesIO(data)).convert("RGB")).astype(int)


def test_pattern_page_has_no_seam(browser, tmp_path):
    """A 3 x 2 ``<pattern>`` page, 100 px per tile: every copy shows the tile's pixels,
    so the rows and columns on both sides of each tile boundary continue the tile's own."""
    rng = np.random.default_rng(7)
    n = 40
    shapes = {"disc": Shape.circle(5, style={"fill": "#d02020", "stroke": "none"}), "bar": Shape.rectangle(18, 4, style={"fill": "#2040d0", "stroke": "none"})}
    a = Arrangement(shapes, np.where(np.arange(n) % 2 == 0, "disc", "bar"), rng.uniform(0, 100, n), rng.uniform(0, 100, n), rng.uniform(0, np.pi, n))
    a = P.mark(a, [0, 0, 100, 100])
    assert len(P.images(a)) > n  # elements cross the edges
    svg = tmp_path / "pattern.svg"
    svg.write_text(to_svg(a, repeat=(3, 2), width=300))
    page = browser.new_page(viewport={"width": 300, "height": 200})
    page.goto(svg.as_uri())
    shot = _png(page.screenshot())
    page.close()
    assert shot.shape[:2] == (200, 300)
    tile = shot[:100, :100]
    assert (tile < 200).any(axis=2).mean() > 0.1  # the tile is drawn
    worst = 0
    for j in range(2):
        for i in range(3):
            block = shot[100 * j : 100 * (j + 1), 100 * i : 100 * (i + 1)]
            worst = max(worst, int(np.abs(block - tile).max()))
    assert worst <= 2, f"a copy differs from the tile by {worst} levels"
    # across the vertical boundary x = 100: the columns on either side are the tile's last and first
    assert np.abs(shot[:100, 99] - tile[:, 99]).max() <= 2 and np.abs(shot[:100, 100] - tile[:, 0]).max() <= 2
    assert np.abs(shot[99, :100] - tile[99]).max() <= 2 and np.abs(shot[100, :100] - tile[0]).max() <= 2


@pytest.fixture(scope="module")
def studio_page(browser, tmp_path_factory):
    pytest.importorskip("fastapi")
    from strew.studio._background import BackgroundStudio

    project = tmp_path_factory.mktemp("repeat_project")
    with BackgroundStudio(project, seed=2) as server:
        pg = browser.new_page(viewport={"width": 1200, "height": 760})
        errors: list[str] = []
        pg.on("pageerror", lambda e: errors.append(str(e)))
        pg.goto(server.url)
        pg.wait_for_function("window.studio && window.studio.connected && window.studio.strokes.region.length > 0")
        pg.page_errors = errors
        yield pg
        pg.close()


def _screen(page, x, y):
    box = page.locator("#scene").bounding_box()
    sx, sy = page.evaluate(f"window.studio.view.toScreen({x}, {y})")
    return box["x"] + sx, box["y"] + sy


def _ink_mask(page, x0, y0, x1, y1):
    """(h, w) bool: canvas pixels of a world box that differ from the white region."""
    d = page.evaluate(
        f"""(() => {{
        const c = document.getElementById('scene'), ctx = c.getContext('2d'), v = window.studio.view;
        const dpr = window.devicePixelRatio || 1;
        const [a, b] = v.toScreen({x0}, {y0}), [e, f] = v.toScreen({x1}, {y1});
        const w = Math.round((e - a) * dpr), h = Math.round((f - b) * dpr);
        const img = ctx.getImageData(Math.round(a * dpr), Math.round(b * dpr), w, h).data;
        const out = new Array(w * h);
        for (let i = 0; i < w * h; i++) out[i] = img[4 * i] < 235 || img[4 * i + 1] < 235 || img[4 * i + 2] < 235 ? 1 : 0;
        return {{w, h, out}};
    }})()"""
    )
    return np.array(d["out"], bool).reshape(d["h"], d["w"])


def test_studio_repeat_view_tiles_3x3_and_strokes_wrap(studio_page):
    page = studio_page
    page.select_option("#files", "example:scales.svg")
    page.click("#load-exemplar")
    page.wait_for_function("window.studio.palette.exemplars.some(e => e.name === 'scales' && e.selected)")
    page.evaluate("(() => { const r = document.getElementById('radius'); r.value = 40; r.dispatchEvent(new Event('input')); })()")
    assert page.get_attribute("#scene", "data-repeat") != "3x3"
    page.click("#repeat")
    page.wait_for_function("document.getElementById('scene').dataset.repeat === '3x3'")
    tile = page.evaluate("window.studio.repeat")
    x0, y0, w, h = tile
    page.wait_for_function("window.studio.copiesDrawn === 9")
    assert page.get_attribute("#repeat", "aria-pressed") == "true"
    # the view shows the 3 x 3 block: its corners are on the canvas
    box = page.locator("#scene").bounding_box()
    for cx, cy in ((x0 - w, y0 - h), (x0 + 2 * w, y0 + 2 * h)):
        sx, sy = _screen(page, cx, cy)
        assert box["x"] - 1 <= sx <= box["x"] + box["width"] + 1 and box["y"] - 1 <= sy <= box["y"] + box["height"] + 1

    # a brush stroke leaving the tile on the right continues on its left
    page.click("#tools button[data-tool=brush]")
    start = len(page.evaluate("window.studio.messages"))
    ymid = y0 + h / 2
    pts = [(x0 + w - 160 + 20 * i, ymid) for i in range(15)]  # to 120 past the right edge
    page.mouse.move(*_screen(page, *pts[0]))
    page.mouse.down()
    for p in pts[1:]:
        page.mouse.move(*_screen(page, *p), steps=3)
        page.wait_for_timeout(10)
    page.mouse.up()
    page.wait_for_function(f"window.studio.messages.slice({start}).some(m => m.startsWith('brush:'))", timeout=60000)
    page.wait_for_timeout(200)
    d = page.evaluate("(() => { const s = window.studio.scene; return {x: Array.from(s.x.subarray(0, s.n))}; })()")
    xs = np.array(d["x"])
    assert (xs < x0 + 100).sum() >= 3 and (xs > x0 + w - 140).sum() >= 3
    assert np.all((xs >= x0) & (xs < x0 + w))

    # on screen: the copy to the right of the tile and the one below repeat its ink
    page.evaluate("window.studio.drawNow(true)")
    centre = _ink_mask(page, x0, y0, x0 + w, y0 + h)
    right = _ink_mask(page, x0 + w, y0, x0 + 2 * w, y0 + h)
    below = _ink_mask(page, x0, y0 + h, x0 + w, y0 + 2 * h)
    assert centre.mean() > 0.01
    for other in (right, below):
        hh, ww = min(centre.shape[0], other.shape[0]), min(centre.shape[1], other.shape[1])
        a, b = centre[:hh, :ww], other[:hh, :ww]
        iou = (a & b).sum() / max(1, (a | b).sum())
        assert iou > 0.8, f"a copy does not repeat the tile (IoU {iou:.2f})"
    # toggling off shows one tile again
    page.click("#repeat")
    page.wait_for_function("document.getElementById('scene').dataset.repeat === 'off' && window.studio.copiesDrawn === 1")
    assert not page.page_errors
