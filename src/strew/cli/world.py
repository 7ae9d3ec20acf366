"""``strew world METHOD``: a world too large for one process, tile by tile on Dask (issue 19).

``strew world pack SHAPE... --size 2000x2000 --tile-size 100 --workers 2 --out w.parquet
--out w.png``. Each method's options come from its spec, as for ``strew <method>``;
:func:`strew.tiles.world` does the work.
"""

from __future__ import annotations

import os
import sys
import time
from pathlib import Path
from typing import Any

import click

from .._errors import InputError
from .._method import names_to_flags, spec
from ._common import echo, progress_bar, quiet_option
from ._spec import INPUTS, _FILE_INPUTS, _convert, _param_option

_OUT_EXT = (".parquet", ".png")


def _check_outs(outs: tuple[str, ...]) -> None:
    if not outs:
        raise InputError("--out: give world.parquet and/or overview.png")
    for o in outs:
        ext = Path(o).suffix.lower()
        if ext not in _OUT_EXT:
            raise InputError(f"--out {o!r}: a world is written as .parquet (a dataset folder) or .png (an overview); "
                             f"{ext or 'no extension'} would not scale: write .parquet, then strew render a part of it")
        parent = Path(o).resolve().parent
        if not parent.is_dir():
            raise InputError(f"--out {o!r}: folder {parent} does not exist")


def _default_workers() -> int:
    try:
        import dask.distributed  # noqa: F401
    except ImportError:
        return 1
    return os.cpu_count() or 1


def _size(text: str) -> tuple[float, float]:
    w, sep, h = text.lower().partition("x")
    try:
        size = (float(w), float(h)) if sep else (float(w), float(w))
    except ValueError:
        raise InputError(f"--size: expected WxH, got {text!r}") from None
    return size


# what --seed, --halo and the command's help say per method: program's tiles are
# independent and draw from fields fixed in the plane (strew.program._world), and a
# program world is not periodic (refused at run time), so it has no --periodic
_SEED_HELP = {"program": "Random seed (a partition's sites come from field cells keyed by (seed, the partition, the cell); "
                         "the world does not depend on the tiles)."}
_HALO_HELP = {"program": "How far past its tile each tile runs the script [default: T/4]; it must hold every cell that "
                         "reaches into the tile, else the run is refused."}
_HOW = {"program": "each tile on its own, its cells the same as in one evaluation of the whole world"}
_NOT_IN_WORLD = {"program": ("periodic",)}


