"""The studio's 3D view in a real browser (issue 20.7): three.js (served from the
package, no CDN) shows examples/meshes/sphere.ply; one shift-drag stroke across it paints
elements through the server, and they are drawn. Playwright drives Debian's chromium
headless (WebGL by SwiftShader)."""

from __future__ import annotations

import io
import os

import numpy as np
import pytest

from strew.studio._background import CHROMIUM, CHROMIUM_ARGS

pytestmark = [
    pytest.mark.browser,
    pytest.mark.skipif(not os.path.exists(CHROMIUM), reason=f"{CHROMIUM} is not installed"),
]

# WebGL needs the GPU process, here SwiftShader in software
GL_ARGS = ["--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--ignore-gpu-blocklist"]


def _png(data):
    from PIL import Image

    return np.asarray(Image.open(io.BytesIO(data)).convert("RGB")).astype(int)


def test_paint_a_stroke_on_the_sphere(tmp_path):
    sync_api = pytest.importorskip("playwright.sync_api")
    pytest.importorskip("fastapi")
    pytest.importorskip("potpourri3d")
    from strew.studio._background import BackgroundStudio

    requested: list[str] = []
    with sync_api.sync_playwright() as p, BackgroundStudio(tmp_path, seed=2) as server:
        b = p.chromium.launch(executable_path=CHROMIUM, args=[a for a in CHROMIUM_ARGS if a != "--disable-gpu"] + GL_ARGS)
        pg = b.new_page(viewport={"width": 640, "height": 480})
        errors: list[str] = []
        pg.on("pageerror", lambda e: errors.append(str(e)))
        pg.on("request", lambda r: requested.append(r.url))
        pg.goto(server.url + "static/view3d.html?mesh=examples/meshes/sphere.ply")
        pg.wait_for_function("window.strew3d && window.strew3d.loaded", timeout=10_000)
        pg.wait_for_timeout(300)
        bg = _png(pg.screenshot())
        lit = (np.abs(bg - np.array([0x1E, 0x1F, 0x22])).sum(axis=2) > 30)[60:]
        assert lit.mean() > 0.1  # the mesh is drawn
        # one shift-drag across the middle of the sphere
        pg.keyboard.down("Shift")
        pg.mouse.move(260, 250)
        pg.mouse.down()
        for i in range(1, 13):
            pg.mouse.move(260 + 10 * i, 250 + 3 * i)
        pg.mouse.up()
        pg.keyboard.up("Shift")
        # every brush3d segment sent is answered (elements3d replies after the mesh's one)
        pg.wait_for_function("window.strew3d.sent > 0 && window.strew3d.replies === window.strew3d.sent + 1", timeout=10_000)
        count = pg.evaluate("window.strew3d.count")
        instances = pg.evaluate("window.strew3d.discs ? window.strew3d.discs.count : 0")
        pg.wait_for_timeout(300)
        shot = _png(pg.screenshot())
        # a plain drag orbits the camera (about the mesh's centre) and paints nothing
        before = pg.evaluate("window.strew3d.camera.position.toArray()")
        pg.mouse.move(320, 400)
        pg.mouse.down()
        pg.mouse.move(420, 380, steps=5)
        pg.mouse.up()
        pg.wait_for_timeout(200)
        after = pg.evaluate("window.strew3d.camera.position.toArray()")
        still = pg.evaluate("window.strew3d.count")
        b.close()
    assert np.linalg.norm(np.subtract(after, before)) > 1 and still == count
    assert abs(np.linalg.norm(after) - np.linalg.norm(before)) < 1e-3 * np.linalg.norm(before)  # an orbit keeps the distance
    assert not errors, errors
    assert count >= 5 and instances == count
    # elements drawn: pixels changed near the stroke, none far from it
    changed = np.abs(shot - bg).sum(axis=2) > 30
    assert changed[200:300, 220:420].mean() > 0.02
    assert changed[60:150].mean() < 0.01  # below the toolbar, above the stroke
    assert all(u.startswith(server.url) for u in requested)  # nothing from a CDN
