"""Adaptive clip art: element types, growth rules and rule files (Wong et al. 1998, §3.2, §4.2).

A :class:`Pattern` is the paper's rule file written as plain Python instead of the
preprocessed C++ dialect::

    from strew.ornament import Pattern, Point, Circle, SUCCESS, FAILURE

    pattern = Pattern("dots", state={"dot_count": 0})
    pattern.element("seed", Point)                 # required (§4.2)
    pattern.element("dot", Circle, order=0)        # a proxy and a user field

    @pattern.rule("seed", children=["dot"])
    def first_dot(ctx, seed, dot):                 # ctx.goal is the empty circle C
        dot.proxy.set(seed.proxy.center, 3.0)
        seed.sterile = True
        return SUCCESS

The paper's dollar tokens map to Python names: ``$$`` is the ``parent`` argument, ``$``
is ``parent.proxy`` (``$(k)`` is ``parent.proxies[k]``), ``$$j`` is the j-th static child
argument, ``$goal`` is ``ctx.goal``, ``new_child`` is ``ctx.new_child(type)``.
"""

from __future__ import annotations

import copy
import hashlib
import importlib
import importlib.util
import sys
import traceback
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from types import SimpleNamespace
from typing import Any

from .._errors import InputError
from ._proxies import PROXY_TYPES, Point, Proxy

__all__ = [
    "SUCCESS",
    "FAILURE",
    "Pattern",
    "ElementType",
    "Element",
    "Rule",
    "Phase",
    "BUILTIN_PATTERNS",
    "load_pattern",
]

SUCCESS = True
FAILURE = False

BUILTIN_PATTERNS = ("dots", "flowers", "spirals", "hierarchy", "vase", "willow")


@dataclass(frozen=True)
class ElementType:
    """An element type: a name, its proxy types (one or more) and user fields with defaults."""

    name: str
    proxies: tuple[type[Proxy], ...]
    fields: Mapping[str, Any] = field(default_factory=dict)


class Element:
    """One element of the ornament.

    Attributes
    ----------
    type : str
        Element type name.
    proxies : list of Proxy
        In declaration order; ``proxy`` is ``proxies[0]`` (the paper's ``$``).
    sterile : bool
        When True, no rule is tried on this element again (§4.1, Appendix A).
    parent : Element or None
        The element the rule that created this one was invoked on.
    children : list of Element
        Elements created by rules invoked on this one.
    index : int
        Placement order (0, 1, ...) once placed; -1 before.
    phase : str or None
        The phase in which it was placed.
    User fields are plain attributes, initialised from the type's defaults.
    """

    def __init__(self, etype: ElementType) -> None:
        self.type = etype.name
        self.proxies: list[Proxy] = [cls() for cls in etype.proxies]
        self.sterile = False
        self.parent: Element | None = None
        self.children: list[Element] = []
        self.index = -1
        self.phase: str | None = None
        for k, v in etype.fields.items():
            setattr(self, k, copy.copy(v))

    @property
    def proxy(self) -> Proxy:
        """Proxy 0 (the paper's ``$``)."""
        return self.proxies[0]

    @property
    def n_children(self) -> int:
        return len(self.children)

    def __repr__(self) -> str:
        return f"Element({self.type!r}, index={self.index}, proxies={self.proxies!r})"


@dataclass(frozen=True)
class Rule:
    """A growth rule: parent type, static child types, precondition and body."""

    name: str
    parent: str
    children: tuple[str, ...]
    body: Callable[..., Any]
    when: Callable[[Any], bool] | None = None
    phase: str | None = None


@dataclass(frozen=True)
class Phase:
    """A growth phase (§5, Fig. 10): rules with ``phase=name`` run only in it.

    The phase ends, and the next one starts, when no eligible empty circle of radius at
    least ``min_radius`` remains (the last phase ends at the run's minimum radius).
    """

    name: str
    min_radius: float | None = None


RenderFn = Callable[..., Any]


