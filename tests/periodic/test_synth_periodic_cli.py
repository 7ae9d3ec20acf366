"""``strew synth --periodic``: a repeat tile grown as a torus of tiles (issue 18, strew.tiles.periodic)."""

from __future__ import annotations

from pathlib import Path

import pytest

from strew import _periodic, metrics
from strew.cli import main
from strew.io import load

EX = Path(__file__).resolve().parents[2] / "examples"


@pytest.mark.slow
@pytest.mark.parametrize("exemplar", ["synth/grid.json", "exemplars/stones.svg"])
def test_synth_periodic_tile_repeats_without_overlaps(tmp_path, exemplar):
    out = tmp_path / "tile.json"
    assert main(["synth", str(EX / exemplar), "--size", "160x120", "--periodic", "--seed", "3", "-o", str(out), "-q"]) == 0
    tile = load(out)
    assert _periodic.frame(tile) == (0.0, 0.0, 160.0, 120.0)
    assert len(tile) > 10
    assert len(metrics.outside(tile)) == 0
    rep = metrics.repeat_report(tile)
    assert rep["overlaps"]["inside"] == rep["overlaps"]["across"] == 0, rep["overlaps"]
    assert metrics.wrap_overlaps(tile)["across"] == 0
    # the same command gives the same bytes
    (tmp_path / "again").mkdir()
    out2 = tmp_path / "again" / "tile.json"
    assert main(["synth", str(EX / exemplar), "--size", "160x120", "--periodic", "--seed", "3", "-o", str(out2), "-q"]) == 0
    again = load(out2)
    assert again.meta["params"] == tile.meta["params"] and again.replace(meta={}).equals(tile.replace(meta={}))


@pytest.mark.parametrize(
    ("extra", "message"),
    [
        (["--region", str(EX / "regions" / "blob_with_hole.svg")], "rectangular region"),
        (["--size", "160x120", "--around", str(EX / "synth" / "grid.json")], "--around is not supported"),
    ],
)
def test_synth_periodic_refuses_what_cannot_repeat(tmp_path, capsys, extra, message):
    out = tmp_path / "tile.json"
    assert main(["synth", str(EX / "synth" / "grid.json"), "--periodic", *extra, "-o", str(out)]) == 2
    assert message in capsys.readouterr().err
    assert not out.exists()
