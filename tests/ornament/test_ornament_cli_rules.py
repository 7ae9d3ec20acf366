"""Rule files, rendering styles and the ``strew ornament`` command."""

from __future__ import annotations

import json
import textwrap

import numpy as np
import pytest

from strew import InputError, Region, load
from strew.cli import main
from strew.ornament import GENERIC_STYLES, grow_elements, load_pattern, tapered_stroke

GOOD_RULES = '''
from strew.ornament import Pattern, Point, Circle, SUCCESS, FAILURE, offset

pattern = Pattern("rings", min_radius=2.0)
pattern.element("seed", Point)
pattern.element("ring", Circle)

@pattern.rule("seed", children=["ring"])
def first(ctx, seed, ring):
    ring.proxy.set(seed.proxy.center, 4.0)
    seed.sterile = True
    return SUCCESS

@pattern.rule("ring", children=["ring"])
def next_ring(ctx, parent, ring):
    r = min(4.0, ctx.goal.radius)
    p = parent.proxy
    ring.proxy.set(offset(p.center, ctx.goal.center - p.center, p.radius + r), r)
    return FAILURE if ctx.intersects(ring) else SUCCESS
'''


def write(tmp_path, name, text):
    p = tmp_path / name
    p.write_text(textwrap.dedent(text))
    return p


def run_cli(capsys, args):
    code = main(args)
    out = capsys.readouterr()
    return code, out.out, out.err


# -- rule files ------------------------------------------------------------------------------
def test_user_rule_file_from_python_and_cli(tmp_path, capsys, monkeypatch):
    rules = write(tmp_path, "rings.py", GOOD_RULES)
    pat = load_pattern(rules)
    assert pat.name == "rings" and [r.name for r in pat.rules] == ["first", "next_ring"]
    orn = grow_elements(pat, Region.rectangle(40, 40), rng=0)
    assert len(orn.of_type("ring")) > 10
    monkeypatch.chdir(tmp_path)
    code, out, err = run_cli(capsys, ["ornament", str(rules), "--size", "40x40", "-o", "r.json", "-q"])
    assert code == 0, err
    arr = load(tmp_path / "r.json")
    assert set(arr["type"]) == {"ring"} and len(arr) == len(orn.of_type("ring"))
    assert arr.meta["method"] == "ornament"


def test_syntax_error_names_file_and_line(tmp_path, capsys):
    bad = write(tmp_path, "bad.py", GOOD_RULES.replace("def next_ring(ctx, parent, ring):", "def next_ring(ctx, parent, ring)"))
    line = GOOD_RULES.splitlines().index("def next_ring(ctx, parent, ring):") + 1
    with pytest.raises(InputError, match=rf"bad\.py, line {line}: syntax error"):
        load_pattern(bad)
    out = tmp_path / "o.svg"
    code, _, err = run_cli(capsys, ["ornament", str(bad), "--size", "20x20", "-o", str(out)])
    assert code == 2
    assert err.count("\n") == 1 and "bad.py" in err and f"line {line}" in err
    assert not out.exists()


def test_rule_for_unknown_type(tmp_path, capsys):
    bad = write(tmp_path, "unknown.py", GOOD_RULES.replace('@pattern.rule("ring", children=["ring"])', '@pattern.rule("ring", children=["blossom"])'))
    with pytest.raises(InputError, match="unknown element type 'blossom'"):
        load_pattern(bad)
    out = tmp_path / "o.json"
    code, _, err = run_cli(capsys, ["ornament", str(bad), "--size", "20x20", "-o", str(out)])
    assert code == 2 and "blossom" in err and "next_ring" in err and err.count("\n") == 1
    assert not out.exists()


