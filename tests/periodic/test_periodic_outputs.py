"""Outputs of a repeat tile (issue 18 points 1 and 3): the SVG and PNG draw the tile
complete, ``--repeat`` pages through an SVG ``<pattern>``, the PNG tiles without a seam."""

import io
import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import strew
from strew import Arrangement, Shape
from strew import _periodic as P
from strew._errors import InputError
from strew.cli import main
from strew.io.document import dumps, loads
from strew.io.png import svg_to_png, to_png
from strew.io.svg import read_svg, to_svg

SVG = "{http://www.w3.org/2000/svg}"
RED = {"fill": "#ff0000", "stroke": "none"}
BLUE = {"fill": "#0000ff", "stroke": "none"}


def _pixels(png):
    from PIL import Image

    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB")).astype(int)


@pytest.fixture(scope="module")
def edge_tile():
    """A 100 x 50 tile: a red disc over the left edge, a blue bar over the bottom-right corner."""
    shapes = {"disc": Shape.circle(6, style=RED), "bar": Shape.rectangle(24, 4, style=BLUE)}
    a = Arrangement(shapes, ["disc", "bar", "disc"], [2.0, 96.0, 50.0], [25.0, 48.0, 20.0], [0, 0.4, 0])
    return P.mark(a, [0, 0, 100, 50])


def test_tile_svg_draws_wrapped_parts_and_keeps_each_element_once(edge_tile, tmp_path):
    text = to_svg(edge_tile)
    root = ET.fromstring(text)
    assert root.get("viewBox") == "0 0 100 50"  # the page is the tile
    indices = [u.get("data-index") for u in root.iter() if u.get("data-index") is not None]
    assert sorted(indices) == ["0", "1", "2"]
    wrap = root.find(f".//{SVG}g[@id='strew-wrap']")
    copies = sorted(int(u.get("data-copy-of")) for u in wrap.iter(f"{SVG}use"))
    assert copies == [0, 1, 1, 1]  # the disc from the right; the bar's corner from 3 sides
    assert len(copies) == len(P.images(edge_tile)) - len(edge_tile)
    # the drawing: red at the right edge (the disc's wrapped half), blue at the top-left
    # corner (the bar's wrapped corner), nothing of either in the middle band
    img = _pixels(svg_to_png(text, width=400))
    px = 4.0
    assert (img[int(25 * px), int(99.5 * px)] == [255, 0, 0]).all()
    assert (img[int(25 * px), int(0.5 * px)] == [255, 0, 0]).all()
    assert (img[int(0.5 * px), int(1.0 * px)] == [0, 0, 255]).all()
    assert (img[int(25 * px), int(75 * px)] == [255, 255, 255]).all()
    # read back, and as a document: each element once, the frame kept
    p = tmp_path / "t.svg"
    p.write_text(text)
    back = read_svg(p)
    assert len(back) == 3 and P.frame(back) == (0.0, 0.0, 100.0, 50.0)
    doc = loads(dumps(edge_tile))
    assert len(doc) == 3 and P.frame(doc) == P.frame(edge_tile)
    # a copy clones its element (Inkscape moves it with the element)
    assert all(u.get("{http://www.w3.org/1999/xlink}href") == f"#strew-e{u.get('data-copy-of')}" for u in wrap.iter(f"{SVG}use"))


def test_tile_svg_reads_back_with_each_element_once(tmp_path):
    a = _torus(5, 40, 30)
    p = tmp_path / "t.svg"
    p.write_text(to_svg(a))
    back = read_svg(p)
    assert len(back) == len(a) and len(P.images(a)) > len(a)
    order = np.lexsort((a.y, a.x))
    border = np.lexsort((back.y, back.x))
    np.testing.assert_allclose(back.xy[border], a.xy[order], atol=1e-6)
    assert back.kind_names[border].tolist() == a.kind_names[order].tolist()


def test_pattern_page(edge_tile):
    text = to_svg(edge_tile, repeat=(3, 2))
    root = ET.fromstring(text)
    assert root.get("viewBox") == "0 0 300 100"
    pat = root.find(f".//{SVG}pattern")
    assert pat.get("patternUnits") == "userSpaceOnUse"
    assert (pat.get("width"), pat.get("height")) == ("100", "50")
    rect = root.find(f"{SVG}rect[@id='strew-repeat']")
    assert rect.get("fill") == "url(#strew-pattern)" and (rect.get("width"), rect.get("height")) == ("300", "100")
    # the tile's elements live once, inside the pattern
    assert len([u for u in pat.iter(f"{SVG}use") if u.get("data-index") is not None]) == 3
    assert to_svg(edge_tile, repeat="3x2") == text
    # drawn: the six copies are the same picture
    img = _pixels(svg_to_png(text, width=600))
    blocks = [img[j * 100 : (j + 1) * 100, i * 200 : (i + 1) * 200] for j in range(2) for i in range(3)]
    for b in blocks[1:]:
        assert np.abs(b - blocks[0]).max() <= 1


def _torus(seed, w, h, r=1.5):
    rng = np.random.default_rng(seed)
    pts = np.zeros((0, 2))
    for p in rng.uniform([0, 0], [w, h], size=(int(0.4 * w * h), 2)):
        if len(pts) and np.hypot(P.wrap_delta(pts[:, 0] - p[0], w), P.wrap_delta(pts[:, 1] - p[1], h)).min() < 2 * r:
            continue
        pts = np.vstack([pts, p])
    kinds = np.where(np.arange(len(pts)) % 2 == 0, "disc", "bar")
    shapes = {"disc": Shape.circle(r, style=RED), "bar": Shape.rectangle(2.4 * r, 0.8 * r, style=BLUE)}
    return P.mark(Arrangement(shapes, kinds, pts[:, 0], pts[:, 1], rng.uniform(0, np.pi, len(pts))), [0, 0, w, h])


