"""The method contract: parameters declared once, provenance recorded by the library.

Each method package (``strew.pack``, ``strew.grow``, ``strew.synth``,
``strew.ornament``, ``strew.program``) declares one :class:`MethodSpec` named ``SPEC``:
its name, entry function and :class:`Param` list (name, type, default, range or choices,
unit, help, paper section). From the spec come

- the validation of Python arguments (:meth:`MethodSpec.validate`), whose messages name
  the Python parameter (the CLI maps names to flags);
- the click command and ``strew <method> --help`` (:mod:`strew.cli._spec`);
- the provenance every entry point stamps into ``meta`` (:func:`stamp`): method, strew
  version, seed or Generator state, every parameter with its default resolved, and the
  input's content hash;
- ``context``: the free part of a region around an existing arrangement
  (:func:`free_region`).

Every entry point has one shape::

    method(input, region=None, *, context=None, rng=None, progress=None,
           should_cancel=None, **params) -> Arrangement

This module sits between the core types / io and the methods: it imports numpy, the
core types and :mod:`strew.io.document` lazily, never a method package (those are found
by name in :data:`METHODS`).
"""

from __future__ import annotations

import hashlib
import importlib
import json
import math
import os
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ._errors import InputError

if TYPE_CHECKING:  # pragma: no cover
    import numpy as np

    from .arrangement import Arrangement
    from .region import Region

__all__ = [
    "Param",
    "MethodSpec",
    "METHODS",
    "spec",
    "specs",
    "seed_record",
    "generator_from",
    "content_hash",
    "stamp",
    "free_region",
    "as_region",
    "check_context",
    "PROVENANCE_FIELDS",
    "rerun",
]

# method name -> package that defines ``SPEC`` (imported on demand; imports point down)
METHODS: dict[str, str] = {
    "pack": "strew.pack",
    "grow": "strew.grow",
    "synth": "strew.synth",
    "ornament": "strew.ornament",
    "program": "strew.program",
}

# the fields every entry point writes into meta
PROVENANCE_FIELDS = ("generator", "method", "params", "input_hash")

_MISSING = object()


