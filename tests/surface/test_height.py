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


def _tile(kind_profile=None):
    # a 60 x 40 repeat tile with elements across the right, the bottom and both edges
    return Arrangement(
        {"dot": Shape.circle(4.0), "ring": Shape.circle(6.0)},
        ["dot", "dot", "dot", "ring"], [58.0, 20.0, 1.0, 35.0], [20.0, 38.5, 1.5, 15.0],
        meta={"periodic": [0.0, 0.0, 60.0, 40.0], **({"height_profiles": kind_profile} if kind_profile else {})},
    )


@pytest.mark.parametrize("profiles", [None, {"ring": "groove", "dot": "plateau"}])
def test_periodic_tile_height_map_is_seamless(profiles):
    tile = _tile(profiles)
    h, frame = height_map(tile, width=120)
    assert h.shape == (80, 120) and frame == (0.0, 0.0, 0.5)
    # the 3x3 copies laid side by side, rendered as one flat picture, hold the tile in
    # their middle pixel for pixel: the tile's edges continue each other
    xs = np.concatenate([tile.x + 60 * i for j in range(3) for i in range(3)])
    ys = np.concatenate([tile.y + 40 * j for j in range(3) for i in range(3)])
    big = Arrangement(tile.shapes, np.tile(tile.kind_names, 9), xs, ys, region=strew.Region.from_size("180x120"),
                      meta={"height_profiles": profiles} if profiles else {})
    hb, _ = height_map(big, width=360)
    assert hb.shape == (240, 360)
    assert np.abs(hb[80:160, 120:240] - h).max() < 1e-9
    # the dot across the right edge (x 58, r 4) wraps in on the left: raised at x = 1
    assert h[40, 2] > 0.2


def test_cli_height_profile_flag(tmp_path, capsys):
    from strew.cli import main

    ex = tmp_path / "tile.json"
    strew.save(_tile(), ex)
    out, doc = tmp_path / "r.height.png", tmp_path / "r.json"
    assert main(["render", str(ex), "--out", str(out), "--out", str(doc), "--height-profile", "dot=plateau:0.6",
                 "--height-profile", "*=groove"]) == 0
    img = read16(out.read_bytes())
    # the plateaus' tops at 0.6, the ring a groove (below ground), nothing above 0.6
    assert img.max() == round(1.6 / 2 * 65535)
    assert img.min() < GROUND
    assert strew.load(doc).meta["height_profiles"] == {"dot": {"profile": "plateau", "height": 0.6}, "*": "groove"}
    # the document remembers them: rendered again without the flag, the same pixels
    again = tmp_path / "again.height.png"
    assert main(["render", str(doc), "--out", str(again)]) == 0
    assert np.array_equal(read16(again.read_bytes()), img)
    capsys.readouterr()
    assert main(["render", str(ex), "--out", str(out), "--height-profile", "leaf=dome"]) == 2
    err = capsys.readouterr().err
    assert "--height-profile" in err and "leaf" in err
    assert main(["render", str(ex), "--out", str(out), "--height-profile", "dot=bump"]) == 2