@pytest.mark.parametrize("w, h, width", [(37.3, 29.1, 173), (51.7, 23.3, 301), (20.1, 33.3, 97)])
def test_png_tile_is_seamless(w, h, width):
    a = _torus(3, w, h)
    tile = _pixels(to_png(a, width=width))
    th, tw = tile.shape[:2]
    assert tw == width and abs(th - width * h / w) <= 0.5
    # a 3 x 3 render: every copy, at every offset, is the tile pixel for pixel, so the
    # tile's right edge continues into its left edge exactly as the render does
    big = _pixels(to_png(a, width=3 * width, repeat=(3, 3)))
    assert big.shape[:2] == (3 * th, 3 * tw)
    for j in range(3):
        for i in range(3):
            assert np.array_equal(big[j * th : (j + 1) * th, i * tw : (i + 1) * tw], tile)
    # and it is the picture: the 3 x 3 copies drawn as one plain scene (no pattern)
    # differ only by anti-aliasing rounding at a few edge pixels (resvg's supersampling
    # turns a pixel where two outlines nearly touch by up to 130 levels between copies
    # of the plain scene itself)
    x0, y0 = P.frame(a)[:2]
    plain = P.mark(P.tiled_copies(a, 3, 3), [x0 - w, y0 - h, 3 * w, 3 * h])
    scene = _pixels(svg_to_png(to_svg(plain, width=3 * tw, height=3 * th), width=3 * tw))
    diff = np.abs(scene - big).max(axis=2)
    assert (diff > 0).mean() < 0.002 and (diff > 32).mean() < 0.0005
    # the seam columns themselves: the tile's last column and the next copy's first
    # against the plain scene's columns there
    for c in (tw - 1, tw, 2 * tw - 1, 2 * tw):
        assert (np.abs(scene[:, c] - big[:, c]).max(axis=1) > 0).mean() < 0.02


@settings(max_examples=15, deadline=None)
@given(st.lists(st.tuples(st.floats(0, 30), st.floats(0, 20)), min_size=1, max_size=10), st.floats(0.5, 6))
def test_wrapped_copies_are_exactly_the_images(pts, r):
    xy = np.array(pts)
    a = P.mark(Arrangement({"d": Shape.circle(r)}, ["d"] * len(xy), xy[:, 0], xy[:, 1]), [0, 0, 30, 20])
    root = ET.fromstring(to_svg(a))
    wrap = root.find(f".//{SVG}g[@id='strew-wrap']")
    got = [] if wrap is None else sorted(int(u.get("data-copy-of")) for u in wrap.iter(f"{SVG}use"))
    assert len(got) == len(P.images(a)) - len(a)
    assert len([u for u in root.iter() if u.get("data-index") is not None]) == len(a)


def test_repeat_needs_a_periodic_arrangement_and_counts():
    flat = Arrangement({"d": Shape.circle(1)}, ["d"], [1.0], [1.0])
    with pytest.raises(InputError, match="not periodic"):
        to_svg(flat, repeat=(2, 2))
    with pytest.raises(InputError, match="not periodic"):
        to_png(flat, repeat=(2, 2))
    tile = P.mark(flat, [0, 0, 4, 4])
    with pytest.raises(InputError, match="at least 1x1"):
        to_svg(tile, repeat=(0, 3))
    with pytest.raises(InputError, match="expected NxM"):
        to_svg(tile, repeat="3by3")


def test_cli_render_repeat(tmp_path, capsys):
    a = _torus(4, 40, 30)
    src = tmp_path / "tile.json"
    strew.save(a, src)
    check = tmp_path / "check.png"
    assert main(["render", str(src), "--repeat", "3x3", "--out", str(check), "--out", str(tmp_path / "p.svg"), "--width", "300", "-q"]) == 0
    img = _pixels(check.read_bytes())
    tile = _pixels(to_png(a, width=100))
    assert img.shape[:2] == (3 * tile.shape[0], 3 * tile.shape[1])
    assert np.array_equal(img[: tile.shape[0], : tile.shape[1]], tile)
    assert re.search(r'<pattern id="strew-pattern"[^>]*width="40" height="30"', (tmp_path / "p.svg").read_text())
    # JSON keeps the tile with --repeat
    assert main(["render", str(src), "--repeat", "2x2", "--out", str(tmp_path / "same.json"), "-q"]) == 0
    assert len(strew.load(tmp_path / "same.json")) == len(a)
    # bad input: exit 2, a message naming the option, nothing written
    capsys.readouterr()
    bad = tmp_path / "bad.png"
    assert main(["render", str(src), "--repeat", "0x3", "--out", str(bad)]) == 2
    assert "--repeat" in capsys.readouterr().err and not bad.exists()
    flat = tmp_path / "flat.json"
    strew.save(a.replace(meta={}), flat)
    assert main(["render", str(flat), "--repeat", "3x3", "--out", str(bad), "--out", str(tmp_path / "bad.svg")]) == 2
    err = capsys.readouterr().err
    assert "--repeat" in err and "not periodic" in err
    assert not bad.exists() and not (tmp_path / "bad.svg").exists()


def test_cli_repeat_without_periodic_is_refused(tmp_path, capsys):
    disc = tmp_path / "disc.json"
    strew.save(Arrangement({"disc": Shape.circle(3)}, ["disc"], [0.0], [0.0]), disc)
    out = tmp_path / "o.svg"
    assert main(["pack", str(disc), "--size", "60x40", "--repeat", "2x2", "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert "--repeat" in err and "periodic" in err and not out.exists()