@dataclass(frozen=True)
class Param:
    """One parameter of a method, declared once.

    Parameters
    ----------
    name : str
        The Python keyword.
    type : {"int", "float", "bool", "str", "range", "point", "points", "any"}
        ``range`` is a pair ``(lo, hi)`` with ``lo <= hi``; ``point`` an ``(x, y)``;
        ``points`` a ``(k, 2)`` list; ``any`` is passed through (checked by the method).
    default : object
        The default; None means "the method decides" (``help`` says what it decides).
    low, high : float, optional
        Inclusive bounds of numbers (or of both ends of a range).
    low_open, high_open : bool
        Whether ``low`` / ``high`` are excluded.
    choices : tuple, optional
        Allowed values.
    unit : str
        Unit shown in ``--help`` ("document units", "radians", "cells", ...).
    help : str
        One line for ``--help`` and the studio.
    section : str
        Where the paper describes it ("§4.2"); "extension" where strew adds it.
    flag : str, optional
        The CLI flag (default ``--name-with-dashes``); None with ``cli=False``.
    cli : str or False
        How the CLI reads it: "value" (one option), "flag" (True when given),
        "no-flag" (False when given), "multiple" (repeatable), or False (Python only).
    parse : str, optional
        Name of the CLI converter in :mod:`strew.cli._spec` (``"degrees"``, ``"point"``,
        ``"per-kind-range-deg"``, ...); the option's text goes through it.
    metavar : str, optional
        The CLI metavar.
    cli_help : str, optional
        ``--help`` text when the flag reads differently from the Python parameter
        (degrees on the CLI, radians in Python).
    what : str
        What the value is, in messages ("the ratio constant must be ...").
    """

    name: str
    type: str = "any"
    default: Any = None
    low: float | None = None
    high: float | None = None
    low_open: bool = False
    high_open: bool = False
    choices: tuple[Any, ...] | None = None
    unit: str = ""
    help: str = ""
    section: str = ""
    flag: str | None = None
    cli: str | bool = "value"
    parse: str | None = None
    metavar: str | None = None
    cli_help: str | None = None
    what: str = ""

    @property
    def cli_flag(self) -> str:
        """The CLI flag of this parameter."""
        return self.flag or "--" + self.name.replace("_", "-")

    def describe_range(self) -> str:
        """``[lo, hi)`` style text of the allowed values, or ''."""
        if self.choices is not None:
            return "one of " + ", ".join(str(c) for c in self.choices)
        if self.low is None and self.high is None:
            return ""
        lo = "-inf" if self.low is None else f"{self.low:g}"
        hi = "inf" if self.high is None else f"{self.high:g}"
        left = "(" if self.low_open or self.low is None else "["
        right = ")" if self.high_open or self.high is None else "]"
        return f"in {left}{lo}, {hi}{right}"

    def _number(self, value: Any, what: str = "") -> float:
        name = self.name + what
        if isinstance(value, bool):
            raise InputError(f"{name}: must be a number, got {value!r}")
        try:
            v = float(value)
        except (TypeError, ValueError):
            raise InputError(f"{name}: must be a number, got {value!r}") from None
        if not math.isfinite(v):
            raise InputError(f"{name}: must be finite, got {value!r}")
        bad = (
            (self.low is not None and (v < self.low or (self.low_open and v == self.low)))
            or (self.high is not None and (v > self.high or (self.high_open and v == self.high)))
        )
        if bad:
            what = f"{self.what} " if self.what else ""
            raise InputError(f"{name}: {what}must be {self.bound_phrase()}, got {value!r}")
        return v

    def bound_phrase(self) -> str:
        """``a positive integer``, ``at least 2``, ``in (0, 1]``: what the bounds ask for."""
        lo, hi = self.low, self.high
        if hi is None and lo is not None:
            if self.type == "int" and lo in (0, 1) and not self.low_open:
                return "a positive integer" if lo == 1 else "a non-negative integer"
            if lo == 0:
                return "positive" if self.low_open else "non-negative"
            return f"greater than {lo:g}" if self.low_open else f"at least {lo:g}"
        if lo is None and hi is not None:
            return f"below {hi:g}" if self.high_open else f"at most {hi:g}"
        return self.describe_range()

    def check(self, value: Any) -> Any:
        """``value`` converted and checked; :class:`InputError` naming :attr:`name` if bad.

        None is accepted when the default is None (the method decides).
        """
        if value is None:
            if self.default is None:
                return None
            raise InputError(f"{self.name}: must not be None (default {self.default!r})")
        if self.choices is not None and self.type != "any":
            if value not in self.choices:
                raise InputError(f"{self.name}: unknown choice {value!r}; use one of {', '.join(map(str, self.choices))}")
            return value
        t = self.type
        if t == "int":
            if isinstance(value, bool) or isinstance(value, float) and not value.is_integer():
                raise InputError(f"{self.name}: must be an integer, got {value!r}")
            try:
                iv = int(value)
            except (TypeError, ValueError):
                raise InputError(f"{self.name}: must be an integer, got {value!r}") from None
            if iv != value:
                raise InputError(f"{self.name}: must be an integer, got {value!r}")
            self._number(iv)
            return iv
        if t == "float":
            return self._number(value)
        if t == "bool":
            if not isinstance(value, (bool, int)) or value not in (0, 1):
                raise InputError(f"{self.name}: must be True or False, got {value!r}")
            return bool(value)
        if t == "str":
            if not isinstance(value, str):
                raise InputError(f"{self.name}: must be a string, got {type(value).__name__}")
            return value
        if t == "range":
            try:
                lo, hi = value
            except (TypeError, ValueError):
                raise InputError(f"{self.name}: expected a pair (lo, hi), got {value!r}") from None
            lo, hi = self._number(lo, "[0]"), self._number(hi, "[1]")
            if lo > hi:
                raise InputError(f"{self.name}: inverted range ({lo:g}, {hi:g})")
            return (lo, hi)
        if t == "point":
            try:
                x, y = value
                p = (float(x), float(y))
            except (TypeError, ValueError):
                raise InputError(f"{self.name}: expected a point (x, y), got {value!r}") from None
            if not all(math.isfinite(c) for c in p):
                raise InputError(f"{self.name}: expected a finite point, got {value!r}")
            return p
        if t == "points":
            import numpy as np

            try:
                a = np.asarray(value, dtype=float)
            except (TypeError, ValueError):
                raise InputError(f"{self.name}: expected (x, y) points") from None
            if a.ndim != 2 or a.shape[1] != 2 or not np.all(np.isfinite(a)):
                raise InputError(f"{self.name}: expected finite (x, y) points, got shape {a.shape}")
            return [tuple(map(float, p)) for p in a]
        return value


