"""Exported SVG opens in a real browser (Debian's headless chromium) and draws the elements
where the strew transform convention puts them."""

from __future__ import annotations

import shutil
import subprocess

import numpy as np
import pytest

import strew
from strew import Arrangement, Region, Shape

CHROMIUM = shutil.which("chromium")
pytestmark = pytest.mark.browser

FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--hide-scrollbars",
]


@pytest.mark.skipif(CHROMIUM is None, reason="chromium is not installed (scripts/test.sh installs it)")
def test_chromium_renders_exported_svg(tmp_path):
    from PIL import Image

    shapes = {
        "red": Shape.rectangle(20, 4, style={"fill": "#ff0000", "stroke": "none"}),
        "blue": Shape.circle(6, style={"fill": "#0000ff", "stroke": "none"}),
    }
    # a long red bar rotated by +90 degrees stands vertically (y-down convention)
    arr = Arrangement(shapes, ["red", "blue"], [30, 80], [50, 50], [np.pi / 2, 0], [1, 1.5], region=Region.rectangle(100, 100))
    svg = tmp_path / "t.svg"
    strew.save(arr, svg, width=400, margin=0.0)
    png = tmp_path / "shot.png"
    subprocess.run(
        [CHROMIUM, *FLAGS, f"--user-data-dir={tmp_path / 'profile'}", f"--screenshot={png}", "--window-size=400,400", svg.as_uri()],
        check=True,
        capture_output=True,
        timeout=120,
    )
    img = np.asarray(Image.open(png).convert("RGB")).astype(int)
    px = 4.0  # 400 px for 100 user units (region bounds, no margin)

    def at(x, y):
        return img[int(y * px), int(x * px)]

    assert (at(30, 50) == [255, 0, 0]).all()  # bar centre
    assert (at(30, 42) == [255, 0, 0]).all()  # 8 units below/above centre: inside the vertical bar
    assert (at(38, 50) > 200).all()  # 8 units to the side: outside (the bar is 4 wide)
    assert (at(80, 50) == [0, 0, 255]).all()  # disc centre
    assert (at(80 + 8, 50) == [0, 0, 255]).all()  # scale 1.5: radius 9
    assert (at(80 + 10.5, 50) > 200).all()
