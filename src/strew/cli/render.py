"""``strew render``: convert between .json, .svg and .png."""

from __future__ import annotations

import click

from ._common import check_outputs, out_option, quiet_option


@click.command("render")
@click.argument("input", type=click.Path(dir_okay=False))
@out_option()
@click.option("--width", type=click.IntRange(min=1), default=1024, show_default=True, help="PNG width in pixels.")
@quiet_option
def command(input: str, outs: tuple[str, ...], width: int, quiet: bool) -> None:
    """Convert INPUT (.json or .svg) into every --out (.json, .svg or .png)."""
    from ..io import load, save_many

    check_outputs(outs)
    if any(o.lower().endswith(".png") for o in outs):
        from .._limits import check_memory

        check_memory(4.0 * width * width, "--width")  # an RGBA raster, at most square
    arr = load(input)
    save_many(arr, outs, width=width)  # all or none
    if not quiet:
        for o in outs:
            click.echo(f"wrote {o} ({len(arr)} elements)", err=True)
