"""Imports point down (issue 15 point 7; README "Architecture").

Layers, lowest first: core types (0), io (1), kernels (2), methods and analysis (3),
cli / studio / demo and the package facade (4). A module may import its own layer or a
lower one. The graph is read from the source (every ``import``, also inside functions and
``if TYPE_CHECKING`` blocks), so deferred imports count too.
"""

from __future__ import annotations

import ast
import functools
import subprocess
import sys
from pathlib import Path

import strew

SRC = Path(strew.__file__).resolve().parent
# _warmup runs every command once to compile the kernels at build time (hatch_build.py): an entry point
APP = {"cli", "studio", "demo", "_demos", "tiles", "_warmup", "__main__", ""}
METHODS = {"pack", "grow", "synth", "ornament", "program", "_method", "surface", "_fidelity", "metrics"}
KERNELS = {"_kernels", "_kernel_cache"}

def _name(p: Path) -> str:
    parts = ["strew", *p.relative_to(SRC).with_suffix("").parts]
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _layer(m: str) -> int:
    top = m.split(".")[1] if "." in m else ""
    if top in APP:
        return 4
    if top in METHODS:
        return 3
    if top in KERNELS:
        return 2
    return 1 if top == "io" else 0


@functools.cache
def _graph() -> dict[str, set[str]]:
    # strew/_examples (the examples folder, shipped in the wheel) holds user scripts: they
    # use the public API from above, like any script, and are no layer of the library
    modules = {_name(p): p for p in SRC.rglob("*.py") if "_examples" not in p.relative_to(SRC).parts}
    edges: dict[str, set[str]] = {}
    for m, p in modules.items():
        pkg = m if p.name == "__init__.py" else m.rsplit(".", 1)[0]
        targets: set[str] = set()
        for node in ast.walk(ast.parse(p.read_text(encoding="utf-8"))):
            names: list[str] = []
            if isinstance(node, ast.ImportFrom):
                if node.level:
                    base = pkg.split(".")[: len(pkg.split(".")) - (node.level - 1)]
                    mod = ".".join(base + ([node.module] if node.module else []))
                else:
                    mod = node.module or ""
                names = [mod] + [f"{mod}.{a.name}" for a in node.names]
            elif isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            for t in names:
                while t not in modules and "." in t:
                    t = t.rsplit(".", 1)[0]
                if t in modules and t != m:
                    targets.add(t)
        edges[m] = targets
    return edges


def test_imports_point_down():
    up = {(m, t) for m, ts in _graph().items() for t in ts if _layer(t) > _layer(m)}
    # no exceptions: Arrangement's display conveniences reach io through the hooks of
    # strew._display, which io fills (issue 15 point 7)
    assert not up, sorted(up)


def _circles(g: dict[str, set[str]]) -> list[set[str]]:
    """Modules that import each other in a loop: the strongly connected components of
    more than one module (Tarjan, iterative)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    out: list[set[str]] = []
    for root in g:
        if root in index:
            continue
        work = [(root, iter(sorted(g[root])))]
        index[root] = low[root] = len(index)
        stack.append(root)
        while work:
            v, it = work[-1]
            w = next(it, None)
            if w is not None:
                if w not in index:
                    index[w] = low[w] = len(index)
                    stack.append(w)
                    work.append((w, iter(sorted(g.get(w, ())))))
                elif w in stack:
                    low[v] = min(low[v], index[w])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[v])
            if low[v] == index[v]:
                comp = set()
                while True:
                    w = stack.pop()
                    comp.add(w)
                    if w == v:
                        break
                if len(comp) > 1:
                    out.append(comp)
    return out


def test_no_import_circle_outside_the_method_packages():
    # issue 15 point 7: arrangement <-> io and cli/_spec <-> cli/surface were such circles;
    # circles inside one method's package are its own business (see the README)
    assert _circles({"a": {"b"}, "b": {"c", "a"}, "c": set()}) == [{"a", "b"}]
    bad = [sorted(c) for c in _circles(_graph()) if any(_layer(m) != 3 for m in c)]
    assert not bad, bad


def test_method_packages_do_not_import_the_app_level_demo():
    bad = [(m, t) for m, ts in _graph().items() for t in ts if _layer(m) == 3 and t == "strew.demo"]
    assert not bad, bad


def test_ornament_render_does_not_import_the_engine():
    g = _graph()
    assert "strew.ornament._engine" not in g["strew.ornament._render"]
    assert "strew.ornament._render" in g["strew.ornament._engine"]  # the one direction left


def test_importing_the_core_type_loads_no_io():
    code = "import sys, strew.arrangement; print(sorted(m for m in sys.modules if m.startswith('strew.io')))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120, check=True)
    assert out.stdout.strip() == "[]", out.stdout


def test_the_core_types_display_through_hooks_that_io_fills():
    # from the core type alone, as a notebook or a script holding an Arrangement: io is
    # not loaded until a writer is used, and then the writers are io's own
    code = (
        "import sys\n"
        "from strew.arrangement import Arrangement\n"
        "from strew.shape import Shape\n"
        "a = Arrangement({'dot': Shape.circle(1)}, ['dot', 'dot'], [0, 5], [0, 0])\n"
        "print(sorted(m for m in sys.modules if m.startswith('strew.io')))\n"
        "svg = a.to_svg(width=120)\n"
        "from strew.io.svg import to_svg\n"
        "from strew.io.png import to_png\n"
        "assert svg == to_svg(a, width=120) and a._repr_svg_() == to_svg(a, width=480)\n"
        "Arrangement.REPR_SVG_MAX_ELEMENTS = 1\n"
        "assert a._repr_svg_() is None and a._repr_png_() == to_png(a, width=720)\n"
        "assert 'data:image/png;base64,' in a._repr_html_()\n"
        "assert Arrangement.from_pandas(a.to_pandas(), a.shapes).equals(a)\n"
        "print('ok')\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["[]", "ok"], out.stdout


def test_no_profiler_dump_in_the_package():
    assert not [p for p in SRC.rglob("*") if p.name in ("prof",) or p.suffix in (".prof", ".pstats")]