class Pattern:
    """Adaptive clip art: element types and growth rules (§3.2).

    Parameters
    ----------
    name : str
        Shown in outputs and messages.
    state : mapping, optional
        Global state of the pattern (the paper's ``%source`` globals). Each run gets a
        deep copy as ``ctx.state`` (attribute access), plus ``ctx.state.phase``.
    phases : sequence of str or (str, float) or Phase, optional
        Phases of hierarchical growth, in order (§5: "state preconditions").
    min_radius : float
        Growth stops when no eligible empty circle is at least this large.
    description : str
        One line for listings and the demo.
    draw_order : sequence of str
        Element types drawn first to last (others follow in declaration order).
    """

    def __init__(
        self,
        name: str,
        *,
        state: Mapping[str, Any] | None = None,
        phases: Sequence[str | tuple[str, float] | Phase] | None = None,
        min_radius: float = 1.0,
        description: str = "",
        draw_order: Sequence[str] = (),
    ) -> None:
        self.name = str(name)
        self.draw_order = tuple(draw_order)
        self.state = dict(state or {})
        self.description = description
        if not min_radius > 0:
            raise InputError(f"pattern {name!r}: min_radius must be positive, got {min_radius!r}")
        self.min_radius = float(min_radius)
        ph: list[Phase] = []
        for p in phases or ():
            if isinstance(p, Phase):
                ph.append(p)
            elif isinstance(p, str):
                ph.append(Phase(p))
            else:
                ph.append(Phase(str(p[0]), None if p[1] is None else float(p[1])))
        self.phases: tuple[Phase, ...] = tuple(ph)
        self.types: dict[str, ElementType] = {}
        self.rules: list[Rule] = []
        self.renderers: dict[tuple[str, str], RenderFn] = {}
        self.groups: dict[str, tuple[str, str]] = {}  # type -> (field, drawn name); see group()
        self.style_help: dict[str, str] = {}
        self.source: str | None = None

    # -- declarations ---------------------------------------------------------------------
    def element(self, name: str, proxies: type[Proxy] | str | Iterable[type[Proxy] | str], **fields: Any) -> ElementType:
        """Declare an element type with one or more proxies and user fields (§4.2).

        Parameters
        ----------
        name : str
            Type name; ``"seed"`` is required and must have a single :class:`Point` proxy.
        proxies : Proxy class or name, or a sequence of them
            E.g. ``Circle`` or ``[Bezier, Bezier]`` or ``"bezier bezier"``.
        **fields
            User fields and their initial values.
        """
        if isinstance(proxies, str):
            proxies = proxies.split()
        elif isinstance(proxies, type):
            proxies = [proxies]
        classes = []
        for p in proxies:
            if isinstance(p, str):
                if p not in PROXY_TYPES:
                    raise InputError(f"element {name!r}: unknown proxy {p!r} (have: {', '.join(sorted(set(PROXY_TYPES)))})")
                p = PROXY_TYPES[p]
            if not (isinstance(p, type) and issubclass(p, Proxy)):
                raise InputError(f"element {name!r}: proxies must be proxy classes, got {p!r}")
            classes.append(p)
        if not classes:
            raise InputError(f"element {name!r}: needs at least one proxy")
        if name in self.types:
            raise InputError(f"element {name!r} declared twice")
        reserved = set(dir(Element)) | {"type", "proxies", "sterile", "parent", "children", "index", "phase"}
        bad = sorted(set(fields) & reserved)
        if bad:
            raise InputError(f"element {name!r}: field name(s) {bad} are reserved")
        et = ElementType(str(name), tuple(classes), dict(fields))
        self.types[et.name] = et
        return et

    def rule(
        self,
        parent: str | Sequence[str],
        children: Sequence[str] | str = (),
        *,
        when: Callable[[Any], bool] | None = None,
        phase: str | None = None,
        name: str | None = None,
    ) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
        """Decorator declaring a growth rule (§4.2); rules are tried in declaration order.

        The body is called as ``body(ctx, parent, *static_children)`` and returns
        ``SUCCESS`` (True) or ``FAILURE`` (False).

        Parameters
        ----------
        parent : str or sequence of str
            The element type the rule acts on; several types (a sequence, or names
            separated by spaces) declare the same body once for each.
        children : sequence of str
            Types of the static children, created fresh for each invocation.
        when : callable, optional
            Precondition on ``ctx.state``; when it is false the rule fails at once.
        phase : str, optional
            Shorthand for ``when=lambda s: s.phase == phase``.
        """
        if isinstance(children, str):
            children = children.split()

        parents = parent.split() if isinstance(parent, str) else [str(p) for p in parent]

        def deco(fn: Callable[..., Any]) -> Callable[..., Any]:
            for par in parents:
                self.rules.append(Rule(name or fn.__name__, par, tuple(children), fn, when, phase))
            return fn

        return deco

    def group(self, type_name: str, field: str, name: str | None = None) -> None:
        """Draw the elements of a type that share a field's value as one element.

        The paper grows a spiral as several Bezier segments, dynamic children (§4.2); the
        reader sees one spiral. With ``pattern.group("arm", "spiral", "spiral")`` the
        arms of one spiral become one row of the output, of kind ``name`` (default: the
        type's name), their marks drawn in order, so that counts per kind count spirals.
        """
        if type_name not in self.types:
            raise InputError(f"pattern {self.name!r}: group of unknown element type {type_name!r}")
        if field not in self.types[type_name].fields:
            raise InputError(f"pattern {self.name!r}: element type {type_name!r} has no field {field!r} to group by")
        self.groups[type_name] = (field, name or type_name)

    def render(self, type_name: str, style: str = "default", help: str | None = None) -> Callable[[RenderFn], RenderFn]:
        """Decorator declaring how an element type is drawn in a named style (§4, Fig. 17).

        The function is called as ``fn(element, ctx)`` and returns a list of
        :class:`~strew.ornament.Mark` (SVG paths with fill and stroke).
        """

        def deco(fn: RenderFn) -> RenderFn:
            self.renderers[(str(type_name), str(style))] = fn
            if help:
                self.style_help[str(style)] = help
            return fn

        return deco

    @property
    def styles(self) -> tuple[str, ...]:
        """Styles this pattern defines itself."""
        return tuple(dict.fromkeys(s for _, s in self.renderers))

    # -- checks ---------------------------------------------------------------------------
    def validate(self) -> None:
        """Raise :class:`InputError` naming the first problem of the declarations."""
        where = f"rule file {self.source}" if self.source else f"pattern {self.name!r}"
        seed = self.types.get("seed")
        if seed is None:
            raise InputError(f"{where}: no 'seed' element type; declare pattern.element('seed', Point)")
        if seed.proxies != (Point,):
            raise InputError(f"{where}: the 'seed' type must have exactly one Point proxy")
        declared = ", ".join(self.types)
        phases = {p.name for p in self.phases}
        if not self.rules:
            raise InputError(f"{where}: declares no rules")
        for r in self.rules:
            for t in (r.parent, *r.children):
                if t not in self.types:
                    line = getattr(getattr(r.body, "__code__", None), "co_firstlineno", None)
                    at = f" (line {line})" if line else ""
                    raise InputError(f"{where}: rule {r.name!r}{at} names unknown element type {t!r} (declared: {declared})")
            if r.phase is not None and r.phase not in phases:
                raise InputError(f"{where}: rule {r.name!r} uses unknown phase {r.phase!r} (declared: {sorted(phases)})")
        for t, s in self.renderers:
            if t not in self.types:
                raise InputError(f"{where}: render function for unknown element type {t!r} (declared: {declared})")

    def new_state(self) -> SimpleNamespace:
        """A fresh copy of the global state for one run."""
        st = SimpleNamespace(**copy.deepcopy(self.state))
        st.phase = self.phases[0].name if self.phases else None
        return st

    def __repr__(self) -> str:
        return f"Pattern({self.name!r}, types={list(self.types)}, rules={[r.name for r in self.rules]})"


