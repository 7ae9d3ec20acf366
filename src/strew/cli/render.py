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
    from pathlib import Path

    from ..io import load, save

    check_outputs(outs)
    arr = load(input)
    for o in outs:
        kwargs = {"width": width} if Path(o).suffix.lower() == ".png" else {}
        save(arr, o, **kwargs)
        if not quiet:
            click.echo(f"wrote {o} ({len(arr)} elements)", err=True)
