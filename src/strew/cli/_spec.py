"""Click commands generated from a :class:`~strew._method.MethodSpec` (issue 15 point 1).

:func:`method_command` turns a method's spec into its ``strew <method>`` command:

- the input argument, ``--region``/``--size``, one option per :class:`Param` (flag,
  click type, choices, ``--help`` text with unit, range and paper section), ``--around
  FILE`` (the ``context``), ``--seed``, ``--out`` and ``--quiet``;
- option text goes through a named converter (:data:`PARSERS`: degrees, ``x,y`` points,
  per-kind ranges, stroke files, ...);
- the library call runs under a progress bar; library messages that name a Python
  parameter are answered with its flag; the library stamps provenance into ``meta``
  and :func:`~strew.cli._common.write_outputs` adds only the command line.

A command module adds what is only the CLI's (extra outputs, a summary line) through
:class:`Hooks`.
"""

from __future__ import annotations

import math
import time
import warnings
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import click

from .._errors import InputError
from .._method import MethodSpec, Param, names_to_flags
from ._common import check_outputs, domain_options, echo, out_option, parse_point, parse_range, progress_bar, quiet_option, resolve_domain

__all__ = ["method_command", "Hooks", "PARSERS", "INPUTS", "Run"]


# -- converters: option text -> Python value ---------------------------------------------
def _number(text: str, name: str) -> float:
    try:
        return float(text)
    except ValueError:
        raise InputError(f"{name}: expected a number, got {text!r}") from None


def _per_kind(values: Sequence[str], name: str, parse: Callable[[str, str], Any]) -> dict[str, Any]:
    """``[KIND=]VALUE`` options: a value for all kinds (key ``*``), overridden per kind."""
    out: dict[str, Any] = {}
    for text in values:
        kind, sep, rest = text.partition("=")
        if sep and ":" not in kind:
            out[kind.strip()] = parse(rest, f"{name} {kind.strip()}")
        else:
            out["*"] = parse(text, name)
    return out


def _collapse(d: dict[str, Any], default: Any) -> Any:
    """A per-kind mapping, or its plain value when no kind is named."""
    if set(d) == {"*"}:
        return d["*"]
    return {"*": default, **d} if "*" not in d else d


def _deg_range(text: str, name: str) -> tuple[float, float]:
    lo, hi = parse_range(text, name)  # type: ignore[misc]
    return math.radians(lo), math.radians(hi)


def _per_kind_range_deg(raw: Sequence[str], p: Param) -> Any:
    return _collapse(_per_kind(raw, p.cli_flag, _deg_range), p.default)


def _per_kind_range(raw: Sequence[str], p: Param) -> Any:
    return _collapse(_per_kind(raw, p.cli_flag, lambda t, n: parse_range(t, n)), p.default)


def _per_kind_number(raw: Sequence[str], p: Param) -> Any:
    return _collapse(_per_kind(raw, p.cli_flag, _number), p.default)


def _kind_weights(raw: Sequence[str], p: Param) -> dict[str, float]:
    return {"*": 1.0, **_per_kind(raw, p.cli_flag, _number)}


def _kind_numbers(raw: Sequence[str], p: Param) -> dict[str, float]:
    out: dict[str, float] = {}
    for text in raw:
        kind, sep, val = text.partition("=")
        if not sep:
            raise InputError(f"{p.cli_flag}: expected {p.metavar or 'KIND=VALUE'}, got {text!r}")
        try:
            out[kind.strip()] = float(val)
        except ValueError:
            raise InputError(f"{p.cli_flag} {kind.strip()}: {(p.metavar or '=V').split('=')[-1]} must be a number, got {val!r}") from None
    return out


def _index_pairs(raw: Sequence[str], p: Param) -> list[tuple[int, int]]:
    out = []
    for text in raw:
        a, b = parse_point(text, p.cli_flag)
        if a != int(a) or b != int(b):
            raise InputError(f"{p.cli_flag}: expected two element indices I,J, got {text!r}")
        out.append((int(a), int(b)))
    return out


def _strokes(raw: str, p: Param) -> list[Any]:
    from ..grow._tools import load_strokes

    return load_strokes(raw, p.cli_flag)


def _stroke(raw: str, p: Param) -> Any:
    strokes = _strokes(raw, p)
    if len(strokes) > 1:
        raise InputError(f"{p.cli_flag} {raw}: expected one path, found {len(strokes)}")
    return strokes[0]