@dataclass(frozen=True)
class MethodSpec:
    """A method's contract: name, entry point and parameters.

    Parameters
    ----------
    name : str
        ``meta["method"]`` and the CLI command (``program`` runs as ``strew run``).
    entry : str
        ``"module:function"`` of the entry point.
    input : Param
        The first positional argument (shapes, exemplar, pattern, script).
    params : tuple of Param
        Keyword parameters, in ``--help`` order.
    paper : str
        The paper it follows.
    summary : str
        One line for ``--help``.
    command : str
        The CLI command name.
    """

    name: str
    entry: str
    input: Param
    params: tuple[Param, ...]
    paper: str = ""
    summary: str = ""
    command: str = ""
    region_required: bool = True
    progress_message: str = ""
    extras: dict[str, Any] = field(default_factory=dict)
    # old parameter names -> current ones, still accepted for one release with a
    # DeprecationWarning naming the new one (Python keyword and CLI flag alike)
    renamed: dict[str, str] = field(default_factory=dict)

    def param(self, name: str) -> Param:
        """The parameter called ``name``."""
        for p in self.params:
            if p.name == name:
                return p
        raise KeyError(name)

    @property
    def names(self) -> tuple[str, ...]:
        return tuple(p.name for p in self.params)

    def function(self) -> Callable[..., Any]:
        """The entry function (imported on demand)."""
        mod, _, fn = self.entry.partition(":")
        return getattr(importlib.import_module(mod), fn)

    def validate(self, params: Mapping[str, Any], *, aliases: Mapping[str, str] | None = None) -> dict[str, Any]:
        """Every parameter checked and with its default resolved, in declaration order.

        Unknown names raise :class:`InputError` naming them (with the closest known
        name); ``aliases`` maps old keyword names to current ones.
        """
        given = dict(params)
        for old, new in self.renamed.items():
            if old in given:
                import warnings

                warnings.warn(f"{self.name}: parameter {old} is renamed {new}; {old} goes in the next release",
                              DeprecationWarning, stacklevel=3)
        for old, new in {**self.renamed, **(aliases or {})}.items():
            if old in given:
                if new in given:
                    raise InputError(f"{old}: give {new} or its old name {old}, not both")
                given[new] = given.pop(old)
        names = self.names
        unknown = [k for k in given if k not in names]
        if unknown:
            import difflib

            close = difflib.get_close_matches(unknown[0], names, n=1)
            hint = f" (did you mean {close[0]}?)" if close else ""
            raise InputError(f"{unknown[0]}: not a parameter of {self.name}{hint}")
        out: dict[str, Any] = {}
        for p in self.params:
            out[p.name] = p.check(given[p.name]) if p.name in given else p.default
        return out

    def help_line(self, p: Param) -> str:
        """The ``--help`` text of one parameter: help, unit, range, paper section, default."""
        bits = [p.cli_help or p.help]
        extra = []
        unit = "degrees" if p.parse in ("degrees", "per-kind-range-deg") else p.unit
        if unit:
            extra.append(unit)
        rng = p.bound_phrase() if p.choices is None and (p.low is not None or p.high is not None) else ""
        if rng:
            extra.append(rng)
        if p.section:
            extra.append(p.section)
        if extra:
            bits.append("(" + "; ".join(extra) + ")")
        if p.default is not None and p.cli == "value" and "[default" not in bits[0]:
            d = p.default
            if p.parse == "degrees" and isinstance(d, (int, float)):
                d = math.degrees(d)
            bits.append(f"[default: {d:g}]" if isinstance(d, float) else f"[default: {d}]")
        return " ".join(b for b in bits if b)


def spec(name: str) -> MethodSpec:
    """The :class:`MethodSpec` of a method by name (imports its package)."""
    if name not in METHODS:
        raise InputError(f"method: unknown method {name!r}; use one of {', '.join(METHODS)}")
    return importlib.import_module(METHODS[name]).SPEC


