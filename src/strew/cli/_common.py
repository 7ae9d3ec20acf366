"""Shared CLI plumbing: common options, error handling, progress bars, outputs.

Every command module uses these so that flags, messages and exit codes agree:

- :func:`out_option`, :func:`seed_option`, :func:`domain_options`, :func:`quiet_option`
  are decorators adding ``--out``, ``--seed``, ``--region/--size`` and ``--quiet``;
- :func:`resolve_domain` turns ``--region``/``--size`` into a :class:`~strew.Region`;
- :func:`progress_bar` gives a ``(progress, should_cancel)`` pair for library calls,
  drawing a rich bar on stderr (off with ``--quiet`` or when stderr is not a TTY);
- :func:`write_outputs` records meta (version, command, seed, params) and writes every
  ``--out`` atomically;
- :func:`parse_range`, :func:`parse_point` parse ``A:B`` and ``x,y`` values.
"""

from __future__ import annotations

import contextlib
import shlex
import sys
import threading
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import click

from .._errors import Cancelled, InputError

if TYPE_CHECKING:
    from ..arrangement import Arrangement
    from ..region import Region

__all__ = [
    "out_option",
    "seed_option",
    "domain_options",
    "quiet_option",
    "resolve_domain",
    "progress_bar",
    "write_outputs",
    "check_outputs",
    "parse_range",
    "parse_point",
    "echo",
    "run_main",
]


def _fail(message: str) -> None:
    click.echo(f"strew: error: {message}", err=True)


def run_main(group: click.Group, argv: Sequence[str] | None = None) -> int:
    """Run the click group, mapping errors to exit codes (0, 1, 2) and one-line messages."""
    args = list(sys.argv[1:] if argv is None else argv)
    try:
        group.main(args=args, prog_name="strew", standalone_mode=False)
    except click.exceptions.Exit as exc:
        return int(exc.exit_code or 0)
    except click.exceptions.Abort:
        _fail("aborted")
        return 1
    except click.ClickException as exc:  # usage errors and bad parameters
        msg = exc.format_message().replace("\n", " ")
        _fail(msg)
        return 2
    except InputError as exc:
        _fail(str(exc).replace("\n", " "))
        return 2
    except Cancelled:
        _fail("cancelled")
        return 1
    except KeyboardInterrupt:
        _fail("interrupted")
        return 130
    except BrokenPipeError:
        return 0
    except Exception as exc:  # pragma: no cover - reported, not expected
        import traceback

        traceback.print_exc()
        _fail(f"internal error: {type(exc).__name__}: {exc}")
        return 1
    return 0


def echo(message: str, *, quiet: bool = False) -> None:
    """Print a result line on stdout unless quiet."""
    if not quiet:
        click.echo(message)


# -- option decorators ------------------------------------------------------------------
def out_option(required: bool = True) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """``--out PATH`` (repeatable); the extension picks the format."""
    return click.option(
        "--out",
        "-o",
        "outs",
        multiple=True,
        required=required,
        type=click.Path(dir_okay=False),
        help="Output file; .json, .svg or .png (repeatable).",
    )


def seed_option(f: Callable[..., Any]) -> Callable[..., Any]:
    """``--seed N``: every random choice comes from ``numpy.random.default_rng(N)``."""
    return click.option("--seed", type=int, default=0, show_default=True, help="Random seed.")(f)


def quiet_option(f: Callable[..., Any]) -> Callable[..., Any]:
    """``--quiet``: no progress bar and no summary lines."""
    return click.option("--quiet", "-q", is_flag=True, help="No progress bar or summary.")(f)


def domain_options(default_size: str | None = None) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """``--region FILE`` (SVG or JSON) or ``--size WxH`` (the rectangle [0, W] x [0, H])."""

    def deco(f: Callable[..., Any]) -> Callable[..., Any]:
        f = click.option(
            "--size",
            default=default_size,
            show_default=default_size is not None,
            help="Rectangle [0, W] x [0, H], written WxH.",
        )(f)
        f = click.option(
            "--region", type=click.Path(dir_okay=False), default=None, help="Region to fill: SVG or JSON file."
        )(f)
        return f

    return deco


