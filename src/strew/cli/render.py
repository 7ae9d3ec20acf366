"""``strew render``: convert between .json, .svg and .png."""

from __future__ import annotations

import click

from ._common import check_outputs, out_option, quiet_option, save_outputs, visible_counts


@click.command("render")
@click.argument("input", type=click.Path())
@out_option()
@click.option("--width", type=click.IntRange(min=1), default=1024, show_default=True, help="PNG width in pixels.")
@quiet_option
def command(input: str, outs: tuple[str, ...], width: int, quiet: bool) -> None:
    """Convert INPUT (.json or .svg; - reads standard input) into every --out (.json, .svg or .png).

    A periodic tile (made with --periodic) is drawn complete and seamless; --repeat 3x3
    previews it repeated (the PNG width is rounded to whole pixels per tile).
    """
    from ..io import load
    from ..io._parquet import is_dataset

    if is_dataset(input):  # a world.parquet (issue 19): a PNG streamed file by file, never loaded whole
        from .world import render_dataset

        return render_dataset(input, outs, width, quiet)
    check_outputs(outs)
    if any(o.lower().endswith(".png") for o in outs):
        from .._limits import check_memory

        check_memory(4.0 * width * width, "--width")  # an RGBA raster, at most square
    arr = load(input)
    files = save_outputs(arr, outs, width=width)  # all or none; '-' is standard output
    if not quiet:
        for o in files:
            click.echo(f"wrote {o} ({visible_counts(arr)[0]} elements)", err=True)
