"""Example palettes (§5.5), per-element parameters (§4.1), the CLI and bad input."""

from __future__ import annotations

import json

import numpy as np
import pytest

from strew import Arrangement, InputError, Region, Shape, load, save
from strew.cli import main
from strew.synth import Palette, element_parameters, load_palette, save_palette, synthesize
from strew.synth._exemplars import grid, stones, stripes


def test_default_parameters_from_shape_and_spacing():
    ex = grid(n=6, spacing=10.0, side=6.0, jitter=0.0)
    r, rbar = element_parameters(ex)
    assert np.allclose(r, np.hypot(3, 3))  # bounding circle of the square
    assert np.allclose(rbar, 30.0)  # 3 x average spacing (§6.1)


def test_parameters_from_columns():
    ex = grid(n=6, jitter=0.0)
    n = len(ex)
    ex = ex.with_columns(radius=np.full(n, 2.0), neighborhood_radius=np.r_[np.full(n - 1, 15.0), np.nan])
    r, rbar = element_parameters(ex)
    assert np.allclose(r, 2.0)
    assert np.allclose(rbar[:-1], 15.0) and rbar[-1] == pytest.approx(30.0)
    out = synthesize(ex, Region.rectangle(80, 80), rng=0)
    assert np.allclose(out["radius"], 2.0)
    assert set(np.round(out["neighborhood_radius"], 6)) <= {15.0, 30.0}


def test_palette_round_trip(tmp_path):
    pal = Palette({"grid": grid(), "stripes": stripes(), "stones": stones()})
    path = tmp_path / "palette.json"
    save_palette(pal, path)
    back = load_palette(path)
    assert back.names == pal.names
    for name in pal.names:
        a, b = pal[name], back[name]
        assert len(a) == len(b)
        assert np.allclose(a.xy, b.xy)
        assert np.allclose(a["radius"], b["radius"]) and np.allclose(a["neighborhood_radius"], b["neighborhood_radius"])
        assert list(a.kind_names) == list(b.kind_names)
    # the palette document renders the exemplars side by side
    doc = load(path)
    assert len(doc) == sum(len(pal[n]) for n in pal.names)
    assert set(doc["exemplar"]) == set(pal.names)


def test_selection_with_weights():
    pal = Palette({"grid": grid(), "stripes": stripes()})
    sel = pal.select({"grid": 3.0, "stripes": 1.0})
    assert sel.names == ("grid", "stripes") and sel.weights == (3.0, 1.0)
    # patches are drawn by weight: with a large weight, the first patch is nearly always grid
    picks = [synthesize(pal, Region.rectangle(60, 60), selection={"grid": 100.0, "stripes": 0.01}, rng=s, optimize="none")["exemplar"][0] for s in range(3)]
    assert picks == ["grid"] * 3
    picks = [synthesize(pal, Region.rectangle(60, 60), selection="stripes", rng=s, optimize="none")["exemplar"][0] for s in range(2)]
    assert picks == ["stripes"] * 2


def test_bad_input_messages():
    pal = Palette({"grid": grid()})
    with pytest.raises(InputError, match="selection: empty"):
        pal.select([])
    with pytest.raises(InputError, match="no exemplar 'nope'"):
        pal.select("nope")
    one = Arrangement({"dot": Shape.circle(1)}, [0], [0.0], [0.0])
    with pytest.raises(InputError, match="at least 2 elements"):
        Palette({"one": one})
    ex = grid(n=4)
    with pytest.raises(InputError, match="radius\\[0\\] must be positive"):
        Palette({"neg": ex.with_columns(radius=np.r_[-1.0, np.ones(len(ex) - 1)])})
    with pytest.raises(InputError, match="ratio constant"):
        synthesize(ex, Region.rectangle(50, 50), c=0.5)


@pytest.fixture
def exemplar_files(tmp_path):
    g = tmp_path / "grid.json"
    save(grid(), g)
    one = tmp_path / "one.json"
    save(Arrangement({"dot": Shape.circle(1)}, [0], [0.0], [0.0]), one)
    neg = tmp_path / "neg.json"
    ex = grid(n=4)
    save(ex.with_columns(radius=np.r_[-2.0, np.ones(len(ex) - 1)]), neg)
    stroke = tmp_path / "stroke.json"
    stroke.write_text(json.dumps({"points": [[20, 50], [80, 60], [140, 50]]}))
    return tmp_path


def _one_line_error(capsys, rc, needle):
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 2
    assert len(err) == 1 and needle in err[0]


