"""Height maps of 2D arrangements (issue 20 point 6, Sakurai & Miyata Fig. 16)."""

from __future__ import annotations

import io

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st
from PIL import Image

import strew
from strew import Arrangement, InputError, Shape
from strew.io._height import height_map, to_height_png

GROUND = 32768
TOP = 65535


def read16(data: bytes) -> np.ndarray:
    with Image.open(io.BytesIO(data)) as img:
        assert img.mode in ("I;16", "I;16B", "I")
        return np.asarray(img).astype(np.int64)


def pixel(x, y, frame):
    x0, y0, px = frame
    return int((y - y0) / px), int((x - x0) / px)


def test_dome_plateau_groove(tmp_path):
    a = Arrangement(
        {"crista": Shape.circle(5.0), "sulcus": Shape.circle(7.0), "tile": Shape.rectangle(10, 10).centered()},
        ["crista", "sulcus", "tile"], [20, 20, 70], [20, 20, 60],
        meta={"height_profiles": {"sulcus": "groove", "tile": "plateau"}},
    )
    path = strew.save(a, tmp_path / "relief.height.png", width=400)
    img = read16(path.read_bytes())
    _, frame = height_map(a, width=400)
    assert img.shape[1] == 400
    # the crista's top, the plateau's flat top
    assert img[pixel(20, 20, frame)] > 0.99 * TOP
    r, c = pixel(70, 60, frame)
    assert np.all(img[r - 3:r + 4, c - 3:c + 4] == TOP)
    # the dome falls towards its edge
    assert GROUND < img[pixel(24.5, 20, frame)] < img[pixel(22, 20, frame)] < img[pixel(20, 20, frame)]
    # the sulcus: a groove below the ground along its outline (radius 7), around the crista
    assert img[pixel(27, 20, frame)] < 0.2 * TOP
    assert img[pixel(13, 20, frame)] < 0.2 * TOP
    # ground far from everything
    assert img[pixel(45, 40, frame)] == GROUND


def test_heights_follow_the_elements():
    a = Arrangement({"d": Shape.circle(3.0)}, ["d", "d"], [10, 40], [10, 30])
    h, frame = height_map(a, width=200)
    for x, y in zip(a.x, a.y):
        r, c = pixel(x, y, frame)
        assert h[r, c] > 0.95
    moved = a.replace(x=a.x + 5)
    h2, frame2 = height_map(moved.replace(), width=200)
    assert frame2[0] == pytest.approx(frame[0] + 5)  # the frame follows the elements' bounds
    assert np.allclose(h, h2)


@settings(max_examples=15, deadline=None)
@given(
    xs=st.lists(st.floats(0, 100), min_size=1, max_size=12),
    seed=st.integers(0, 1000),
)
def test_raised_exactly_inside_elements(xs, seed):
    rng = np.random.default_rng(seed)
    ys = rng.uniform(0, 100, len(xs))
    a = Arrangement({"d": Shape.circle(4.0)}, ["d"] * len(xs), xs, ys)
    h, (x0, y0, px) = height_map(a, width=128)
    assert h.min() >= 0 and h.max() <= 1
    rows, cols = np.mgrid[: h.shape[0], : h.shape[1]]
    cx, cy = x0 + (cols + 0.5) * px, y0 + (rows + 0.5) * px
    d = np.min(np.hypot(cx[..., None] - np.asarray(xs), cy[..., None] - ys), axis=-1)
    # the circle is a 32-gon: inside radius 4 cos(pi/32)
    assert np.all(h[d > 4.0 + 1e-9] == 0)
    assert np.all(h[d < 4.0 * np.cos(np.pi / 32) - 1.5 * px] > 0)


def test_png_is_16_bit_and_save_many(tmp_path):
    a = Arrangement({"d": Shape.circle(3.0)}, ["d"], [10], [10])
    data = to_height_png(a, width=64)
    assert data[24] == 16  # IHDR bit depth
    out = strew.io.save_many(a, [tmp_path / "a.height.png", tmp_path / "a.png"], width=64)
    assert all(p.exists() for p in out)
    with Image.open(out[0]) as height, Image.open(out[1]) as colour:
        assert height.mode.startswith("I") and colour.mode in ("RGB", "RGBA")


@pytest.mark.parametrize(
    "kwargs, message",
    [
        ({"profiles": {"d": "crater"}}, "profiles.d: expected one of dome, plateau, groove"),
        ({"profiles": {"x": "dome"}}, "profiles: unknown kind 'x'"),
        ({"profiles": {"d": {"profile": "dome", "height": 2}}}, "profiles.d.height: expected a number in (0, 1]"),
        ({"width": 0}, "width: expected an integer"),
    ],
)
def test_bad_profiles(kwargs, message):
    a = Arrangement({"d": Shape.circle(3.0)}, ["d"], [10], [10])
    with pytest.raises(InputError) as info:
        to_height_png(a, **kwargs)
    assert message in str(info.value)
