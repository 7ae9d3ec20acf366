"""Tiled worlds (issue 19): phases, seeds, Dask, Parquet, the ``strew world`` CLI."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import strew
from strew._errors import InputError
from strew.cli import main
from strew.tiles import _neighbours, plan, tile_rng, tiled, world

sys.path.insert(0, str(Path(__file__).parent))
from world_stats import border_strips, overlapping_pairs  # noqa: E402

pytest.importorskip("dask.distributed")
pytest.importorskip("pyarrow")

from strew.io._parquet import ParquetWriter, iter_parquet_tiles, load_parquet, parquet_info  # noqa: E402

SHAPES = {"bar": strew.Shape.rectangle(3, 1.5), "disc": strew.Shape.circle(1.0, 16)}
SIZE = (150.0, 120.0)  # 5 x 4 = 20 tiles
TILE = 30.0


def _write(folder: Path, workers: int) -> tuple[strew.Arrangement, object]:
    w = ParquetWriter(folder)
    parts = {}

    def sink(k, a):
        w.write(k, a)
        parts[k] = a

    info = world("pack", SHAPES, SIZE, tile_size=TILE, seed=3, workers=workers, processes=False, sink=sink)
    w.close(info.shapes, info.meta, strew.Region.rectangle(*SIZE))
    arr = strew.arrangement.concat([parts[k] for k in sorted(parts) if len(parts[k])])
    return arr, info


@pytest.fixture(scope="module")
def worlds(tmp_path_factory):
    base = tmp_path_factory.mktemp("worlds")
    one = _write(base / "one.parquet", 1)
    two = _write(base / "two.parquet", 2)  # a LocalCluster of 2 threads (processes=False)
    return base, one, two


def test_one_and_two_workers_write_the_same_bytes(worlds):
    base, (a1, i1), (a2, i2) = worlds
    files1 = sorted(p.name for p in (base / "one.parquet").iterdir())
    files2 = sorted(p.name for p in (base / "two.parquet").iterdir())
    assert files1 == files2 and len(files1) == 21  # 20 tiles and _common_metadata
    for name in files1:
        assert (base / "one.parquet" / name).read_bytes() == (base / "two.parquet" / name).read_bytes(), name
    assert a1.equals(a2)
    assert i2.workers == 2 and i1.workers == 1
    assert i1.meta == i2.meta


def test_no_overlaps_across_borders_and_all_inside(worlds):
    _, (arr, info), _ = worlds
    assert len(arr) > 2000
    assert overlapping_pairs(arr) == 0
    region = strew.Region.rectangle(*SIZE)
    import shapely

    assert shapely.contains(region.geometry.buffer(1e-6), arr.geometry_of("geometry")).all()
    # each element in the tile that owns its centre, every tile holds elements
    tiles, nx, _ = plan(SIZE, TILE)
    assert (info.counts > 0).all() and info.counts.sum() == len(arr)


def test_border_strips_match_the_interior(worlds):
    # Strips of half-width halo along the inner tile borders against the interior, pooled
    # over the fixture's world (seed 3) and two more seeds: one 150 x 120 world is too
    # small for a 3% verdict on its own (seeds 3-22 at 7c83aee: density sd 0.017, 1 of
    # 20 below 0.97; with pack's compactness-weighted ramp, 2 of 20, mean 0.989 against
    # 0.992). Pooled seeds 3-5: 0.989 at 7c83aee, 0.980 with the ramp. Before the
    # keep-rule of run_tile (a tile keeps what it places in finished neighbours): 0.948x.
    _, (arr, info), _ = worlds
    halo = info.meta["world"]["halo"]
    counts = np.zeros(4)
    bars_strip, bars_inner = [], []
    for a in (arr, *(tiled("pack", SHAPES, SIZE, tile_size=TILE, seed=s, workers=1) for s in (4, 5))):
        strip, inner, sa, ia = border_strips(a, SIZE, TILE, halo, halo)
        counts += (strip.sum(), sa, inner.sum(), ia)
        bars_strip.append(a.kind[strip] == 0)
        bars_inner.append(a.kind[inner] == 0)
    ratio = (counts[0] / counts[1]) / (counts[2] / counts[3])
    assert 0.97 <= ratio <= 1.03, ratio
    frac_strip = np.concatenate(bars_strip).mean()
    frac_inner = np.concatenate(bars_inner).mean()
    assert abs(frac_strip - frac_inner) < 0.03, (frac_strip, frac_inner)


def test_parquet_round_trip_and_streaming(worlds):
    import pandas as pd

    base, (arr, info), _ = worlds
    folder = base / "one.parquet"
    back = load_parquet(folder)
    assert back.without_columns("tile").equals(arr.replace(region=back.region, meta=back.meta))
    assert np.array_equal(np.bincount(back["tile"], minlength=20), info.counts)
    assert back.meta["world"]["tiles"] == 20 and back.meta["seed"] == 3
    assert strew.load(folder).equals(back)
    meta = parquet_info(folder)
    assert meta["elements"] == len(arr) and meta["tiles"] == 20
    assert set(meta["shapes"]) == {"bar", "disc"}
    sizes = [len(t) for t in iter_parquet_tiles(folder)]
    assert sizes == info.counts.tolist()
    df = pd.read_parquet(folder)
    assert len(df) == len(arr) and set(df.kind.astype(str)) == {"bar", "disc"}
    with pytest.raises(InputError, match="too many to load whole"):
        load_parquet(folder, max_elements=100)


def test_seeds_derive_by_spawning_and_differ():
    for k in (0, 7, 19):
        child = np.random.SeedSequence(3).spawn(20)[k]
        want = np.random.Generator(np.random.PCG64(child)).random(4)
        assert np.array_equal(tile_rng(3, k).random(4), want)
    a = tiled("pack", SHAPES, (60, 30), tile_size=30, seed=1)
    b = tiled("pack", SHAPES, (60, 30), tile_size=30, seed=2)
    assert not np.array_equal(a.x[:10], b.x[:10])


@settings(max_examples=40, deadline=None)
@given(st.floats(1, 500), st.floats(1, 500), st.floats(0.02, 2))
def test_plan_partitions_and_phases_never_touch(w, h, frac):
    t = frac * max(w, h) / 1  # at most 50 x 50 tiles
    tiles, nx, ny = plan((w, h), t)
    assert len(tiles) == nx * ny
    area = sum((r[2] - r[0]) * (r[3] - r[1]) for r in (x.rect for x in tiles))
    assert area == pytest.approx(w * h, rel=1e-9)
    for x in tiles:
        assert x.rect[2] > x.rect[0] and x.rect[3] > x.rect[1]
        for d in _neighbours(x, nx, ny):  # dependencies: touching tiles of a lower phase
            y = tiles[d]
            assert y.phase < x.phase and max(abs(y.i - x.i), abs(y.j - x.j)) == 1
        # tiles of the same phase are at least one tile apart: every touching tile differs
        for dj in (-1, 0, 1):
            for di in (-1, 0, 1):
                i, j = x.i + di, x.j + dj
                if (di or dj) and 0 <= i < nx and 0 <= j < ny:
                    assert tiles[j * nx + i].phase != x.phase


def test_bad_input_names_the_field():
    with pytest.raises(InputError, match="^halo"):
        world("pack", SHAPES, (60, 60), tile_size=4)
    with pytest.raises(InputError, match="^tile_size"):
        world("pack", SHAPES, (60, 60), tile_size=-1)
    with pytest.raises(InputError, match="^method"):
        world("grow", "x", (60, 60), tile_size=30)
    with pytest.raises(InputError, match="^workers"):
        world("pack", SHAPES, (60, 60), tile_size=30, workers=0)
    with pytest.raises(InputError, match="^max_failures"):
        world("pack", SHAPES, (60, 60), tile_size=30, max_failures=0)


@pytest.fixture
def shapes_file(tmp_path):
    from strew.io import save

    p = tmp_path / "shapes.json"
    save(strew.Arrangement(SHAPES, [], [], []), p)
    return p


def test_cli_world_writes_parquet_and_a_bounded_overview(tmp_path, shapes_file, worlds):
    from PIL import Image

    base, (arr, _), _ = worlds
    out = tmp_path / "w.parquet"
    png = tmp_path / "w.png"
    argv = ["world", "pack", str(shapes_file), "--size", "150x120", "--tile-size", "30", "--workers", "1",
            "--seed", "3", "--overview-px", "300", "--out", str(out), "--out", str(png), "-q"]
    assert main(argv) == 0
    for p in sorted(out.glob("part-*.parquet")):  # the CLI and Python give the same tiles
        assert p.read_bytes() == (base / "one.parquet" / p.name).read_bytes()
    assert load_parquet(out).meta["command"].startswith("strew world pack")
    im = Image.open(png)
    assert im.size == (300, 240)
    # elements drawn: not blank, and not one colour
    px = np.asarray(im.convert("RGB")).reshape(-1, 3)
    assert 0.05 < (px.sum(axis=1) < 3 * 250).mean() < 0.95


def test_cli_unreachable_scheduler_exits_2_quickly(tmp_path, shapes_file, capsys):
    import time

    t0 = time.perf_counter()
    argv = ["world", "pack", str(shapes_file), "--size", "60x60", "--tile-size", "30", "--scheduler",
            "tcp://127.0.0.1:9", "--timeout", "1", "--out", str(tmp_path / "x.parquet"), "-q"]
    assert main(argv) == 2
    assert "--scheduler: no Dask scheduler answers at tcp://127.0.0.1:9" in capsys.readouterr().err
    assert time.perf_counter() - t0 < 15
    assert not (tmp_path / "x.parquet").exists()


def test_cli_refuses_json_and_svg_worlds(tmp_path, shapes_file, capsys):
    argv = ["world", "pack", str(shapes_file), "--size", "60x60", "--tile-size", "30", "--out", str(tmp_path / "x.json")]
    assert main(argv) == 2
    assert "--out" in capsys.readouterr().err and not (tmp_path / "x.json").exists()


@pytest.mark.slow
def test_cli_two_worker_processes_give_the_same_tiles(tmp_path, shapes_file, worlds):
    # a real LocalCluster of 2 processes (each compiles or loads the kernels: ~15 s)
    base, _, _ = worlds
    out = tmp_path / "w.parquet"
    argv = ["world", "pack", str(shapes_file), "--size", "150x120", "--tile-size", "30", "--workers", "2",
            "--seed", "3", "--out", str(out), "-q"]
    assert main(argv) == 0
    names = sorted(p.name for p in out.glob("part-*.parquet"))
    assert len(names) == 20
    for name in names:
        assert (out / name).read_bytes() == (base / "one.parquet" / name).read_bytes(), name


def test_cli_info_summarises_a_dataset_without_loading_it(worlds, capsys):
    import json

    base, (arr, _), _ = worlds
    assert main(["info", str(base / "one.parquet"), "--json"]) == 0
    s = json.loads(capsys.readouterr().out)
    assert s["elements"] == len(arr) and s["tiles"] == 20
    assert s["counts"] == arr.counts()
    lo = [float(arr.x.min()), float(arr.y.min()), float(arr.x.max()), float(arr.y.max())]
    assert s["centre_bounds"] == pytest.approx(lo)


def test_synth_tiles_never_overlap_across_borders():
    # synth runs through the tiler without overlaps, with its finished neighbours as a
    # frozen neighbourhood (synth/_context.py); border-strip densities are measured by
    # `benchmarks/worlds.py --synth-seams` and asserted in tests/worlds/test_synth_tiles.py
    from strew.io import load

    ex = load(Path(__file__).parents[2] / "examples" / "exemplars" / "stones.svg")
    a = tiled("synth", ex, (300, 200), tile_size=100, seed=1)
    b = tiled("synth", ex, (300, 200), tile_size=100, seed=1)
    assert len(a) > 50 and a.equals(b)
    assert overlapping_pairs(a) == 0
    assert ((a.x >= 0) & (a.x <= 300) & (a.y >= 0) & (a.y <= 200)).all()


def test_libraries_agree_where_elements_carry_their_parts():
    # ornament's tiles name a kind with shapes that differ a little; its elements carry
    # their own geometry (parts), so the tiles concatenate with the first tile's shape
    from strew.arrangement import concat
    from strew.tiles import _harmonize, _own_parts

    small, big = strew.Shape.circle(1.0, 16), strew.Shape.circle(1.0 + 1e-12, 16)
    a = strew.Arrangement({"d": small}, ["d", "d"], [0.0, 5.0], [0.0, 0.0], columns={"parts": [[small], None]})
    b = strew.Arrangement({"d": big}, ["d"], [10.0], [0.0], columns={"parts": [[big]]})
    with pytest.raises(InputError, match="names different shapes"):
        concat([a, b])
    a = _own_parts(a)
    assert all(p is not None for p in a.element_parts)  # the element that drew its kind's shape now has it
    both = concat(_harmonize([a, b]))
    assert both.shapes["d"] == small and len(both) == 3
    assert both.geometry[2].equals(b.geometry[0])  # geometry kept through the parts
    plain = strew.Arrangement({"d": big}, ["d"], [10.0], [0.0])  # no parts: still refused
    with pytest.raises(InputError, match="names different shapes"):
        concat(_harmonize([a, plain]))


@pytest.mark.slow
def test_ornament_tiles_without_overlaps_and_round_trips_its_parts(tmp_path):
    # 2 tiles of ornament's dots (about 17 s on the loaded 2-core machine); measured at
    # 200 x 200 in tiles of 100: 1,984 dots, 0 overlaps, border strips 1.09x the interior
    # (flowers 160 x 80, tiles 80: 0.99x)
    from strew.io._parquet import ParquetWriter

    parts = {}
    info = world("ornament", "dots", (120, 60), tile_size=60, seed=1, sink=parts.__setitem__)
    a = tiled("ornament", "dots", (120, 60), tile_size=60, seed=1)
    assert len(a) > 150 and overlapping_pairs(a) == 0
    assert all(p is not None for p in a.element_parts)
    w = ParquetWriter(tmp_path / "o.parquet")
    for k in sorted(parts):
        w.write(k, parts[k])
    w.close(info.shapes, info.meta)
    back = load_parquet(tmp_path / "o.parquet")
    assert len(back) == len(a)
    assert all(g.equals(h) for g, h in zip(back.geometry, a.geometry))


def test_render_streams_a_dataset_to_png_and_refuses_large_svg(worlds, tmp_path, capsys, monkeypatch):
    from PIL import Image

    import strew.io._parquet as pq_mod

    base, (arr, _), _ = worlds
    folder = str(base / "one.parquet")
    png = tmp_path / "o.png"
    assert main(["render", folder, "--out", str(png), "--width", "300", "-q"]) == 0
    im = np.asarray(Image.open(png).convert("RGB"))
    assert im.shape == (240, 300, 3)
    assert 0.05 < (im.sum(axis=2) < 3 * 250).mean() < 0.95
    # the same picture as the overview that strew world draws while it runs
    from strew.io._overview import Overview

    ov = Overview(SIZE, 300, kinds=list(arr.shapes))
    for a in pq_mod.iter_parquet_tiles(folder):
        ov.add(a)
    assert np.array_equal(np.asarray(ov.image), im)
    # small worlds still convert to SVG; above the stated size the message points to Parquet
    assert main(["render", folder, "--out", str(tmp_path / "o.svg"), "-q"]) == 0
    assert (tmp_path / "o.svg").stat().st_size > 1000
    monkeypatch.setattr(pq_mod, "TEXT_LIMIT", 100)
    assert main(["render", folder, "--out", str(tmp_path / "big.json")]) == 2
    err = capsys.readouterr().err
    assert f"{len(arr):,} elements, more than 100 for SVG or JSON" in err and "Parquet" in err
    assert not (tmp_path / "big.json").exists()


def test_pyramid_levels_agree_and_match_the_overview(worlds, tmp_path):
    from PIL import Image

    from strew.io._overview import write_pyramid

    base, (arr, _), _ = worlds
    out = tmp_path / "pyr"
    n = write_pyramid(base / "one.parquet", out, 2)
    # level 2: 4 x 4 tiles over the 150 x 150 square; the world (150 x 120) misses none of
    # them (120 > 3/4 of 150): 16 + 4 + 1
    assert n == 21
    assert sorted(p.relative_to(out).as_posix() for p in out.glob("0/*/*.png")) == ["0/0/0.png"]
    z2 = {(int(p.parent.name), int(p.stem)): np.asarray(Image.open(p).convert("RGB")) for p in out.glob("2/*/*.png")}
    assert len(z2) == 16 and all(im.shape == (256, 256, 3) for im in z2.values())
    # the four level-2 tiles of the top-left quarter, halved, make level 1's tile 0/0
    big = np.zeros((512, 512, 3))
    for dx in (0, 1):
        for dy in (0, 1):
            big[dy * 256:(dy + 1) * 256, dx * 256:(dx + 1) * 256] = z2[(dx, dy)]
    halved = big.reshape(256, 2, 256, 2, 3).mean(axis=(1, 3))
    z1 = np.asarray(Image.open(out / "1" / "0" / "0.png").convert("RGB")).astype(float)
    assert np.abs(halved - z1).mean() < 2.0
    # the top row of the world (y near 120) is the bottom band of level 2's row 0
    # (the square's top 30 units lie above the world): drawn white
    top = z2[(1, 0)]
    assert (top[:40] == 255).all() and (top[-60:] < 250).any()
    with pytest.raises(InputError, match="pyramid-zoom"):
        write_pyramid(base / "one.parquet", out, 13)


def test_cli_pyramid_needs_a_parquet_out(tmp_path, shapes_file, capsys):
    argv = ["world", "pack", str(shapes_file), "--size", "60x60", "--tile-size", "30", "--out", str(tmp_path / "x.png"),
            "--pyramid", str(tmp_path / "pyr")]
    assert main(argv) == 2
    assert "--pyramid: the pyramid is drawn from the Parquet dataset" in capsys.readouterr().err