@pytest.mark.parametrize(
    "args, needle",
    [
        (["one.json", "--size", "50x50"], "at least 2 elements"),
        (["neg.json", "--size", "50x50"], "must be positive"),
        (["grid.json", "--size", "50x50", "--select", "nope"], "no exemplar 'nope'"),
        (["grid.json", "--size", "50x50", "--select", ":2"], "--select"),
        (["grid.json", "--size", "50x50", "--select", ""], "empty selection"),
        (["grid.json", "--size", "50x50", "--select", "grid:0"], "weight of 'grid' must be positive"),
        (["grid.json", "--size", "50x50", "--brush", "stroke.json", "--brush-radius", "-3"], "--brush-radius: must be positive"),
        (["grid.json", "--size", "50x50", "--brush", "stroke.json"], "needs --brush-radius"),
        (["grid.json", "--size", "50x50", "--fill", "500,500"], "outside the region"),
        (["grid.json", "--size", "50x50", "--c", "1"], "ratio constant"),
        (["grid.json", "--size", "50x50", "--k", "0"], "--k: must be a positive integer"),
        (["grid.json"], "--region or --size"),
        (["grid.json", "--size", "50x50", "--plot", "p.svg"], "--plot"),
    ],
)
def test_cli_bad_input_exit_2_no_output(exemplar_files, monkeypatch, capsys, args, needle):
    monkeypatch.chdir(exemplar_files)
    rc = main(["synth", *args, "--out", "out.json", "--quiet"])
    _one_line_error(capsys, rc, needle)
    assert not (exemplar_files / "out.json").exists()


def test_cli_fill_brush_and_plot(exemplar_files, monkeypatch, capsys):
    monkeypatch.chdir(exemplar_files)
    rc = main(["synth", "grid.json", "--size", "120x100", "--seed", "2", "--out", "a.json", "--plot", "p.png", "--save-palette", "pal.json"])
    assert rc == 0
    out = capsys.readouterr().out
    assert "synth:" in out and "average neighbourhood distance" in out
    a = load("a.json")
    assert len(a) > 60 and a.meta["method"] == "synth" and a.meta["seed"] == 2
    assert a.meta["params"]["optimize"] == "horizon"
    assert (exemplar_files / "p.png").read_bytes()[:4] == b"\x89PNG"
    assert load_palette("pal.json").names == ("grid",)
    rc = main(["synth", "grid.json", "--size", "160x100", "--brush", "stroke.json", "--brush-radius", "12", "--out", "b.json", "--quiet"])
    assert rc == 0
    b = load("b.json")
    import shapely

    d = shapely.distance(shapely.LineString([[20, 50], [80, 60], [140, 50]]), shapely.points(b.xy))
    assert len(b) > 10 and np.all(d <= 12 + 1e-9)
    rc = main(["synth", "grid.json", "--size", "200x200", "--fill", "100,100", "--init", "grow", "--optimize", "none", "--out", "c.json", "--quiet"])
    assert rc == 0 and len(load("c.json")) > 200


def test_cli_deterministic(exemplar_files, tmp_path, monkeypatch, capsys):
    outs = []
    for sub in ("x", "y"):
        d = tmp_path / sub
        d.mkdir()
        for f in ("grid.json",):
            (d / f).write_bytes((exemplar_files / f).read_bytes())
        monkeypatch.chdir(d)
        assert main(["synth", "grid.json", "--size", "100x80", "--seed", "5", "--out", "o.json", "--out", "o.svg", "--quiet"]) == 0
        outs.append(((d / "o.json").read_bytes(), (d / "o.svg").read_bytes()))
    assert outs[0] == outs[1]


def test_cli_patch_init(exemplar_files, monkeypatch, capsys):
    monkeypatch.chdir(exemplar_files)
    rc = main(["synth", "grid.json", "--size", "100x100", "--init", "patch", "--patch-rounds", "2", "--out", "p.json", "--quiet"])
    assert rc == 0
    p = load("p.json")
    assert len(p) > 40 and Region.rectangle(100, 100).contains(p.xy).all()
    assert p.meta["params"]["init"] == "patch" and p.meta["params"]["patch_rounds"] == 2
    # deterministic: the same command gives the same document
    rc = main(["synth", "grid.json", "--size", "100x100", "--init", "patch", "--patch-rounds", "2", "--out", "q.json", "--quiet"])
    assert rc == 0 and load("q.json").equals(p.with_meta(command=load("q.json").meta["command"]))


def test_cli_svg_exemplar(tmp_path, monkeypatch, capsys):
    from strew._resources import example_path

    svg = example_path("exemplars", "stones.svg")
    monkeypatch.chdir(tmp_path)
    rc = main(["synth", str(svg), "--size", "200x150", "--seed", "1", "--out", "s.json", "--quiet"])
    assert rc == 0
    out = load("s.json")
    ex = load(svg)
    assert len(out) > len(ex) // 2
    assert set(out.kinds) == set(ex.kinds)
    assert Region.rectangle(200, 150).contains_geometry(out.geometry).all()