def _flow(raw: str, p: Param) -> Any:
    from ..fields import flow_field

    return flow_field(_strokes(raw, p))


def _shapes_file(raw: str, p: Param) -> Any:
    from ..io import load_shapes

    return load_shapes(raw)


def _selection(raw: Sequence[str], p: Param) -> dict[str, Any] | None:
    """``NAME``, ``NAME:WEIGHT`` or ``NAME=REGION`` (a region file: that texture fills it)."""
    out: dict[str, Any] = {}
    flag = p.cli_flag
    for item in raw:
        if not item.strip():
            raise InputError(f"{flag}: empty selection (name an exemplar)")
        if "=" in item:
            name, _, path = item.partition("=")
            if not name or not path:
                raise InputError(f"{flag}: expected NAME=REGION.svg, got {item!r}")
            from ..io import load_region

            out[name] = load_region(path)
            continue
        name, _, w = item.partition(":")
        if not name:
            raise InputError(f"{flag}: expected NAME or NAME:WEIGHT, got {item!r}")
        try:
            out[name] = float(w) if w else 1.0
        except ValueError:
            raise InputError(f"{flag}: weight of {name!r} must be a number, got {w!r}") from None
    return out or None


#: parse name (``Param.parse``) -> converter(raw option value, param)
PARSERS: dict[str, Callable[[Any, Param], Any]] = {
    "point": lambda raw, p: parse_point(raw, p.cli_flag),
    "points": lambda raw, p: [parse_point(t, p.cli_flag) for t in raw],
    "degrees": lambda raw, p: math.radians(raw),
    "number": lambda raw, p: _number(raw, p.cli_flag),
    "text": lambda raw, p: raw,
    "per-kind-range-deg": _per_kind_range_deg,
    "per-kind-range": _per_kind_range,
    "per-kind-number": _per_kind_number,
    "kind-weights": _kind_weights,
    "kind-numbers": _kind_numbers,
    "index-pairs": _index_pairs,
    "strokes": _strokes,
    "stroke": _stroke,
    "flow-strokes": _flow,
    "shapes-file": _shapes_file,
    "selection": _selection,
}


def _shape_files(raw: Sequence[str]) -> dict[str, Any]:
    from ..io import load_shapes

    lib: dict[str, Any] = {}
    for path in raw:
        for name, sh in load_shapes(path).items():
            key = name if name not in lib else f"{Path(path).stem}-{name}"
            lib[key] = sh
    return lib


def _arrangement_file(raw: str) -> Any:
    from ..io import load

    return load(raw)


def _palette_files(raw: Sequence[str]) -> Any:
    from ..synth import load_palette

    return load_palette(list(raw))


#: input parse name (``spec.input.parse``) -> converter(raw argument)
INPUTS: dict[str, Callable[[Any], Any]] = {
    "shape-files": _shape_files,
    "arrangement-file": _arrangement_file,
    "palette-files": _palette_files,
    "text": lambda raw: raw,
}

_FILE_INPUTS = ("shape-files", "arrangement-file", "palette-files")


# -- the command ---------------------------------------------------------------------------
@dataclass
class Run:
    """One CLI run, handed to the hooks: the raw options, the converted values and so on."""

    spec: MethodSpec
    options: dict[str, Any]
    values: dict[str, Any]
    input: Any = None
    region: Any = None
    context: Any = None
    seed: int = 0
    quiet: bool = False
    seconds: float = 0.0
    state: dict[str, Any] = field(default_factory=dict)


@dataclass
class Hooks:
    """What a command adds to the generated one.

    options : click decorators for CLI-only options (extra outputs, files).
    check : ``check(run)`` before any work (after ``--out`` is checked).
    prepare : ``prepare(run)`` after inputs are read, before the library call.
    finish : ``finish(run, arr)`` after the call, before writing (extra outputs).
    summary : ``summary(run, arr) -> str``, the line printed on stdout.
    domain : ``"size"`` (``--size WxH``) or ``"square"`` (``--size N`` also means N x N).
    """

    options: Sequence[Callable[[Callable[..., Any]], Callable[..., Any]]] = ()
    check: Callable[[Run], None] | None = None
    prepare: Callable[[Run], None] | None = None
    finish: Callable[[Run, Any], None] | None = None
    summary: Callable[[Run, Any], str] | None = None
    domain: str = "size"
    description: str = ""