def specs() -> list[MethodSpec]:
    """Every method's spec."""
    return [spec(n) for n in METHODS]


# -- seeds ---------------------------------------------------------------------------------
def seed_record(rng: Any) -> tuple[np.random.Generator, dict[str, Any]]:
    """The Generator a run draws from, and what to record so that it can be drawn again.

    An int seed is recorded as ``{"seed": n}``; a Generator as ``{"rng_state": ...}``,
    its bit generator's state *before* the run; None draws a fresh seed from the OS's
    entropy and records it, so that an unseeded run can be reproduced too.
    """
    import numpy as np

    if rng is None:
        seed = int(np.random.SeedSequence().generate_state(1, np.uint32)[0])
        return np.random.default_rng(seed), {"seed": seed}
    if isinstance(rng, np.random.Generator):
        return rng, {"rng_state": _jsonable(rng.bit_generator.state)}
    if isinstance(rng, (bool, np.bool_)) or not isinstance(rng, (int, np.integer)):
        raise InputError(f"rng: must be an int, a numpy Generator or None, got {type(rng).__name__}")
    if rng < 0:
        raise InputError(f"rng: a seed must be non-negative, got {rng}")
    return np.random.default_rng(int(rng)), {"seed": int(rng)}


def generator_from(meta: Mapping[str, Any]) -> Any:
    """The ``rng`` argument that repeats a run recorded in ``meta`` (an int or a Generator)."""
    import numpy as np

    if "rng_state" in meta:
        state = meta["rng_state"]
        bg = getattr(np.random, state["bit_generator"])()
        bg.state = state
        return np.random.Generator(bg)
    if "seed" in meta:
        return int(meta["seed"])
    raise InputError("meta: records neither seed nor rng_state")


