"""``strew run``: run a program script (Loi et al.) and write its arrangement.

Options, checks and ``--help`` come from :data:`strew.program.SPEC`; ``--size N`` is
the square [0, N]^2 (``--size WxH`` and ``--region FILE`` work as elsewhere).
"""

from __future__ import annotations

import click

from ..program._script import SPEC
from ._spec import Hooks, method_command


def _finish(run, arr) -> None:
    if len(arr) == 0:
        name = run.values.get("name", "arrangement")
        click.echo(f"strew: warning: {name!r} of {run.input} is empty on this region: its lengths may not fit this --size", err=True)


def _summary(run, arr) -> str:
    pm = arr.meta.get("program", {})
    return (f"{run.input}: {pm.get('vertices', 0)} vertices, {pm.get('edges', 0)} edges, {pm.get('faces', 1) - 1} bounded faces "
            f"in {run.seconds:.2f} s")


command = method_command(SPEC, Hooks(
    finish=_finish,
    summary=_summary,
    domain="square",
    description="Run SCRIPT.py as `python SCRIPT.py` would, evaluate its `arrangement` on the region (default the "
    "square [0, 2000]^2; --size N for [0, N]^2) and write it: faces as closed paths, edges as open paths.\n\n"
    "SCRIPT is a Python program: it runs with your rights (it can read, write and delete your files), so run only "
    "scripts you trust.",
))
