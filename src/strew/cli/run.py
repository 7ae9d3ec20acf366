"""``strew run``: run a program script (Loi et al.) and write its arrangement."""

from __future__ import annotations

import click

from ._common import check_outputs, echo, out_option, quiet_option, seed_option


@click.command("run")
@click.argument("script", type=click.Path(dir_okay=False))
@click.option("--size", type=float, default=2000, show_default=True, help="Evaluate on the square [0, N] x [0, N].")
@click.option("--name", default="arrangement", show_default=True, help="Module-level variable to evaluate.")
@seed_option
@out_option()
@quiet_option
def command(script: str, size: float, name: str, seed: int, outs: tuple[str, ...], quiet: bool) -> None:
    """Run SCRIPT.py as `python SCRIPT.py` would, evaluate its `arrangement` on the
    square [0, N]^2 and write it: faces as closed paths, edges as open paths.

    SCRIPT is a Python program: it runs with your rights (it can read, write and delete
    your files), so run only scripts you trust.
    """
    import time

    from ..program import run_script
    from ._common import write_outputs

    check_outputs(outs)
    import math

    from .._errors import InputError
    from .._limits import MAX_COORD

    if not (math.isfinite(size) and 0 < size <= MAX_COORD):
        raise InputError(f"--size: must be a positive number up to {MAX_COORD:.0e}, got {size!r}")
    t0 = time.perf_counter()
    pm, arr = run_script(script, size=size, seed=seed, name=name)
    dt = time.perf_counter() - t0
    if len(arr) == 0:
        click.echo(f"strew: warning: {name!r} of {script} is empty on [0, {size:g}]^2: its lengths may not fit this --size", err=True)
    write_outputs(arr, outs, method="program", seed=seed, params={"script": script, "size": size, "name": name}, quiet=quiet)
    echo(
        f"{script}: {pm.n_vertices} vertices, {pm.n_edges} edges, {pm.n_faces - 1} bounded faces in {dt:.2f} s",
        quiet=quiet,
    )
