"""The ``strew`` command line: a thin click layer over the library.

Commands live in their own modules (``strew.cli.<name>``) and are imported only when
run, so that ``strew --help`` answers quickly. To add a command, write
``src/strew/cli/<name>.py`` defining a click command called ``command`` and add one line
to :data:`COMMANDS`.

Exit codes (DESIGN.md): 0 success; 2 bad input or usage, with a one-line message that
names the problem; 130 interrupted (Ctrl-C), with nothing written; 1 internal error.
"""

from __future__ import annotations

import importlib
import sys

import click

from .._version import __version__

__all__ = ["main", "cli", "COMMANDS"]

# name -> (module, one-line help). Keep the help here so that `strew --help` imports nothing.
COMMANDS: dict[str, tuple[str, str]] = {
    "render": ("strew.cli.render", "Convert between .json, .svg and .png."),
    "info": ("strew.cli.info", "Counts per kind, bounds and metrics of an arrangement."),
    "compare": ("strew.cli.compare", "How faithfully a result continues its exemplar (fidelity metrics)."),
    "demo": ("strew.cli.demo", "Write a gallery of examples (SVG, PNG and index.html)."),
    "ornament": ("strew.cli.ornament", "Grow rule-driven floral ornament into a panel (adaptive clip art)."),
    "run": ("strew.cli.run", "Run a program script (planar maps, partitions, mappers) and write its arrangement."),
    "pack": ("strew.cli.pack", "Pack shapes densely and non-periodically into a region (fill-gap)."),
    "surface": ("strew.cli.surface", "Pack shapes on a 3D surface mesh (.glb, .json, .png preview)."),
    "grow": ("strew.cli.grow", "Grow from an exemplar, element by element, from one seed (Ijiri et al.)."),
    "studio": ("strew.cli.studio", "Paint with example palettes in the browser (brush, spray, filler, eraser)."),
    "synth": ("strew.cli.synth", "Synthesize a texture from exemplars by fast region growing (Davison et al.)."),
    "world": ("strew.cli.world", "Fill a world too large for one process, tile by tile on Dask (Parquet, PNG overview)."),
    "rerun": ("strew.cli.rerun", "Repeat the command recorded in an output's meta and check it byte for byte."),
}


class LazyGroup(click.Group):
    """A click group whose subcommands are imported on first use."""

    def list_commands(self, ctx: click.Context) -> list[str]:
        return sorted(COMMANDS)

    def get_command(self, ctx: click.Context, name: str) -> click.Command | None:
        if name not in COMMANDS:
            return None
        module = importlib.import_module(COMMANDS[name][0])
        return module.command

    def format_commands(self, ctx: click.Context, formatter: click.HelpFormatter) -> None:
        rows = [(name, COMMANDS[name][1]) for name in self.list_commands(ctx)]
        if rows:
            with formatter.section("Commands"):
                formatter.write_dl(rows)


@click.group(cls=LazyGroup, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, "--version", prog_name="strew", message="%(prog)s %(version)s")
@click.option("--limit-elements", metavar="N", default=None, help="Refuse work expected to make more elements [default: 1e7].")
@click.option("--limit-memory", metavar="SIZE", default=None, help="Refuse work expected to need more memory, e.g. 8GB [default: 4GB].")
@click.option("--limit-file-size", metavar="SIZE", default=None, help="Refuse larger input files, e.g. 200MB [default: 64MB].")
@click.option("--limit-paths", metavar="N", default=None, help="Refuse SVG files with more objects [default: 50000].")
def cli(limit_elements: str | None, limit_memory: str | None, limit_file_size: str | None, limit_paths: str | None) -> None:
    """strew: fill 2D regions with many small vector elements.

    Every command reads .json (strew documents) or .svg, and writes whatever --out
    names: .json, .svg or .png. --seed makes runs repeatable.

    Work is estimated before it starts: input that would make too many elements, need
    too much memory, or files too large, are refused with exit code 2; the --limit-*
    options (given before the command) or STREW_LIMIT_* variables raise the limits.
    Ctrl-C stops a command with exit code 130 and writes nothing.

    `strew run` scripts and `strew ornament` rule files are Python programs: they run
    with your rights, so run only files you trust.
    """
    given = {
        "elements": limit_elements,
        "memory": limit_memory,
        "file_size": limit_file_size,
        "paths": limit_paths,
    }
    if any(v is not None for v in given.values()):
        from .._limits import set_limits

        set_limits(**{k: v for k, v in given.items() if v is not None})


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``strew`` script; returns the exit code."""
    from ._common import run_main

    return run_main(cli, argv)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
