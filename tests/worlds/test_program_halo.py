"""Program worlds refuse a halo that does not hold the cells reaching into a tile (issue 19.1)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import shapely

from strew._errors import InputError
from strew.program._world import HaloError, evaluate_world
from strew.tiles import tiled

# Fig. 6's coarse grid: KEEP_INSIDE cells far larger than a tile and its halo
BIG_GRID = """
from strew.program import *
from strew.program import pi
tiles = grid_partition(stripes_properties(0.2, 200), stripes_properties(0.2 + pi / 2, 200), KEEP_INSIDE)
arrangement = map_to_faces(lambda f: scale(contour(f), 0.6), tiles)
"""

# Voronoi cells cropped at the region, each given to a mapper (about 30 across)
CELLS = """
from strew.program import *
cells = uniform_partition(irregular_properties({density}), CROP)
arrangement = union(cells, map_to_faces(lambda f: scale(contour(f), 0.5), cells))
"""

# long stripe lines given to an edge mapper: a tile sees them cut by its grown rectangle
EDGE_MAPPER = """
from strew.program import *
lines = stripes_partition(stripes_properties(0.4, 30))
arrangement = map_to_edges(lambda e: to_curve(e) if random(e, 0, 1, 0) < 0.5 else nothing(), lines)
"""

SIZE = (240.0, 200.0)


def _script(tmp_path: Path, text: str, name: str) -> str:
    p = tmp_path / f"{name}.py"
    p.write_text(text)
    return str(p)


def test_a_grid_cell_larger_than_tile_and_halo_is_refused(tmp_path):
    script = _script(tmp_path, BIG_GRID, "big_grid")
    with pytest.raises(HaloError) as err:
        tiled("program", script, (480.0, 400.0), tile_size=80.0, halo=40.0, seed=1)
    msg = str(err.value)
    assert msg.startswith("halo: 40 is too small")
    assert "raise halo to at least" in msg and "tile_size" in msg and "big_grid.py" in msg
    need = float(msg.split("raise halo to at least ")[1].split()[0])
    assert need > 200.0  # the cell's extent, not the halo


def test_cells_just_larger_than_the_halo_are_refused_and_a_halo_that_holds_them_is_not(tmp_path):
    script = _script(tmp_path, CELLS.format(density=0.0012), "cells")  # spacing ~29, cells up to ~40
    with pytest.raises(HaloError, match=r"^halo: 12 is too small: a face given to map_to_faces"):
        tiled("program", script, SIZE, tile_size=80.0, halo=12.0, seed=3)
    arr = tiled("program", script, SIZE, tile_size=80.0, halo=40.0, seed=3)  # holds them (30 does not: a cut cell reaches into a tile)
    ref = evaluate_world(script, SIZE, seed=3)
    re_, te = np.asarray(ref["cell"]) == "edge", np.asarray(arr["cell"]) == "edge"
    rg, tg = ref.geometry, arr.geometry
    assert shapely.length(tg[te]).sum() == pytest.approx(shapely.length(rg[re_]).sum(), rel=1e-12)
    assert shapely.hausdorff_distance(shapely.union_all(rg[re_]), shapely.union_all(tg[te])) < 1e-9


def test_an_edge_cut_by_the_grown_rectangle_is_refused_to_an_edge_mapper(tmp_path):
    script = _script(tmp_path, EDGE_MAPPER, "edges")
    with pytest.raises(HaloError, match=r"an edge given to map_to_edges"):
        tiled("program", script, SIZE, tile_size=80.0, halo=30.0, seed=1)
    # one tile: the grown rectangle is the world, whose outline cuts the lines in one evaluation too
    assert len(tiled("program", script, SIZE, tile_size=240.0, halo=30.0, seed=1)) > 0


def test_cli_refuses_with_exit_2_and_writes_nothing(tmp_path, capsys):
    pytest.importorskip("pyarrow")
    from strew.cli import main

    script = _script(tmp_path, BIG_GRID, "cli_grid")
    out, png = tmp_path / "w.parquet", tmp_path / "ov.png"
    rc = main(["world", "program", script, "--size", "480x400", "--tile-size", "80", "--halo", "40",
               "--workers", "1", "-q", "--out", str(out), "--out", str(png)])
    assert rc == 2
    err = capsys.readouterr().err
    assert "--halo: 40 is too small" in err and "raise --halo to at least" in err and "--tile-size" in err
    assert not out.exists() and not png.exists()


def test_world_program_help_is_honest(capsys):
    from strew.cli import main

    assert main(["world", "program", "--help"]) == 0
    text = " ".join(capsys.readouterr().out.split())
    assert "--periodic" not in text and "tile k draws" not in text and "2x2" not in text
    assert "field cells keyed by (seed, the partition, the cell)" in text and "else the run is refused" in text
    assert main(["world", "pack", "--help"]) == 0  # the other methods keep theirs
    text = " ".join(capsys.readouterr().out.split())
    assert "--periodic" in text and "tile k draws from (seed, k)" in text
