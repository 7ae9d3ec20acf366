"""Program worlds in tiles (issue 19.1): the pieces of the tiles make the untiled map."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import shapely

from strew.program import _world
from strew.program._world import evaluate_world
from strew.tiles import plan, tiled

VORONOI = """
from strew.program import *
p = set_weighted_face_labels(irregular_properties(0.003), "a", 0.5, "b", 0.3)
p = set_weighted_edge_labels(p, "e", 0.4)
cells = uniform_partition(p, KEEP_INSIDE)
def shrink(face):
    if random(face, 0, 1, 0) < 0.25:
        return nothing()
    return scale(contour(face), 0.7)
arrangement = union(cells, map_to_faces(shrink, cells))
"""

GRID = """
from math import pi
from strew.program import *
s1 = set_face_labels(stripes_properties(0.3, 30, 20), "x", "y")
tiles = grid_partition(s1, stripes_properties(0.3 + pi / 2, 25), KEEP_INSIDE)
def age(face):
    if random(face, 0, 1, 0) < 0.3:
        return nothing()
    return contour(face)
arrangement = union(map_to_faces(age, tiles), map_to_faces(lambda f: scale(contour(f), 0.5), tiles))
"""

STRIPES = """
from strew.program import *
arrangement = stripes_partition(set_edge_labels(stripes_properties(0.5, 30, 10), "a", "b"))
"""

RANDOM = """
from strew.program import *
arrangement = random_partition(set_weighted_edge_labels(irregular_properties(0.002), "x", 0.5), CROP_ADD_BOUNDARY)
"""

SIZE = (240.0, 200.0)  # tiles of 80: 3 x 3


def _script(tmp_path: Path, text: str, name: str) -> str:
    p = tmp_path / f"{name}.py"
    p.write_text(text)
    return str(p)


def _compare(ref, arr, tile: float, halo: float, labelled_share: float = 0.8, size: tuple[float, float] = SIZE) -> None:
    """Every untiled face is the union of its pieces, the pieces do not overlap and lie in
    their tiles, and the edges are the same lines. A face within the halo of every tile it
    meets has its labels (a larger one, e.g. the gap of several deleted cells, gets labels
    only from the edges its tiles see: face labels are rebuilt from the sides of edges)."""
    rg, tg = ref.geometry, arr.geometry
    rc, tc = np.asarray(ref["cell"]), np.asarray(arr["cell"])
    rl, tl = np.asarray(ref["labels"]), np.asarray(arr["labels"])
    rf, tf = np.flatnonzero(rc == "face"), np.flatnonzero(tc == "face")
    assert len(rf) > 10 and len(tf) > len(rf)  # some faces cross borders
    qi, qj = shapely.STRtree(rg[rf]).query(shapely.point_on_surface(tg[tf]), predicate="within")
    assert sorted(qi.tolist()) == list(range(len(tf)))  # every piece in exactly one face
    groups: dict[int, list[int]] = {}
    for i, j in zip(qi.tolist(), qj.tolist()):
        groups.setdefault(j, []).append(int(tf[i]))
    assert len(groups) == len(rf)
    tiles_of = np.asarray(arr["tile"])
    plan_tiles = plan(size, tile)[0]
    labelled = 0
    for j, lst in groups.items():
        whole = rg[rf[j]]
        assert shapely.symmetric_difference(shapely.union_all(tg[lst]), whole).area <= 1e-9 * whole.area
        x0, y0, x1, y1 = whole.bounds
        if all(x0 >= t.rect[0] - halo and x1 <= t.rect[2] + halo and y0 >= t.rect[1] - halo and y1 <= t.rect[3] + halo
               for t in (plan_tiles[k] for k in set(tiles_of[lst].tolist()))):
            assert {tl[k] for k in lst} == {rl[rf[j]]}
            labelled += 1
    assert labelled >= labelled_share * len(rf)
    areas = shapely.area(tg[tf])
    assert areas.sum() == pytest.approx(shapely.union_all(tg[tf]).area, rel=1e-12)  # no overlaps
    assert areas.sum() == pytest.approx(size[0] * size[1], rel=1e-12)  # the world, covered
    b = shapely.bounds(tg)
    for t in plan_tiles:
        sel = tiles_of == t.index
        x0, y0, x1, y1 = t.rect
        assert (b[sel, 0] >= x0 - 1e-9).all() and (b[sel, 2] <= x1 + 1e-9).all()
        assert (b[sel, 1] >= y0 - 1e-9).all() and (b[sel, 3] <= y1 + 1e-9).all()
    re_, te = np.flatnonzero(rc == "edge"), np.flatnonzero(tc == "edge")
    assert shapely.length(tg[te]).sum() == pytest.approx(shapely.length(rg[re_]).sum(), rel=1e-12)
    assert shapely.hausdorff_distance(shapely.union_all(rg[re_]), shapely.union_all(tg[te])) < 1e-9
    for lab in set(rl[re_].tolist()):
        assert shapely.length(tg[te][tl[te] == lab]).sum() == pytest.approx(shapely.length(rg[re_][rl[re_] == lab]).sum(), rel=1e-9)


@pytest.mark.parametrize(("text", "tile", "halo", "labelled"), [
    (VORONOI, 80.0, 30.0, 0.8),
    pytest.param(VORONOI, 120.0, 30.0, 0.8, marks=pytest.mark.slow),  # another tile size: the same world
    (GRID, 80.0, 40.0, 0.8),
    (RANDOM, 80.0, 40.0, 0.8),
    (STRIPES, 80.0, 30.0, 0.0),  # open lines: faces closed by the world's outline, across tiles
], ids=["uniform-80", "uniform-120", "grid", "random", "stripes"])
def test_pieces_of_every_cell_make_the_untiled_cell(tmp_path, text, tile, halo, labelled):
    script = _script(tmp_path, text, "world")
    ref = evaluate_world(script, SIZE, seed=5)
    arr = tiled("program", script, SIZE, tile_size=tile, halo=halo, seed=5)
    assert arr.meta["world"]["tiles"] == len(plan(SIZE, tile)[0])
    _compare(ref, arr, tile, halo, labelled)


def test_edges_along_tile_borders_are_drawn_once():
    """Fig. 7's puzzle at 800: its bricks' lines run along the borders of tiles of 400, and
    a tab leaves such a line into one tile and comes back: each segment is one tile's."""
    script = str(Path(__file__).parents[2] / "examples" / "program" / "fig07_mappers.py")
    size = (800.0, 800.0)
    ref = evaluate_world(script, size, seed=1)
    arr = tiled("program", script, size, tile_size=400.0, halo=200.0, seed=1)
    _compare(ref, arr, 400.0, 200.0, 0.0, size)