# -- rule files ---------------------------------------------------------------------------
def _error_line(exc: BaseException, path: str) -> int | None:
    line = None
    for fr in traceback.extract_tb(exc.__traceback__):
        if Path(fr.filename).resolve() == Path(path).resolve():
            line = fr.lineno
    return line


def _exec_rule_file(path: Path) -> Any:
    digest = hashlib.sha1(str(path.resolve()).encode()).hexdigest()[:12]
    modname = f"strew_rule_file_{digest}"
    try:
        source = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise InputError(f"rule file {path}: cannot read ({exc})") from None
    try:
        code = compile(source, str(path), "exec")
    except SyntaxError as exc:
        raise InputError(f"rule file {path}, line {exc.lineno}: syntax error: {exc.msg}") from None
    spec = importlib.util.spec_from_loader(modname, loader=None, origin=str(path))
    module = importlib.util.module_from_spec(spec)  # type: ignore[arg-type]
    module.__file__ = str(path)
    sys.modules[modname] = module
    try:
        exec(code, module.__dict__)
    except InputError as exc:
        line = _error_line(exc, str(path))
        at = f", line {line}" if line else ""
        raise InputError(f"rule file {path}{at}: {exc}") from None
    except Exception as exc:
        line = _error_line(exc, str(path))
        at = f", line {line}" if line else ""
        raise InputError(f"rule file {path}{at}: {type(exc).__name__}: {exc}") from None
    finally:
        sys.modules.pop(modname, None)
    return module


def load_pattern(spec: str | Path | Pattern) -> Pattern:
    """The :class:`Pattern` named by a built-in name or a rule-file path, validated.

    Parameters
    ----------
    spec : str, path or Pattern
        ``"dots"``, ``"flowers"``, ``"spirals"``, ``"hierarchy"``, or a ``.py`` file that
        assigns ``pattern = Pattern(...)``.

    Raises
    ------
    InputError
        Unknown name, missing file, syntax error (with file and line), a rule naming an
        unknown type, a missing ``seed`` type.
    """
    if isinstance(spec, Pattern):
        spec.validate()
        return spec
    text = str(spec)
    if text in BUILTIN_PATTERNS:
        module = importlib.import_module(f"strew.ornament.patterns.{text}")
        pat = module.pattern
        pat.validate()
        return pat
    path = Path(text)
    if not path.is_file():
        raise InputError(
            f"pattern: {text!r} is neither a built-in pattern ({', '.join(BUILTIN_PATTERNS)}) nor a rule file"
        )
    if path.suffix != ".py":
        raise InputError(f"rule file {path}: expected a Python file (.py)")
    module = _exec_rule_file(path)
    pat = getattr(module, "pattern", None)
    if not isinstance(pat, Pattern):
        found = [v for v in vars(module).values() if isinstance(v, Pattern)]
        if len(found) != 1:
            raise InputError(f"rule file {path}: defines no pattern; assign `pattern = Pattern(...)`")
        pat = found[0]
    pat.source = str(path)
    pat.validate()
    return pat
