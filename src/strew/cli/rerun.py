"""``strew rerun OUTPUT.json``: repeat the command recorded in an output's meta.

The recorded command runs again, writing to a temporary file of the same kind, with
``meta.command`` recorded unchanged; the result is compared with OUTPUT byte for byte.
Exit 0 when they are identical, 1 when they differ (the message says what may explain
it: another strew version, a changed input file). ``--out`` also writes the reproduction.
"""

from __future__ import annotations

import click

from ._common import echo, quiet_option


def _strip_outs(argv: list[str]) -> list[str]:
    out, skip = [], False
    for a in argv:
        if skip:
            skip = False
            continue
        if a in ("--out", "-o"):
            skip = True
            continue
        if a.startswith("--out="):
            continue
        out.append(a)
    return out


@click.command("rerun")
@click.argument("output", type=click.Path(dir_okay=False))
@click.option("--out", "-o", "outs", multiple=True, type=click.Path(dir_okay=False), help="Also write the reproduction here (repeatable).")
@quiet_option
def command(output: str, outs: tuple[str, ...], quiet: bool) -> None:
    """Repeat the run recorded in OUTPUT (.json or .svg) and check that it reproduces OUTPUT byte for byte.

    Run it from the folder the original command ran in (input paths are relative to it).
    """
    import shlex
    import tempfile
    from pathlib import Path

    from .. import __version__
    from .._errors import InputError
    from ..io import load
    from . import _common, cli

    src = Path(output)
    if src.suffix.lower() not in (".json", ".svg"):
        raise InputError(f"OUTPUT {output!r}: must be a .json or .svg output (a PNG keeps no meta)")
    arr = load(src)
    recorded = arr.meta.get("command")
    if not isinstance(recorded, str) or not recorded.startswith("strew "):
        raise InputError(f"meta.command: {src.name} records no strew command (from Python, use strew._method.rerun)")
    argv = _strip_outs(shlex.split(recorded)[1:])
    if argv and argv[0] == "rerun":
        raise InputError(f"meta.command: {src.name} records a rerun")
    with tempfile.TemporaryDirectory(prefix="strew-rerun-") as tmp:
        again = Path(tmp) / src.name
        _common._COMMAND_OVERRIDE.append(recorded)
        try:
            extra = [a for o in outs for a in ("--out", o)]
            with cli.make_context("strew", [*argv, "--out", str(again), *extra, "--quiet"]) as ctx:
                cli.invoke(ctx)
        finally:
            _common._COMMAND_OVERRIDE.pop()
        same = again.read_bytes() == src.read_bytes()
    if same:
        echo(f"reproduced {src} byte for byte: {recorded}", quiet=quiet)
        return
    why = []
    if arr.meta.get("generator") != f"strew {__version__}":
        why.append(f"it was made by {arr.meta.get('generator')}, this is strew {__version__}")
    why.append("an input file may have changed since")
    click.echo(f"strew: error: the rerun differs from {src} ({'; '.join(why)})", err=True)
    raise click.exceptions.Exit(1)