# -- hashing and JSON ----------------------------------------------------------------------
def _jsonable(value: Any) -> Any:
    """``value`` as plain JSON data (tuples -> lists, numpy scalars -> numbers, objects
    -> a short description)."""
    import numpy as np

    if value is None or isinstance(value, (bool, str)):
        return value
    if isinstance(value, (int, np.integer)):
        return int(value)
    if isinstance(value, (float, np.floating)):
        v = float(value)
        return v if math.isfinite(v) else str(v)
    if isinstance(value, np.ndarray):
        return _jsonable(value.tolist())
    if isinstance(value, Mapping):
        return {str(k): _jsonable(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_jsonable(v) for v in value]
    if isinstance(value, os.PathLike):
        return os.fspath(value)
    name = getattr(value, "name", None)
    kind = type(value).__name__
    if isinstance(name, str):
        return f"<{kind} {name}>"
    if callable(value):
        return f"<{kind} {getattr(value, '__qualname__', kind)}>"
    return f"<{kind}>"


def content_hash(obj: Any) -> str:
    """``"sha256:<hex>"`` of an input's content: an Arrangement's document without its
    meta, a file's bytes for a path, JSON for plain data, recursively for collections."""
    return "sha256:" + _digest(obj).hexdigest()


def _digest(obj: Any) -> Any:
    h = hashlib.sha256()
    from .arrangement import Arrangement
    from .region import Region
    from .shape import Shape

    if isinstance(obj, Arrangement):
        from .io.document import dumps

        h.update(b"A")
        h.update(dumps(obj.replace(meta={})).encode())
    elif isinstance(obj, Shape):
        h.update(b"S" + json.dumps(_jsonable(obj.to_dict()), sort_keys=True).encode())
    elif isinstance(obj, Region):
        h.update(b"R" + json.dumps(_jsonable(obj.to_dict()), sort_keys=True).encode())
    elif isinstance(obj, (str, os.PathLike)) and Path(obj).is_file():
        h.update(b"F" + Path(obj).read_bytes())
    elif isinstance(obj, Mapping):
        h.update(b"M")
        for k in sorted(obj, key=str):
            h.update(str(k).encode() + b"=" + _digest(obj[k]).digest())
    elif isinstance(obj, (list, tuple)):
        h.update(b"L")
        for v in obj:
            h.update(_digest(v).digest())
    elif hasattr(obj, "content_items"):  # e.g. a synth Palette / Selection
        h.update(b"C" + _digest(obj.content_items()).digest())
    else:
        h.update(b"J" + json.dumps(_jsonable(obj), sort_keys=True).encode())
    return h


# -- provenance ----------------------------------------------------------------------------
def stamp(
    arr: Arrangement,
    spec: MethodSpec,
    input: Any,
    params: Mapping[str, Any],
    seed: Mapping[str, Any],
    *,
    region: Region | None = None,
    context: Arrangement | None = None,
) -> Arrangement:
    """``arr`` with its provenance in ``meta``.

    Writes ``generator`` (strew version), ``method``, ``seed`` or ``rng_state``,
    ``params`` (every parameter, defaults resolved, as JSON data), ``input_hash`` and,
    when given, ``region_hash`` and ``context`` (its element count and hash). Entries
    the method wrote already (e.g. ``meta["pack"]``) are kept; the CLI adds only
    ``command``.
    """
    from ._version import __version__

    meta = dict(arr.meta)
    meta.pop("seed", None)
    meta.pop("rng_state", None)
    meta.update(generator=f"strew {__version__}", method=spec.name, **_jsonable(dict(seed)))
    meta["params"] = _jsonable(dict(params))
    meta["input_hash"] = content_hash(input)
    if region is not None:
        meta["region_hash"] = content_hash(region)
    if context is not None:
        meta["context"] = {"elements": len(context), "hash": content_hash(context)}
    return arr.replace(meta=meta)


# -- inputs --------------------------------------------------------------------------------
def as_shapes(shapes: Any, name: str = "shapes") -> dict:
    """A shape library (kind name -> :class:`~strew.Shape`) from a Shape, a sequence of
    them (kinds ``shape0``, ``shape1``, ...) or a mapping; refuses anything else, an empty
    library and entries that are not Shapes, naming ``name``."""
    from .shape import Shape

    if isinstance(shapes, Shape):
        return {"shape": shapes}
    if isinstance(shapes, Mapping):
        out = dict(shapes)
    elif isinstance(shapes, Sequence) and not isinstance(shapes, str):
        out = {f"shape{i}": s for i, s in enumerate(shapes)}
    else:
        raise InputError(f"{name}: expected a Shape, a list of shapes or a mapping of name -> Shape, got {type(shapes).__name__}")
    if not out:
        raise InputError(f"{name}: no shape given")
    for k, s in out.items():
        if not isinstance(s, Shape):
            raise InputError(f"{name}.{k}: must be a Shape, got {type(s).__name__}")
    return out


# -- region and context --------------------------------------------------------------------
def as_region(region: Any, name: str = "region") -> Region | None:
    """A :class:`Region` from a Region, a shapely polygon, ``"WxH"`` or ``(W, H)``; None stays None."""
    import shapely

    from .region import Region

    if region is None or isinstance(region, Region):
        return region
    if isinstance(region, (shapely.Polygon, shapely.MultiPolygon)):
        return Region(region)
    if isinstance(region, str):
        return Region.from_size(region)
    if isinstance(region, (tuple, list)) and len(region) == 2:
        return Region.rectangle(float(region[0]), float(region[1]))
    raise InputError(f"{name}: expected a Region, a polygon, 'WxH' or (W, H), got {type(region).__name__}")


def check_context(context: Any) -> Arrangement | None:
    """``context`` checked: None or an Arrangement."""
    from .arrangement import Arrangement

    if context is None or isinstance(context, Arrangement):
        return context
    raise InputError(f"context: expected an Arrangement of fixed elements, got {type(context).__name__}")


def context_footprint(context: Arrangement, gap: float = 0.0) -> Any:
    """The union of the context's visible elements (closed paths as areas, open paths
    as their strokes), grown by ``gap``: the area new elements must keep out of."""
    import numpy as np
    import shapely

    if len(context) == 0:
        return shapely.Polygon()
    keep = np.ones(len(context), bool)
    if "void" in context.columns:
        keep &= ~np.asarray(context["void"], bool)
    geoms = context.geometry_of("geometry")[keep] if keep.any() else np.array([])
    parts = []
    for g in geoms:
        if g is None or g.is_empty:
            continue
        if g.area > 0:
            parts.append(g)
        # open paths (and outlines) take room too: a thin band about their lines
        if not isinstance(g, (shapely.Polygon, shapely.MultiPolygon)):
            parts.append(shapely.buffer(g, 1e-6))
    if not parts:
        return shapely.Polygon()
    u = shapely.union_all(shapely.make_valid(np.asarray(parts, dtype=object)))
    return shapely.buffer(u, gap) if gap > 0 else u


def free_region(region: Region | None, context: Arrangement | None, *, gap: float = 0.0) -> Region | None:
    """``region`` less the footprint of ``context`` (issue 15 point 4: fixed obstacles).

    With no context, ``region`` itself. A region that the context covers wholly gives
    :data:`EMPTY_REGION` (see :func:`is_empty`), which every method answers with an
    empty arrangement.
    """
    if region is None or context is None or len(context) == 0:
        return region
    import shapely

    from .region import Region

    rest = shapely.difference(region.geometry, context_footprint(context, gap))
    polys = [g for g in shapely.get_parts(rest) if isinstance(g, shapely.Polygon) and g.area > 0]
    if not polys:
        return EMPTY_REGION  # type: ignore[return-value]
    return Region(shapely.MultiPolygon(polys) if len(polys) != 1 else polys[0])


class _EmptyRegion:
    """What is left of a region that a context covers wholly (a Region always has area)."""

    area = 0.0

    def __repr__(self) -> str:
        return "EMPTY_REGION"


EMPTY_REGION = _EmptyRegion()


def is_empty(region: Any) -> bool:
    """Whether a region (from :func:`free_region`) holds no area at all."""
    return region is EMPTY_REGION or (region is not None and not (region.area > 0))


def empty_result(shapes: Mapping[str, Any] | None, region: Region | None, why: str) -> Arrangement:
    """An arrangement of no element (for an empty region), saying why in ``meta["stopped"]``."""
    from .arrangement import Arrangement

    return Arrangement(dict(shapes or {}), [], [], [], region=region, meta={"stopped": why})


def iter_params(specs_: Iterable[MethodSpec]) -> Iterable[tuple[MethodSpec, Param]]:
    """Every (spec, param) pair, for tables and tests."""
    for s in specs_:
        for p in s.params:
            yield s, p


def names_to_flags(spec: MethodSpec, message: str) -> str:
    """A library message with its leading Python parameter name replaced by the CLI flag."""
    # the input is a positional argument on the CLI (EXEMPLAR, SHAPES...): its name stays
    for p in spec.params:
        if not p.cli and p.flag is None:
            continue
        for sep in (":", " ", "["):
            if message.startswith(p.name + sep):
                return p.cli_flag + message[len(p.name):]
    for word, flag in (("region", "--region or --size"), ("context", "--around"), ("rng", "--seed")):
        if message.startswith((word + ":", word + " ")):
            return flag + message[len(word):]
    return message



def rerun(arr: Arrangement, input: Any, *, context: Arrangement | None = None, **overrides: Any) -> Arrangement:
    """Repeat the run that made ``arr`` from its ``meta``: same method, parameters, seed
    (or Generator state) and region, on ``input`` (whose content hash must match).

    Parameters recorded as objects (a flow callable, exclusive shapes) cannot be read
    back from meta: pass them again in ``overrides``. From the CLI, ``strew rerun
    OUTPUT.json`` repeats the recorded command instead.
    """
    meta = arr.meta
    if "method" not in meta or "params" not in meta:
        raise InputError("meta: records no method and parameters (not made by a strew method)")
    s = spec(meta["method"])
    want = meta.get("input_hash")
    if want is not None and content_hash(input) != want:
        raise InputError("input: its content hash differs from the one recorded in meta")
    params = dict(meta["params"])
    params.pop("pattern", None)  # ornament records its input by name too
    for k, v in params.items():
        if isinstance(v, str) and v.startswith("<") and k not in overrides:
            raise InputError(f"{k}: recorded as {v}; pass it again to rerun")
    params.update(overrides)
    params = {k: v for k, v in params.items() if v is not None}
    return s.function()(input, arr.region, context=context, rng=generator_from(meta), **params)
