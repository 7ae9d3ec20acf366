"""Shared CLI plumbing: common options, error handling, progress bars, outputs.

Every command module uses these so that flags, messages and exit codes agree:

- :func:`out_option`, :func:`seed_option`, :func:`domain_options`, :func:`quiet_option`
  are decorators adding ``--out``, ``--seed``, ``--region/--size`` and ``--quiet``;
- :func:`resolve_domain` turns ``--region``/``--size`` into a :class:`~strew.Region`;
- :func:`progress_bar` gives a ``(progress, should_cancel)`` pair for library calls,
  drawing a rich bar on stderr (off with ``--quiet`` or when stderr is not a TTY);
- :func:`write_outputs` adds the command line to meta (the library stamps the rest) and
  writes every ``--out`` atomically;
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


def _interrupted(exc: BaseException) -> bool:
    """Whether ``exc`` is, or was caused by, a Ctrl-C (also through a compiled kernel)."""
    seen = set()
    e: BaseException | None = exc
    while e is not None and id(e) not in seen:
        if isinstance(e, (KeyboardInterrupt, Cancelled)):
            return True
        seen.add(id(e))
        e = e.__cause__ or e.__context__
    return False


@contextlib.contextmanager
def _one_line_warnings() -> Iterator[None]:
    """Warnings raised outside a method's own capture (reading an SVG, say) print as one
    ``strew: warning: ...`` line, like the method's, not Python's two-line format."""
    import warnings

    def show(message: Any, category: Any, filename: str, lineno: int, file: Any = None, line: Any = None) -> None:
        click.echo(f"strew: warning: {message}", err=True)

    saved = warnings.showwarning
    warnings.showwarning = show
    try:
        yield
    finally:
        warnings.showwarning = saved


def run_main(group: click.Group, argv: Sequence[str] | None = None) -> int:
    """Run the click group, mapping errors to exit codes (0, 1, 2, 130) and one-line messages.

    The group is invoked without click's own ``main`` wrapper, which would turn Ctrl-C
    into ``Abort`` (exit 1) after printing an empty line: here Ctrl-C exits 130 with one
    line, and since outputs are written only after the work, nothing is left behind.
    Limits set with ``--limit-*`` hold for this run only.
    """
    from .._limits import limits

    args = list(sys.argv[1:] if argv is None else argv)
    _ARGV[:] = args  # for meta.command (with '-' as given)
    _STDOUT.clear()
    try:
        with limits(), _one_line_warnings(), _stdin_inputs(args) as args:
            with group.make_context("strew", args) as ctx:
                group.invoke(ctx)
    except click.exceptions.Exit as exc:
        return int(exc.exit_code or 0)
    except click.exceptions.Abort as exc:
        if _interrupted(exc):
            _fail("interrupted")
            return 130
        _fail("aborted")
        return 1
    except click.ClickException as exc:  # usage errors and bad parameters
        msg = exc.format_message().replace("\n", " ")
        _fail(msg)
        return 2
    except InputError as exc:
        _fail(str(exc).replace("\n", " "))
        return 2
    except (Cancelled, KeyboardInterrupt):
        _fail("interrupted")
        return 130
    except BrokenPipeError:
        return 0
    except MemoryError:
        _fail("out of memory: the input asks for more work than this machine can hold (see --limit-memory)")
        return 2
    except Exception as exc:  # pragma: no cover - reported, not expected
        if _interrupted(exc):
            # e.g. numba's "CPUDispatcher(...) returned a result with an exception set"
            _fail("interrupted")
            return 130
        import traceback

        traceback.print_exc()
        _fail(f"internal error: {type(exc).__name__}: {exc}")
        return 1
    return 0


def visible_counts(arr: Arrangement) -> tuple[int, str]:
    """The visible element count and ``"kind n, ..."`` for a summary line.

    One count everywhere (issue 23 point 9): what the picture shows, as the gallery's
    captions and ``strew info`` give it; void and hidden elements are left out.
    """
    import numpy as np

    from ..metrics import visible

    vis = visible(arr)
    names = arr.kind_names[vis] if len(arr) else []
    kinds, n = np.unique(names, return_counts=True) if len(names) else ([], [])
    order = {k: i for i, k in enumerate(arr.kinds)}
    pairs = sorted(zip(kinds, n), key=lambda kv: order.get(kv[0], 0))
    return int(vis.sum()), ", ".join(f"{k} {int(c)}" for k, c in pairs)


def echo(message: str, *, quiet: bool = False) -> None:
    """Print a result line on stdout unless quiet (on stderr when ``--out -`` writes there)."""
    if not quiet:
        click.echo(message, err=bool(_STDOUT))


# -- standard input and output (issue 22 point 2) ------------------------------------------
# ``-`` as an input reads standard input; ``--out -`` writes standard output, in the
# format given by ``--format``. The data are the same bytes a file would get.
_STDOUT: list[str] = []  # the format of ``--out -`` in this run, once checked
_OUT_VALUE_FLAGS = ("-o", "--out", "--exemplar-out", "--plot")
_STDIN_CAP = 4 * 10**9  # bytes copied from a pipe at most


def _sniff(data: bytes) -> str:
    """The suffix of piped input: ``.svgz`` (gzip), ``.json`` or ``.svg``."""
    if data[:2] == b"\x1f\x8b":
        return ".svgz"
    head = data.lstrip()[:1]
    if head in (b"{", b"["):
        return ".json"
    if head == b"<":
        return ".svg"
    raise InputError("-: standard input is neither a strew document (JSON) nor an SVG")


@contextlib.contextmanager
def _stdin_inputs(args: list[str]) -> Iterator[list[str]]:
    """Replace an input argument ``-`` by a temporary copy of standard input.

    The copy has the suffix its content calls for, so every reader (documents, SVG,
    regions, shapes) and every check (size limits) works on it unchanged. Only one input
    can come from standard input.
    """
    idx = [i for i, a in enumerate(args) if a == "-" and not (i > 0 and args[i - 1] in _OUT_VALUE_FLAGS)]
    if not idx:
        yield args
        return
    if len(idx) > 1:
        raise InputError("-: standard input can be read once; give the other inputs as files")
    if sys.stdin is None or sys.stdin.isatty():
        raise InputError("-: standard input is a terminal; pipe a file in (strew ... - < FILE)")
    import tempfile

    with tempfile.TemporaryDirectory(prefix="strew-stdin-") as tmp:
        # streamed to disk (the readers' size limit applies to the copy, with the
        # command's --limit-file-size); a bound so that an endless pipe cannot fill it
        raw = Path(tmp) / "stdin"
        with raw.open("wb") as f:
            copied = 0
            while chunk := sys.stdin.buffer.read(1 << 20):
                copied += len(chunk)
                if copied > _STDIN_CAP:
                    raise InputError(f"-: standard input runs past {_STDIN_CAP:,} bytes; give a file")
                f.write(chunk)
        with raw.open("rb") as f:
            head = f.read(4096)
        if not head.strip():
            raise InputError("-: standard input is empty")
        path = raw.rename(raw.with_suffix(_sniff(head)))
        out = list(args)
        out[idx[0]] = str(path)
        yield out


def _remember_format(ctx: click.Context, param: click.Parameter, value: str | None) -> str | None:
    ctx.meta["strew.out_format"] = value
    return value


def _ctx_meta(key: str, default: Any = None) -> Any:
    """``key`` in the meta of the current click context or of the nearest parent that has it."""
    ctx = click.get_current_context(silent=True)
    while ctx is not None:
        if key in ctx.meta:
            return ctx.meta[key]
        ctx = ctx.parent
    return default


def _out_format() -> str | None:
    return _ctx_meta("strew.out_format")


# -- option decorators ------------------------------------------------------------------
def _remember_repeat(ctx: click.Context, param: click.Parameter, value: str | None) -> tuple[int, int] | None:
    counts = None
    if value is not None:
        from ..io._svg_export import _repeat_counts

        try:
            counts = _repeat_counts(value)
        except InputError as exc:
            raise click.BadParameter(str(exc).removeprefix("repeat: "), ctx=ctx, param=param) from None
    ctx.meta["strew.out_repeat"] = counts
    return counts


def _remember_height_profiles(ctx: click.Context, param: click.Parameter, value: tuple[str, ...]) -> dict | None:
    """``--height-profile KIND=PROFILE[:HEIGHT]`` (repeatable) -> ``meta["height_profiles"]`` (issue 20.6)."""
    out: dict[str, object] = {}
    for text in value or ():
        kind, sep, rest = text.partition("=")
        name, _, amp = rest.partition(":")
        if not sep or not kind or not name:
            raise click.BadParameter(f"expected KIND=PROFILE[:HEIGHT], got {text!r}", ctx=ctx, param=param)
        try:
            out[kind] = {"profile": name, "height": float(amp)} if amp else name
        except ValueError:
            raise click.BadParameter(f"{text!r}: HEIGHT must be a number in (0, 1]", ctx=ctx, param=param) from None
    ctx.meta["strew.height_profiles"] = out or None
    return out or None


def _out_height_profiles() -> dict | None:
    return _ctx_meta("strew.height_profiles")


def _out_repeat() -> tuple[int, int] | None:
    return _ctx_meta("strew.out_repeat")


def out_option(required: bool = True) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """``--out PATH`` (repeatable); the extension picks the format. With it come
    ``--format`` (of ``--out -``) and ``--repeat NxM`` (a periodic tile's SVG and PNG
    outputs show ``N x M`` copies; issue 18)."""
    out = click.option(
        "--out",
        "-o",
        "outs",
        multiple=True,
        required=required,
        type=click.Path(dir_okay=False, allow_dash=True),
        help="Output file; .json, .svg, .png or .glb (3D scene: the elements on the plane z = 0) (repeatable); - writes standard output (with --format).",
    )
    fmt = click.option(
        "--format",
        "out_format",
        type=click.Choice(["json", "svg", "png"]),
        default=None,
        expose_value=False,
        callback=_remember_format,
        help="Format of --out - (standard output).",
    )
    repeat = click.option(
        "--repeat",
        "out_repeat",
        default=None,
        metavar="NxM",
        expose_value=False,
        callback=_remember_repeat,
        help="SVG and PNG outputs of a periodic tile repeat it N across and M down (SVG through a <pattern>); .json keeps the tile.",
    )
    heights = click.option(
        "--height-profile",
        "out_height_profiles",
        multiple=True,
        metavar="KIND=PROFILE[:H]",
        expose_value=False,
        callback=_remember_height_profiles,
        help="Height profile of a kind in .height.png outputs: dome, plateau or groove, optionally with a height "
             "in (0, 1] (repeatable; * for the other kinds; default dome).",
    )
    return lambda f: out(fmt(repeat(heights(f))))


def seed_option(f: Callable[..., Any]) -> Callable[..., Any]:
    """``--seed N``: every random choice comes from ``numpy.random.default_rng(N)``."""
    return click.option("--seed", type=int, default=0, show_default=True, help="Random seed.")(f)


def quiet_option(f: Callable[..., Any]) -> Callable[..., Any]:
    """``--quiet``: no progress bar and no summary lines."""
    return click.option("--quiet", "-q", is_flag=True, help="No progress bar or summary.")(f)


def domain_options(default_size: str | None = None, *, square: bool = False) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """``--region FILE`` (SVG or JSON) or ``--size WxH`` (the rectangle [0, W] x [0, H]);
    with ``square``, ``--size N`` is also accepted (the square [0, N] x [0, N])."""

    def deco(f: Callable[..., Any]) -> Callable[..., Any]:
        f = click.option(
            "--size",
            default=default_size,
            show_default=default_size is not None,
            metavar="N|WxH" if square else "WxH",
            help="Square [0, N] x [0, N], or rectangle [0, W] x [0, H] written WxH." if square else "Rectangle [0, W] x [0, H], written WxH.",
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
        with flag_for("size", "--size"):
            return Region.from_size(size)
    return None


@contextlib.contextmanager
def flag_for(name: str, flag: str) -> Iterator[None]:
    """Re-raise a library :class:`InputError` that starts with the Python parameter
    ``name`` (``"size: ..."``) with the CLI ``flag`` in its place (``"--size: ..."``)."""
    try:
        yield
    except InputError as exc:
        msg = str(exc)
        if msg.startswith((name + ":", name + " ")):
            raise InputError(flag + msg[len(name):]) from exc
        raise


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
def _sigint_cancels(cancelled: threading.Event) -> Iterator[None]:
    """While active, the first Ctrl-C sets ``cancelled``; a second one interrupts at once.

    A flag instead of an exception means no ``KeyboardInterrupt`` is raised inside a
    compiled (numba) kernel, which would surface as ``SystemError: CPUDispatcher(...)
    returned a result with an exception set``: the library sees ``should_cancel()`` turn
    True at its next check and raises :class:`Cancelled`.
    """
    import signal

    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def handler(signum: int, frame: Any) -> None:
        if cancelled.is_set():
            raise KeyboardInterrupt
        cancelled.set()

    try:
        previous = signal.signal(signal.SIGINT, handler)
    except ValueError:  # not the main interpreter
        yield
        return
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)


@contextlib.contextmanager
def progress_bar(description: str, *, quiet: bool = False) -> Iterator[tuple[Callable[[int, int | None, str], None] | None, Callable[[], bool]]]:
    """Yield ``(progress, should_cancel)`` for a library call.

    ``progress`` draws a rich progress bar on stderr; it is None when ``quiet`` or when
    stderr is not a terminal. ``should_cancel`` turns True after Ctrl-C, so that the
    library stops cleanly at its next check (a second Ctrl-C interrupts at once). A
    cancelled run raises :class:`Cancelled` at the end of the block even when the
    library finished first, so that nothing is written.
    """
    cancelled = threading.Event()

    def should_cancel() -> bool:
        return cancelled.is_set()

    if not quiet and sys.stderr.isatty():  # (logs keep their one-line errors)
        from .._kernel_cache import kernels_cached

        if not kernels_cached(description):  # issue 16: a first run does not look hung
            click.echo("compiling kernels, first run only", err=True)
    with _sigint_cancels(cancelled):
        if quiet or not sys.stderr.isatty():
            yield None, should_cancel
        else:
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

                yield progress, should_cancel
    if cancelled.is_set():
        raise Cancelled("interrupted")


# -- outputs ------------------------------------------------------------------------------
def _check_glb_output(path: str) -> None:
    """A ``.glb`` output of a flat result (issue 20.4, Sakurai Fig. 15): its folder, that it
    can be written, and the ``surface`` extra (trimesh) that writes it, before any work."""
    from ..io import probe_writable

    parent = Path(path).parent
    if not parent.exists():
        raise InputError(f"--out {path!r}: folder {str(parent)!r} does not exist")
    probe_writable(path, "--out")
    try:
        from ..surface._deps import require

        require("trimesh")
    except ImportError as exc:  # a missing extra is a usage problem: exit 2, one line
        raise InputError(f"--out {path!r}: {exc}") from None


def remember_glb_options(element_meshes: dict[str, str], style: str = "extrude", instancing: bool = False) -> None:
    """How this command's ``.glb`` outputs of a flat result draw the kinds (``--element
    KIND=MESH``, ``--style``, ``--instancing`` without ``--surface``)."""
    ctx = click.get_current_context(silent=True)
    if ctx is not None:
        ctx.meta["strew.glb"] = {"element_meshes": dict(element_meshes), "style": style, "instancing": bool(instancing)}


def _glb_options() -> dict[str, Any]:
    return _ctx_meta("strew.glb", {})


def _encode_glb(arr: Arrangement) -> bytes:
    """The ``.glb`` of ``arr``: a surface arrangement as it is, a flat one lifted onto the
    plane z = 0 (:func:`strew.surface.lift`; kinds with ``--element`` carry their mesh)."""
    from .. import surface

    opts = _glb_options()
    scene = arr if surface.is_surface(arr) else surface.lift(arr)
    return surface.to_glb(scene, element_meshes=opts.get("element_meshes") or None,
                          style=opts.get("style", "extrude"), instancing=opts.get("instancing", False))


def check_outputs(outs: Sequence[str]) -> None:
    """Validate every ``--out`` before doing work: extension, folder, and that it can be written."""
    from ..io import check_output_path

    if not outs:
        raise InputError("--out: give at least one output file")
    fmt = _out_format()
    piped = [o for o in outs if o == "-"]
    if len(piped) > 1:
        raise InputError("--out -: standard output can be given once")
    if piped and fmt is None:
        raise InputError("--out -: give --format json, svg or png for standard output")
    if fmt is not None and not piped:
        raise InputError(f"--format: only for --out - (a file's extension gives its format), got --format {fmt}")
    for o in outs:
        if o == "-":
            continue
        if Path(o).suffix.lower() == ".glb":
            _check_glb_output(o)
        else:
            check_output_path(o)
    ctx = click.get_current_context(silent=True)
    if _out_repeat() is not None and ctx is not None and "periodic" in ctx.params and not ctx.params["periodic"]:
        # refused before the work (the written tile is checked again in save_outputs)
        raise InputError("--repeat: the result is not periodic; add --periodic to make a repeat tile")
    _STDOUT[:] = [fmt] if piped else []


# methods that fill a region: an empty result means the region holds no element
_FILLING = ("pack", "grow", "synth", "ornament")


# ``strew rerun`` repeats a recorded command and records it unchanged (byte for byte)
_COMMAND_OVERRIDE: list[str] = []
# the arguments of the running command (set by run_main; sys.argv when called otherwise)
_ARGV: list[str] = []


def command_line() -> str:
    """The command line that produced this run, for ``meta.command``."""
    if _COMMAND_OVERRIDE:
        return _COMMAND_OVERRIDE[-1]
    return "strew " + " ".join(shlex.quote(a) for a in (_ARGV or sys.argv[1:]))


def write_outputs(
    arr: Arrangement,
    outs: Sequence[str],
    *,
    method: str | None = None,
    seed: int | None = None,
    params: dict[str, Any] | None = None,
    quiet: bool = False,
) -> Arrangement:
    """Add the command line to ``meta`` and write every output, all or none.

    The methods stamp their own provenance (:func:`strew._method.stamp`: version,
    method, seed, parameters, input hash); the CLI adds only ``command``. ``seed`` and
    ``params`` are recorded for commands whose library call does not stamp them.
    Refuses (:class:`InputError`) to write an empty result of a filling method.

    Returns the arrangement with its meta filled in.
    """
    from .. import __version__

    if method in _FILLING and len(arr) == 0:
        info = arr.meta.get(method)
        why = arr.meta.get("stopped") or (info.get("stopped") if isinstance(info, dict) else None)
        raise InputError(f"{method}: no element fits ({why or 'is the region smaller than one element?'}); nothing written")

    meta: dict[str, Any] = {}
    if "generator" not in arr.meta:
        meta["generator"] = f"strew {__version__}"
    if method is not None and "method" not in arr.meta:
        meta["method"] = method
    if seed is not None and "seed" not in arr.meta and "rng_state" not in arr.meta:
        meta["seed"] = seed
    if params is not None and "params" not in arr.meta:
        meta["params"] = params
    meta["command"] = command_line()
    arr = arr.with_meta(**meta)
    files = save_outputs(arr, outs)
    if not quiet:
        for o in files:
            click.echo(f"wrote {Path(o)}", err=True)
    return arr


def save_outputs(arr: Arrangement, outs: Sequence[str], **png_kwargs: Any) -> list[str]:
    """Write ``arr`` to every ``--out``, all or none; ``-`` is standard output.

    Checked first by :func:`check_outputs`. Returns the files written (not ``-``).
    """
    from ..io import atomic_write_many, check_output_path, encode, save_many

    files = [o for o in outs if o != "-"]
    heights = _out_height_profiles()
    if heights:  # recorded in the document too, so that strew render draws the same relief
        from ..io._height import _profiles

        try:  # unknown kinds or profiles: exit 2 before anything is written
            _profiles(arr, heights)
        except InputError as exc:
            raise InputError(f"--height-profile: {str(exc).removeprefix('profiles')}".replace(": .", ": ").replace(": :", ":")) from None
        arr = arr.with_meta(height_profiles=heights)
    repeat = _out_repeat()
    if repeat is not None:
        from .._periodic import frame

        if frame(arr) is None:
            raise InputError("--repeat: the arrangement is not periodic (no meta.periodic); make it with --periodic")

    def kwargs(name: str) -> dict[str, Any]:
        low = name.lower()
        if low.endswith(".png") and not low.endswith(".height.png"):
            return {**png_kwargs, **({"repeat": repeat} if repeat else {})}
        return {"repeat": repeat} if repeat and low.endswith(".svg") else {}

    piped = None
    if "-" in outs:  # encoded before any file is written: all or none
        fmt = _STDOUT[0] if _STDOUT else _out_format()
        piped = encode(arr, f"stdout.{fmt}", **kwargs(f"stdout.{fmt}"))
    glb = [p for p in files if Path(p).suffix.lower() == ".glb"]
    if files and (repeat is not None or glb):
        for p in files:
            if p in glb:
                _check_glb_output(p)
            else:
                check_output_path(p)
        atomic_write_many([(p, _encode_glb(arr) if p in glb else encode(arr, p, **kwargs(p))) for p in files])
    elif files:
        save_many(arr, files, **png_kwargs)
    if piped is not None:
        stream = sys.stdout.buffer
        stream.write(piped.encode("utf-8") if isinstance(piped, str) else piped)
        stream.flush()
    return files
