"""The page draws the method controls from the spec (issue 15 point 1), in chromium."""

from __future__ import annotations

import json
import os

import pytest

from strew._method import spec
from strew.studio._background import CHROMIUM, CHROMIUM_ARGS

pytestmark = [
    pytest.mark.browser,
    pytest.mark.slow,
    pytest.mark.skipif(not os.path.exists(CHROMIUM), reason=f"{CHROMIUM} is not installed"),
]


def test_controls_are_drawn_from_the_spec_and_set_the_session(tmp_path):
    pytest.importorskip("fastapi")
    sync_api = pytest.importorskip("playwright.sync_api")
    from strew.studio._background import BackgroundStudio

    with BackgroundStudio(tmp_path, seed=1) as server, sync_api.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        try:
            pg = browser.new_page()
            errors: list[str] = []
            pg.on("pageerror", lambda e: errors.append(str(e)))
            frames: list[dict] = []
            pg.on("websocket", lambda ws: ws.on("framereceived", lambda f: frames.append(json.loads(f))))
            pg.goto(server.url)
            pg.wait_for_function("window.studio && window.studio.connected && document.getElementById('grow-mode')")
            grow = spec("grow")
            mode = grow.param("mode")
            assert pg.eval_on_selector_all("#grow-mode option", "os => os.map(o => o.value)") == list(mode.choices)
            assert pg.input_value("#grow-mode") == mode.default
            js = grow.param("jitter_scale")
            assert float(pg.get_attribute("#jitter-scale", "max")) == js.high
            assert float(pg.get_attribute("#jitter-scale", "min")) == js.low
            assert float(pg.input_value("#jitter-scale")) == js.default
            jr = grow.param("jitter_rotation")
            assert pg.get_attribute("#jitter-rotation", "max") is None and jr.high is None
            assert jr.help in pg.get_attribute("#jitter-rotation", "title")
            # the density slider in the page takes the declared bounds
            from strew.studio._controls import BRUSH_DENSITY

            assert float(pg.get_attribute("#density", "min")) == BRUSH_DENSITY.low
            # a change goes to the session as a settings message, checked there
            pg.select_option("#grow-mode", "rotate")
            pg.fill("#jitter-rotation", "30")
            pg.dispatch_event("#jitter-rotation", "change")
            # the session answers each settings message with its status
            pg.wait_for_function("document.getElementById('st-conn').textContent === 'connected'")
            for _ in range(100):
                if sum(f.get("type") == "status" and f.get("grow_mode") == "rotate" for f in frames) >= 2:
                    break
                pg.wait_for_timeout(50)
            assert sum(f.get("type") == "status" and f.get("grow_mode") == "rotate" for f in frames) >= 2
            # a bad value typed in is refused by the spec's check, with the key named
            pg.fill("#jitter-scale", "1")
            pg.dispatch_event("#jitter-scale", "change")
            for _ in range(100):
                if any(f.get("type") == "error" for f in frames):
                    break
                pg.wait_for_timeout(50)
            assert any(f.get("type") == "error" and f["message"].startswith("jitter_scale:") for f in frames)
            assert not errors
        finally:
            browser.close()