def test_missing_seed_type(tmp_path, capsys):
    bad = write(tmp_path, "noseed.py", GOOD_RULES.replace('pattern.element("seed", Point)\n', "").replace('@pattern.rule("seed"', '@pattern.rule("ring"'))
    with pytest.raises(InputError, match="no 'seed' element type"):
        load_pattern(bad)
    out = tmp_path / "o.json"
    code, _, err = run_cli(capsys, ["ornament", str(bad), "--size", "20x20", "-o", str(out)])
    assert code == 2 and "seed" in err and err.count("\n") == 1
    assert not out.exists()


def test_runtime_error_in_rule_file_and_missing_pattern(tmp_path):
    boom = write(tmp_path, "boom.py", "x = 1\nraise RuntimeError('nope')\n")
    with pytest.raises(InputError, match=r"boom\.py, line 2: RuntimeError: nope"):
        load_pattern(boom)
    empty = write(tmp_path, "empty.py", "x = 1\n")
    with pytest.raises(InputError, match="defines no pattern"):
        load_pattern(empty)
    with pytest.raises(InputError, match="neither a built-in pattern"):
        load_pattern(tmp_path / "missing.py")


def test_rule_returning_none_is_reported(tmp_path):
    bad = write(tmp_path, "none.py", GOOD_RULES.replace("    seed.sterile = True\n    return SUCCESS", "    seed.sterile = True"))
    with pytest.raises(InputError, match="returned None"):
        grow_elements(load_pattern(bad), Region.rectangle(20, 20))


# -- rendering -------------------------------------------------------------------------------
def test_styles_draw_the_same_geometry_differently():
    orn = grow_elements("flowers", Region.rectangle(50, 40), rng=0)
    outline, ink, tapered = orn.render("outline"), orn.render("ink"), orn.render("tapered")
    drawn = {e.index for e in orn.elements if e.type != "seed"}
    for arr in (outline, ink, tapered):
        assert set(arr["element"].tolist()) == drawn
        assert len(arr) == len(drawn)  # one row per element, its marks in its parts
    # outline: one unfilled mark per proxy; the ink style fills flowers and leaves
    assert all(p.style["fill"] == "none" for parts in outline.element_parts for p in parts)
    ink_fills = {p.style["fill"] for parts in ink.element_parts for p in parts}
    assert len(ink_fills - {"none"}) >= 3
    n_proxies = sum(len(e.proxies) for e in orn.elements if e.type != "seed")
    assert sum(len(parts) for parts in outline.element_parts) == n_proxies


def test_tapered_stroke_width_varies_along_the_curve():
    pts = np.c_[np.linspace(0, 10, 11), np.zeros(11)]
    outline = tapered_stroke(pts, (2.0, 0.0))
    upper = outline[:11]
    assert upper[0, 1] == pytest.approx(1.0) and upper[-1, 1] == pytest.approx(0.0)
    assert np.all(np.diff(upper[:, 1]) < 0)
    assert set(GENERIC_STYLES) == {"outline", "tapered", "filigree", "skeletal", "skeletal-leafy", "skeletal-beads", "skeletal-ribbon"}


def test_unknown_style_exit_2(tmp_path, capsys):
    out = tmp_path / "o.svg"
    code, _, err = run_cli(capsys, ["ornament", "dots", "--size", "20x20", "--style", "glitter", "-o", str(out)])
    assert code == 2 and "glitter" in err and "outline" in err and err.count("\n") == 1
    assert not out.exists()


# -- CLI -------------------------------------------------------------------------------------
@pytest.mark.parametrize("name, style", [("dots", "order"), ("flowers", "ink"), ("spirals", "vine"), ("hierarchy", "color")])
def test_cli_each_pattern(tmp_path, capsys, name, style):
    out = tmp_path / f"{name}.svg"
    code, stdout, err = run_cli(capsys, ["ornament", name, "--size", "48x36", "--style", style, "--seed", "2", "-o", str(out), "-o", str(tmp_path / "x.json")])
    assert code == 0, err
    assert out.read_text().startswith("<?xml") and name in stdout
    arr = load(tmp_path / "x.json")
    assert arr.meta["seed"] == 2 and arr.meta["params"]["style"] == style and arr.meta["params"]["pattern"] == name
    assert Region.rectangle(48, 36).contains_geometry(arr.geometry, tolerance=1e-6).all()