def _click_type(p: Param) -> Any:
    if p.choices is not None and p.cli in ("value",):
        return click.Choice([str(c) for c in p.choices])
    if p.parse in (None, "degrees"):
        return {"int": click.INT, "float": click.FLOAT}.get(p.type, click.STRING)
    return click.STRING


def _param_option(spec: MethodSpec, p: Param) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    help_text = spec.help_line(p)
    if p.cli in ("flag", "no-flag"):
        return click.option(p.cli_flag, p.name, is_flag=True, default=None, help=help_text)
    kw: dict[str, Any] = {"default": None, "help": help_text, "type": _click_type(p)}
    if p.metavar:
        kw["metavar"] = p.metavar
    if p.cli == "multiple":
        kw["multiple"] = True
        kw["default"] = ()
    return click.option(p.cli_flag, p.name, **kw)


def _renamed_option(spec: MethodSpec, old: str, new: str) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """The hidden option of a renamed parameter's old flag (``MethodSpec.renamed``)."""
    p = spec.param(new)
    kw: dict[str, Any] = {"default": None, "hidden": True, "type": _click_type(p)}
    if p.cli in ("flag", "no-flag"):
        kw = {"default": None, "hidden": True, "is_flag": True}
    elif p.cli == "multiple":
        kw.update(multiple=True, default=())
    return click.option("--" + old.replace("_", "-"), "renamed_" + old, **kw)


def _convert(p: Param, raw: Any) -> Any:
    """The Python value of an option (None: not given, the library's default)."""
    if raw is None or (p.cli == "multiple" and not raw):
        return None
    if p.cli == "flag":
        return True if raw else None
    if p.cli == "no-flag":
        return False if raw else None
    if p.parse is not None:
        return PARSERS[p.parse](raw, p)
    if p.choices is not None:
        return next(c for c in p.choices if str(c) == raw)
    return raw


# methods whose --periodic runs through strew.tiles.periodic (no torus of their own)
TILED_PERIODIC = ("synth",)


def _tiled_periodic(method: str) -> Callable[..., Any]:
    """``fn(input, region, *, context, rng, progress, should_cancel, **params)`` for a repeat tile."""

    def fn(input: Any, region: Any, *, context: Any = None, rng: Any = None, progress: Any = None,
           should_cancel: Any = None, **params: Any) -> Any:
        from ..tiles import periodic

        if region is None:
            raise InputError("--periodic: give the tile with --size WxH")
        return periodic(method, input, region, rng=rng, **params)

    return fn