def resolve_domain(region: str | None, size: str | None) -> Region | None:
    """The :class:`Region` given by ``--region`` or ``--size`` (``--region`` wins if both)."""
    from ..io import load_region
    from ..region import Region

    if region is not None:
        return load_region(region)
    if size is not None:
        return Region.from_size(size)
    return None


def parse_range(text: str | None, name: str, *, default: tuple[float, float] | None = None) -> tuple[float, float] | None:
    """Parse ``A:B`` (or a single value ``A``, meaning ``A:A``) with ``A <= B``."""
    if text is None:
        return default
    parts = str(text).split(":")
    try:
        if len(parts) == 1:
            lo = hi = float(parts[0])
        elif len(parts) == 2:
            lo, hi = float(parts[0]), float(parts[1])
        else:
            raise ValueError
    except ValueError:
        raise InputError(f"{name}: expected A:B, got {text!r}") from None
    if lo > hi:
        raise InputError(f"{name}: inverted range {text!r} (A must not exceed B)")
    return lo, hi


def parse_point(text: str, name: str) -> tuple[float, float]:
    """Parse ``x,y``."""
    parts = str(text).split(",")
    try:
        if len(parts) != 2:
            raise ValueError
        return float(parts[0]), float(parts[1])
    except ValueError:
        raise InputError(f"{name}: expected x,y, got {text!r}") from None


# -- progress -----------------------------------------------------------------------------
@contextlib.contextmanager
def progress_bar(description: str, *, quiet: bool = False) -> Iterator[tuple[Callable[[int, int | None, str], None] | None, Callable[[], bool]]]:
    """Yield ``(progress, should_cancel)`` for a library call.

    ``progress`` draws a rich progress bar on stderr; it is None when ``quiet`` or when
    stderr is not a terminal. ``should_cancel`` turns True after Ctrl-C, so that the
    library stops cleanly at its next check (a second Ctrl-C interrupts at once).
    """
    cancelled = threading.Event()

    def should_cancel() -> bool:
        return cancelled.is_set()

    if quiet or not sys.stderr.isatty():
        yield None, should_cancel
        return
    from rich.console import Console
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

    console = Console(stderr=True)
    with Progress(
        TextColumn("[bold]{task.description}"),
        BarColumn(),
        MofNCompleteColumn(),
        TextColumn("{task.fields[note]}"),
        TimeElapsedColumn(),
        console=console,
        transient=True,
    ) as bar:
        task = bar.add_task(description, total=None, note="")

        def progress(done: int, total: int | None, message: str) -> None:
            bar.update(task, completed=done, total=total, note=message or "")

        try:
            yield progress, should_cancel
        except KeyboardInterrupt:
            cancelled.set()
            raise


# -- outputs ------------------------------------------------------------------------------
def check_outputs(outs: Sequence[str]) -> None:
    """Validate every ``--out`` before doing work (extension and folder)."""
    from ..io import check_output_path

    if not outs:
        raise InputError("--out: give at least one output file")
    for o in outs:
        check_output_path(o)


def command_line() -> str:
    """The command line that produced this run, for ``meta.command``."""
    return "strew " + " ".join(shlex.quote(a) for a in sys.argv[1:])


def write_outputs(
    arr: Arrangement,
    outs: Sequence[str],
    *,
    method: str | None = None,
    seed: int | None = None,
    params: dict[str, Any] | None = None,
    quiet: bool = False,
) -> Arrangement:
    """Record how the arrangement was made in ``meta`` and write every output atomically.

    Returns the arrangement with its meta filled in.
    """
    from .. import __version__
    from ..io import save

    meta: dict[str, Any] = {"generator": f"strew {__version__}"}
    if method is not None:
        meta["method"] = method
    if seed is not None:
        meta["seed"] = seed
    if params is not None:
        meta["params"] = params
    meta["command"] = command_line()
    arr = arr.with_meta(**meta)
    for o in outs:
        save(arr, o)
        if not quiet:
            click.echo(f"wrote {Path(o)}", err=True)
    return arr