def test_cli_seed_points_and_determinism(tmp_path, capsys, monkeypatch):
    args = ["ornament", "dots", "--size", "40x30", "--seed-point", "5,5", "--seed-point", "35,25", "--seed", "4", "-o", "d.json", "-q"]
    outs = []
    for sub in ("a", "b"):
        (tmp_path / sub).mkdir()
        monkeypatch.chdir(tmp_path / sub)
        assert main(args) == 0
        outs.append((tmp_path / sub / "d.json").read_bytes())
    assert outs[0] == outs[1]
    doc = json.loads(outs[0])
    assert doc["meta"]["params"]["seeds"] == [[5.0, 5.0], [35.0, 25.0]]
    arr = load(tmp_path / "a" / "d.json")
    # the first dot grows on a seed point (seeds are elements 0 and 1)
    first = arr.select(arr["parent"] <= 1)
    assert len(first) >= 1
    assert set(zip(first.x.round(9).tolist(), first.y.round(9).tolist())) <= {(5.0, 5.0), (35.0, 25.0)}


def test_cli_bad_input_exit_2(tmp_path, capsys):
    out = tmp_path / "o.json"
    for args, word in (
        (["--size", "20x20", "--seed-point", "30,5"], "outside"),
        (["--size", "20x20", "--seed-point", "3;5"], "--seed-point"),
        (["--size", "20x20", "--cells", "2"], "--cells"),
        ([], "--size"),
    ):
        code, _, err = run_cli(capsys, ["ornament", "dots", *args, "-o", str(out)])
        assert code == 2, args
        assert word in err and err.count("\n") == 1
        assert not out.exists()


def test_cli_region_file_with_hole(tmp_path, capsys):
    region = {"format": "strew.arrangement", "version": 1, "shapes": {}, "elements": {"kind": [], "x": [], "y": []},
              "region": {"paths": [{"points": [[0, 0], [60, 0], [60, 40], [0, 40]], "closed": True},
                                   {"points": [[20, 10], [40, 10], [40, 30], [20, 30]], "closed": True}]}}
    rf = tmp_path / "panel.json"
    rf.write_text(json.dumps(region))
    out = tmp_path / "o.json"
    code, _, err = run_cli(capsys, ["ornament", "dots", "--region", str(rf), "--seed-point", "5,5", "-o", str(out), "-q"])
    assert code == 0, err
    arr = load(out)
    assert arr.region is not None and arr.region.area == pytest.approx(60 * 40 - 20 * 20)
    assert arr.region.contains_geometry(arr.geometry, tolerance=1e-6).all()


def test_example_rule_file_and_svg_panel_with_hole(tmp_path, capsys):
    from strew._resources import example_path
    import shapely

    rules = example_path("ornament", "berries.py")
    panel = example_path("ornament", "shield.svg")
    out = tmp_path / "b.json"
    code, stdout, err = run_cli(capsys, ["ornament", str(rules), "--size", "40x40", "--style", "tapered", "-o", str(out)])
    assert code == 0, err
    arr = load(out)
    assert {"stalk", "berry"} <= set(arr["type"])
    out2 = tmp_path / "d.json"
    code, _, err = run_cli(capsys, ["ornament", "dots", "--region", str(panel), "--seed-point", "60,20", "-o", str(out2), "-q"])
    assert code == 0, err
    arr = load(out2)
    window = shapely.Point(60, 50).buffer(18)
    assert arr.region is not None and arr.region.area < 120 * 140 - 900
    assert arr.region.contains_geometry(arr.geometry, tolerance=1e-3).all()
    assert not shapely.intersects(window.buffer(-0.1), arr.geometry).any()
    assert len(arr) > 200
