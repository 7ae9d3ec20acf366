"""strew compare: the table, --json, --plot, exit codes; strew info's g(r) and neighbours."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

import strew
from strew import Arrangement, Region, Shape
from strew.cli import main

ROOT = Path(__file__).resolve().parents[2]
EXEMPLAR = ROOT / "examples" / "fidelity" / "clusters.json"


@pytest.fixture(scope="module")
def tiled(tmp_path_factory):
    ex = strew.load(EXEMPLAR)
    x0, y0, x1, y1 = ex.region.bounds
    w, h = x1 - x0, y1 - y0
    parts = [Arrangement(ex.shapes, ex.kind, ex.x + i * w, ex.y + j * h) for i in range(3) for j in range(3)]
    big = strew.arrangement.concat(parts).replace(region=Region.rectangle(3 * w, 3 * h))
    p = tmp_path_factory.mktemp("cmp") / "tiled.json"
    strew.save(big, p)
    return p


def test_compare_prints_a_table_and_exits_0(tiled, capsys):
    assert main(["compare", str(EXEMPLAR), str(tiled), "--no-eq5"]) == 0
    out = capsys.readouterr().out
    for word in ("fraction[disc]", "g[disc,dot]", "nn[dot>disc]", "tolerance", "faithful", "worst window"):
        assert word in out


def test_compare_exits_0_on_a_failing_verdict(tmp_path, capsys):
    ex = strew.load(EXEMPLAR)
    rng = np.random.default_rng(0)
    x0, y0, x1, y1 = ex.region.bounds
    kinds = np.tile(ex.kind, 9)
    scatter = Arrangement(ex.shapes, kinds, rng.uniform(0, 3 * (x1 - x0), len(kinds)), rng.uniform(0, 3 * (y1 - y0), len(kinds)), region=Region.rectangle(3 * (x1 - x0), 3 * (y1 - y0)))
    p = tmp_path / "scatter.json"
    strew.save(scatter, p)
    assert main(["compare", str(EXEMPLAR), str(p), "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["faithful"] is False
    assert "g[disc,dot]" in d["failures"]
    assert d["metrics"]["g[disc,dot]"]["passed"] is False


def test_compare_json_and_plot(tiled, tmp_path, capsys):
    png = tmp_path / "fig.png"
    assert main(["compare", str(EXEMPLAR), str(tiled), "--json", "--plot", str(png)]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["faithful"] is True and d["failures"] == []
    assert d["local"]["worst"]["score"] >= 0 and len(d["local"]["score"]) >= 1
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_compare_is_deterministic(tiled, capsys):
    assert main(["compare", str(EXEMPLAR), str(tiled), "--json"]) == 0
    a = capsys.readouterr().out
    assert main(["compare", str(EXEMPLAR), str(tiled), "--json"]) == 0
    assert capsys.readouterr().out == a


def _write(tmp_path, name, arr):
    p = tmp_path / name
    strew.save(arr, p)
    return p


@pytest.mark.parametrize(
    "make, message",
    [
        (lambda: Arrangement({"leaf": Shape.circle(1)}, [0, 0, 0], [0, 4, 9], [0, 1, 2]), "no kind in common"),
        (lambda: Arrangement({"disc": Shape.circle(1)}, np.zeros(0, int), [], []), "no visible elements"),
    ],
)
def test_compare_bad_results_exit_2(tmp_path, capsys, make, message):
    p = _write(tmp_path, "bad.json", make())
    assert main(["compare", str(EXEMPLAR), str(p)]) == 2
    err = capsys.readouterr().err
    assert message in err and err.count("\n") == 1


def test_compare_nan_and_missing_files_exit_2(tmp_path, capsys):
    doc = json.loads(EXEMPLAR.read_text())
    doc["elements"]["x"][0] = float("nan")
    p = tmp_path / "nan.json"
    p.write_text(json.dumps(doc))
    assert main(["compare", str(EXEMPLAR), str(p)]) == 2
    assert "NaN" in capsys.readouterr().err
    assert main(["compare", str(EXEMPLAR), str(tmp_path / "missing.json")]) == 2
    assert "missing.json" in capsys.readouterr().err
    assert main(["compare", str(EXEMPLAR), str(EXEMPLAR), "--plot", str(tmp_path / "fig.svg")]) == 2
    assert ".png" in capsys.readouterr().err
    assert not (tmp_path / "fig.svg").exists()


def test_info_adds_pair_correlation_and_neighbours(capsys):
    assert main(["info", str(EXEMPLAR), "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert set(d["nearest_neighbor_by_kind"]) == {"disc>disc", "disc>dot", "dot>disc", "dot>dot"}
    g = d["pair_correlation"]["g"]["disc,dot"]
    r = d["pair_correlation"]["r"]
    # each disc is ringed by small discs: the cross g peaks at the ring radius (12.5)
    assert abs(r[int(np.nanargmax(np.array(g, float)))] - 12.5) < 3.0
    assert main(["info", str(EXEMPLAR)]) == 0
    out = capsys.readouterr().out
    assert "g(disc,dot) peak" in out and "nearest dot>disc" in out