def method_command(spec: MethodSpec, hooks: Hooks | None = None) -> click.Command:
    """The click command of a method, generated from its spec."""
    hooks = hooks or Hooks()
    cli_params = [p for p in spec.params if p.cli]
    renamed = {old: new for old, new in spec.renamed.items() if new in spec.names and spec.param(new).cli}
    on_surfaces = spec.name in ("pack", "synth", "grow")
    # --periodic for methods without a torus of their own (synth): strew.tiles
    # grows the tile as a torus of 2 x 2 tiles, each around its finished neighbours (issue 18)
    tiled_periodic = spec.name in TILED_PERIODIC and "periodic" not in spec.names
    from . import surface as _surface

    def callback(**options: Any) -> None:
        renamed_notes = []  # printed with the library's warnings after the run: an error stays one line
        for old, new in renamed.items():  # a renamed option: accepted for one release, with a warning
            raw = options.pop("renamed_" + old)
            if raw is None or raw == ():
                continue
            flag_new = spec.param(new).cli_flag
            if options.get(new) not in (None, ()):
                raise InputError(f"--{old.replace('_', '-')}: give {flag_new} or its old name, not both")
            renamed_notes.append(f"--{old.replace('_', '-')} is renamed {flag_new}; the old name goes in the next release")
            options[new] = raw
        outs = options.pop("outs")
        quiet = options.pop("quiet")
        seed = options.pop("seed")
        around = options.pop("around")
        region_file, size = options.pop("region"), options.pop("size")
        raw_input = options.pop(spec.input.name)
        periodic = options.pop("periodic", False) if tiled_periodic else False
        surf = _surface.pop_surface_options(options) if on_surfaces else {}
        if periodic and surf.get("surface_mesh") is not None:
            raise InputError("--periodic makes a flat repeat tile: it does not apply with --surface")
        if surf.get("surface_mesh") is not None:  # --surface MESH: strew.surface does the work (issue 20)
            return _surface.run_on_surface(spec, options, raw_input, outs, surf, seed=seed, quiet=quiet, region=(region_file, size), around=around,
                                           convert=_convert, read_input=INPUTS[spec.input.parse or "text"])
        if surf:  # flat: --element / --style / --instancing shape the .glb outputs (Sakurai Fig. 15)
            _surface.remember_flat_glb(surf, outs)
        check_outputs(outs)
        run = Run(spec, options, {}, seed=seed, quiet=quiet)
        if hooks.check is not None:
            hooks.check(run)
        for p in cli_params:
            value = _convert(p, options.get(p.name))
            if value is not None:
                run.values[p.name] = value
        run.input = INPUTS[spec.input.parse or "text"](raw_input)
        if hooks.domain == "square" and size is not None and "x" not in size.lower() and region_file is None:
            run.values["size"] = size  # strew run --size N: the square [0, N]^2 (the spec checks N)
            size = None
        run.region = resolve_domain(region_file, size)
        if around is not None:
            from ..io import load

            run.context = load(around)
        if hooks.prepare is not None:
            hooks.prepare(run)
        if run.region is None and spec.region_required:
            raise InputError("give --region FILE or --size WxH")
        fn = spec.function()
        if periodic:
            if run.context is not None:
                raise InputError("--periodic: --around is not supported with a repeat tile (the tile's own edges are its context)")
            fn = _tiled_periodic(spec.name)
        label = spec.progress_message or spec.name
        if spec.name == "pack" and run.values.get("method") == "naive":
            label += " (naive)"  # dart throwing compiles no kernel: no compile notice (issue 16)
        t0 = time.perf_counter()
        try:
            with warnings.catch_warnings(record=True) as caught, progress_bar(label, quiet=quiet) as (prog, cancel):
                warnings.simplefilter("always")
                arr = fn(run.input, run.region, context=run.context, rng=seed, progress=prog, should_cancel=cancel, **run.values)
        except InputError as exc:  # the library names Python parameters; answer with flags
            msg = names_to_flags(spec, str(exc))
            if msg == str(exc):
                raise
            raise InputError(msg) from exc
        run.seconds = time.perf_counter() - t0
        for note in [*renamed_notes, *(str(w.message) for w in caught)]:
            click.echo(f"strew: warning: {note}", err=True)
        if hooks.finish is not None:
            hooks.finish(run, arr)
        from ._common import write_outputs

        write_outputs(arr, outs, method=spec.name, quiet=quiet)
        if hooks.summary is not None:
            echo(hooks.summary(run, arr), quiet=quiet)

    f: Callable[..., Any] = callback
    # decorators apply bottom-up: list them in reverse of the --help order
    for deco in reversed(
        [
            click.argument(
                spec.input.name,
                nargs=-1 if (spec.input.metavar or "").endswith("...") else 1,
                required=True,
                metavar=spec.input.metavar,
                type=click.Path(dir_okay=False) if spec.input.parse in _FILE_INPUTS or spec.name == "program" else click.STRING,
            ),
            domain_options(square=hooks.domain == "square"),
            *[_param_option(spec, p) for p in cli_params],
            *[_renamed_option(spec, old, new) for old, new in renamed.items()],
            *hooks.options,
            *(_surface.surface_options() if on_surfaces else []),
            *([click.option("--periodic", is_flag=True, default=False,
                            help="Make a seamless repeat tile of --size WxH: grown as a torus of 2 x 2 tiles, "
                                 "each around its neighbours across the edges (strew.tiles.periodic).")]
              if tiled_periodic else []),
            click.option("--around", type=click.Path(dir_okay=False), default=None,
                         help="Fixed elements (.json or .svg) to fill around: never overlapped (context)."),
            click.option("--seed", type=int, default=0, show_default=True, help="Random seed."),
            out_option(),
            quiet_option,
        ]
    ):
        f = deco(f)
    doc = hooks.description or spec.summary
    doc += f"\n\nFollows {spec.paper}; every option names its paper section." if spec.paper else ""
    return click.command(spec.command or spec.name, help=doc)(f)