@pytest.mark.slow
def test_a_tile_alone_is_the_same_tile(tmp_path):
    """A tile needs nothing from the others (any worker, any order): run alone, with the
    partition's field drawn afresh, it is the same bytes as in the whole world."""
    script = _script(tmp_path, VORONOI, "alone")
    arr = tiled("program", script, SIZE, tile_size=80.0, halo=30.0, seed=2)
    _world._CACHE.clear()
    t = plan(SIZE, 80.0)[0][4]  # the middle tile, last of its phase
    alone = _world.evaluate_tile(script, "arrangement", SIZE, t.rect, 30.0, 2)
    mine = arr.select(np.asarray(arr["tile"]) == 4)
    assert len(alone) == len(mine) > 0
    assert np.array_equal(alone.x, mine.x) and np.array_equal(alone.y, mine.y)
    assert [s.to_dict() for p in alone.element_parts for s in p] == [s.to_dict() for p in mine.element_parts for s in p]
    other = _world.evaluate_tile(script, "arrangement", SIZE, t.rect, 30.0, 3)
    assert not np.array_equal(np.sort(other.x), np.sort(alone.x))  # the seed matters


def test_uniform_sites_keep_their_distance_across_field_cells():
    """The field's Poisson-disk cells (Wei's phases) make one Poisson-disk set."""
    from scipy.spatial import cKDTree

    from strew.program._sampling import DISK_PACKING

    d = 0.01
    c = _world.FIELD_CELL / np.sqrt(d)
    pts = _world.field_sites("uniform_partition", d, 7, (-c, -c, 2.5 * c, 2.5 * c))
    r = np.sqrt(DISK_PACKING / d)
    dist, _ = cKDTree(pts).query(pts, k=2)
    assert dist[:, 1].min() >= r * (1 - 1e-12)
    # and the field is maximal up to the cells' borders: no disk of radius 2r empty
    g = np.mgrid[-c + 3 * r : 2.5 * c - 3 * r : 40j, -c + 3 * r : 2.5 * c - 3 * r : 40j].reshape(2, -1).T
    assert cKDTree(pts).query(g)[0].max() < 2 * r


@pytest.mark.slow
def test_cli_one_and_two_workers_write_the_same_tiles(tmp_path):
    pytest.importorskip("dask.distributed")
    pytest.importorskip("pyarrow")
    from strew.cli import main

    script = _script(tmp_path, VORONOI, "cli")
    outs = []
    for workers in (1, 2):
        out = tmp_path / f"w{workers}.parquet"
        assert main(["world", "program", script, "--size", "240x200", "--tile-size", "80", "--halo", "30",
                     "--workers", str(workers), "--seed", "4", "--out", str(out), "-q"]) == 0
        outs.append(out)
    names = sorted(p.name for p in outs[0].glob("part-*.parquet"))
    assert len(names) == 9
    for n in names:
        assert (outs[0] / n).read_bytes() == (outs[1] / n).read_bytes(), n
    from strew.io._parquet import load_parquet

    back = load_parquet(outs[0])
    assert len(back) > 0 and set(np.asarray(back["cell"]).tolist()) == {"face", "edge"}