def _make(name: str) -> click.Command:
    s = spec(name)
    cli_params = [p for p in s.params if p.cli and p.name not in _NOT_IN_WORLD.get(name, ())]

    def callback(**options: Any) -> None:
        outs, quiet, seed = options.pop("outs"), options.pop("quiet"), options.pop("seed")
        size, tile_size, halo = options.pop("size"), options.pop("tile_size"), options.pop("halo")
        workers, scheduler, timeout = options.pop("workers"), options.pop("scheduler"), options.pop("timeout")
        overview_px = options.pop("overview_px")
        pyramid, zoom = options.pop("pyramid"), options.pop("pyramid_zoom")
        raw_input = options.pop(s.input.name)
        _check_outs(outs)
        if pyramid is not None and not any(o.lower().endswith(".parquet") for o in outs):
            raise InputError("--pyramid: the pyramid is drawn from the Parquet dataset: add --out world.parquet")
        values = {}
        for p in cli_params:
            v = _convert(p, options.get(p.name))
            if v is not None:
                values[p.name] = v
        inp = INPUTS[s.input.parse or "text"](raw_input)
        wsize = _size(size)
        from ..tiles import world

        sinks = []
        parquet = [o for o in outs if o.lower().endswith(".parquet")]
        pngs = [o for o in outs if o.lower().endswith(".png")]
        writers = []
        if parquet:
            from ..io._parquet import ParquetWriter

            writers = [ParquetWriter(o) for o in parquet]
            sinks += [w.write for w in writers]
        canvas = None
        if pngs:
            from ..io._overview import Overview

            canvas = Overview(wsize, overview_px)
            sinks.append(lambda k, a: canvas.add(a))

        def sink(k: int, a: Any) -> None:
            for f in sinks:
                f(k, a)

        def dashboard(link: str) -> None:
            if not quiet:
                click.echo(f"dask dashboard: {link}", err=True)

        t0 = time.perf_counter()
        try:
            with progress_bar(f"world {name}", quiet=quiet) as (prog, cancel):
                info = world(name, inp, wsize, tile_size=tile_size, halo=halo, seed=seed,
                             workers=workers or _default_workers(), scheduler=scheduler, timeout=timeout,
                             sink=sink, progress=prog, should_cancel=cancel, on_dashboard=dashboard, **values)
        except BaseException as exc:
            for w in writers:
                w.abort()
            if not isinstance(exc, InputError):
                raise
            msg = names_to_flags(s, str(exc))
            for word, flag in (("tile_size", "--tile-size"), ("halo", "--halo"), ("workers", "--workers"),
                               ("scheduler", "--scheduler"), ("size", "--size"), ("seed", "--seed")):
                if msg.startswith(word + ":"):
                    msg = flag + msg[len(word):]
            if msg.startswith("--halo:"):  # program's halo refusal names both options in its advice
                msg = msg.replace("raise halo ", "raise --halo ").replace("tile_size", "--tile-size")
            raise InputError(msg) from exc
        from ..region import Region
        from ._common import command_line

        meta = dict(info.meta, command=command_line())
        for w in writers:
            w.close(info.shapes, meta, Region.rectangle(*wsize))
        if canvas is not None:
            from ..io import atomic_write

            data = canvas.png()
            for o in pngs:
                atomic_write(o, data)
        if pyramid is not None:
            from ..io._overview import write_pyramid

            made = write_pyramid(parquet[0], pyramid, zoom)
            echo(f"pyramid: {made} PNG tiles of 256 px, levels 0-{zoom}, in {pyramid}/z/x/y.png", quiet=quiet)
        secs = time.perf_counter() - t0
        n = int(info.counts.sum())
        echo(f"world: {n:,} elements in {len(info.counts)} tiles ({', '.join(f'{k} {c:,}' for k, c in info.kinds.items())}), "
             f"{secs:.1f} s, {n / max(secs, 1e-9):,.0f} el/s on {info.workers} worker(s)", quiet=quiet)

    f: Any = callback
    for deco in reversed([
        click.argument(s.input.name, nargs=-1 if (s.input.metavar or "").endswith("...") else 1, required=True,
                       metavar=s.input.metavar,
                       type=click.Path(dir_okay=False) if s.input.parse in _FILE_INPUTS else click.STRING),
        click.option("--size", required=True, metavar="WxH", help="The world: rectangle [0, W] x [0, H]."),
        click.option("--tile-size", type=float, required=True, metavar="T", help="Side of a tile (document units)."),
        click.option("--halo", type=float, default=None, metavar="H",
                     help=_HALO_HELP.get(name, "How far a tile reaches into its neighbours [default: twice the largest "
                                                "element for pack, T/4 otherwise].")),
        click.option("--workers", type=int, default=None, metavar="N",
                     help="Local Dask workers [default: all cores; 1 runs in this process]."),
        click.option("--scheduler", default=None, metavar="tcp://HOST:PORT", help="Run on an existing Dask cluster."),
        click.option("--timeout", type=float, default=10.0, show_default=True, help="Seconds to wait for --scheduler."),
        *[_param_option(s, p) for p in cli_params],
        click.option("--seed", type=int, default=0, show_default=True, help=_SEED_HELP.get(name, "Random seed (tile k draws from (seed, k)).")),
        click.option("--overview-px", type=click.IntRange(16, 16384), default=2048, show_default=True,
                     help="Longer side of the PNG overview."),
        click.option("--pyramid", type=click.Path(file_okay=False), default=None, metavar="DIR",
                     help="Also write a z/x/y pyramid of 256-pixel PNG tiles (web map viewers) into DIR."),
        click.option("--pyramid-zoom", type=click.IntRange(0, 12), default=4, show_default=True, metavar="Z",
                     help="Deepest pyramid level: 2^Z x 2^Z tiles across the world's longer side."),
        click.option("--out", "-o", "outs", multiple=True, required=True, type=click.Path(),
                     help="world.parquet (dataset folder, one file per tile) and/or overview.png."),
        quiet_option,
    ]):
        f = deco(f)
    how = _HOW.get(name, "phases of 2x2 tiles, Wei 2008")
    return click.command(name, help=f"Fill a world with {name}, tile by tile ({how}), "
                         f"in this process or on Dask ({s.summary})")(f)


def render_dataset(input: str, outs: tuple[str, ...], width: int, quiet: bool) -> None:
    """``strew render world.parquet --out ...``: a PNG overview streamed from the files;
    SVG and JSON only up to :data:`strew.io._parquet.TEXT_LIMIT` elements (then loaded)."""
    from ..io import atomic_write
    from ..io._overview import render_dataset_png
    from ..io._parquet import TEXT_LIMIT, load_parquet, parquet_info
    from ._common import check_outputs, save_outputs

    check_outputs(outs)
    info = parquet_info(input)
    n = info["elements"]
    for o in outs:
        if not o.lower().endswith(".png") and n > TEXT_LIMIT:
            raise InputError(f"--out {o}: the world holds {n:,} elements, more than {TEXT_LIMIT:,} for SVG or JSON "
                             "(hundreds of MB of text); keep it as Parquet (pandas, DuckDB or strew.io.iter_parquet_tiles "
                             "read it) and render a PNG overview or a pyramid (strew world --pyramid)")
    size = info["meta"].get("world", {}).get("size") or [1.0, 1.0]
    for o in outs:
        if o.lower().endswith(".png"):
            from .._limits import check_memory

            side = max(1, round(width * max(size) / size[0]))
            check_memory(4.0 * side * side, "--width")
            atomic_write(o, render_dataset_png(input, side))
        else:
            save_outputs(load_parquet(input, max_elements=TEXT_LIMIT), (o,), width=width)
        echo(f"wrote {o} ({n:,} elements)", quiet=quiet)


class _WorldGroup(click.Group):
    def list_commands(self, ctx: click.Context) -> list[str]:
        from ..tiles import TILED_METHODS

        return list(TILED_METHODS)

    def get_command(self, ctx: click.Context, name: str) -> click.Command | None:
        from ..tiles import TILED_METHODS

        return _make(name) if name in TILED_METHODS else None


@click.group("world", cls=_WorldGroup)
def command() -> None:
    """Fill a world too large for one process, tile by tile, on Dask.

    Needs pip install 'strew[distributed]' for more than one worker and for Parquet.
    """


if __name__ == "__main__":  # pragma: no cover
    sys.exit(0)
