"""SVG import of drawings of many distinct shapes, against the importer without its
kind pre-filter (every object fully matched against every kind found so far).

Distinct shapes are the worst case of kind detection: each new object is compared with
every kind already found. The pre-filter compares similarity invariants on arrays of all
kinds at once and fully matches only the kinds that can match. Printed: seconds per
file and the ratio pre-filter / all-pairs (< 1 is good), and ms per object, whose
growth with n shows how far from linear the import is.

    python benchmarks/svg_import.py [--quick] [--repeat N]

With ``--against FILE`` (an older single-file ``_svg_import.py``, e.g. from
``git show COMMIT:src/strew/io/_svg_import.py > /tmp/old_import.py``, read with today's
``_svg_flatten``) or ``--against COMMIT`` (the reader as it was at that commit: its
``_svg_flatten``, ``_svg_match``, ``_svg_tree`` and ``_svg_import`` modules, those it had) it instead times
that importer and today's on the same files in one run: n distinct polygons, n copies of
one curved path under transforms, and n ``<use>`` clones of three symbols (as strew's own
exports look). Both must give the same kinds, counts and poses (to 1e-3, see ``_same``).

With ``--scaling`` (issue 17.3) it times files of about 0.1, 1 and 10 MB (``--max-mb``)
of four kinds: distinct polygons (every object a kind of its own: the worst case), copies
of one path text under transforms, copies with their coordinates baked into the path data
(as Inkscape stores moved copies: one kind found by geometry) and clones of three
symbols. It prints seconds per MB (CPU time of this process, so that other load on the
machine counts less; the median of ``--repeat`` reads, the two importers' reads
interleaved) and, with ``--against``, the older importer's seconds per MB on the
files up to ``--old-max-mb`` (default 1) and the ratio, and the exponent ``e`` of
cost ~ size^e between consecutive sizes (1 is linear). ``--max-mb 50`` adds 50 MB files
(the size of issue 17's 687k-path file); ``--only distinct,clones`` picks kinds of file. The path-count limit is raised
for the run (10 MB holds over 50,000 objects).

    python benchmarks/svg_import.py --scaling --against b8e4e2d
"""

from __future__ import annotations

from typing import Any

import numpy as np
from _runner import Bench, median_time, parse_args, timed


def drawing(n: int, seed: int = 1) -> str:
    """An SVG of ``n`` random 5- to 8-gons, all different (a hand-drawn exemplar's worst case)."""
    rng = np.random.default_rng(seed)
    parts = []
    for _ in range(n):
        x, y = rng.uniform(0, 1000, 2)
        k = int(rng.integers(5, 9))
        t = np.sort(rng.uniform(0, 2 * np.pi, k))
        r = rng.uniform(2, 6, k)
        pts = " ".join(f"{x + a * np.cos(b):.2f},{y + a * np.sin(b):.2f}" for a, b in zip(r, t))
        parts.append(f'<polygon points="{pts}"/>')
    return '<svg xmlns="http://www.w3.org/2000/svg">' + "".join(parts) + "</svg>"


def copies(n: int, seed: int = 2) -> str:
    """An SVG of ``n`` copies of one curved path, each moved, turned and scaled by a transform."""
    rng = np.random.default_rng(seed)
    parts = []
    for _ in range(n):
        x, y = rng.uniform(0, 1000, 2)
        parts.append(f'<path transform="translate({x:.2f} {y:.2f}) rotate({rng.uniform(0, 360):.1f}) scale({rng.uniform(0.5, 2):.2f})" '
                     'd="M0,0 C2,3 5,3 6,0 Q3,-2 0,0 Z"/>')
    return '<svg xmlns="http://www.w3.org/2000/svg">' + "".join(parts) + "</svg>"


def clones(n: int, seed: int = 3) -> str:
    """An SVG of ``n`` ``<use>`` clones of three symbols."""
    rng = np.random.default_rng(seed)
    head = ('<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink"><defs>'
            '<symbol id="leaf"><path d="M0,0 C2,3 5,3 6,0 Q3,-2 0,0 Z"/></symbol><symbol id="dot"><circle r="1"/></symbol>'
            '<symbol id="sq"><rect x="-1" y="-1" width="2" height="2"/></symbol></defs>')
    uses = [f'<use xlink:href="#{("leaf", "dot", "sq")[i % 3]}" transform="translate({x:.2f} {y:.2f}) rotate({a:.1f})"/>'
            for i, (x, y, a) in enumerate(rng.uniform((0, 0, 0), (1000, 1000, 360), (n, 3)))]
    return head + "".join(uses) + "</svg>"


def baked(n: int, seed: int = 4) -> str:
    """``n`` copies of one curved outline, each moved, turned and scaled with the numbers
    written into its path data (Inkscape's default for moved paths)."""
    rng = np.random.default_rng(seed)
    ctrl = np.array([[0, 0], [2, 3], [5, 3], [6, 0], [3, -2], [0, 0]], dtype=float) - (3, 0.7)
    parts = []
    for _ in range(n):
        x, y = rng.uniform(0, 1000, 2)
        a, s = rng.uniform(0, 2 * np.pi), rng.uniform(0.5, 2)
        q = s * ctrl @ np.array([[np.cos(a), np.sin(a)], [-np.sin(a), np.cos(a)]]) + (x, y)
        f = [f"{v:.4f}" for v in q.ravel()]
        parts.append(f'<path d="M{f[0]},{f[1]} C{f[2]},{f[3]} {f[4]},{f[5]} {f[6]},{f[7]} Q{f[8]},{f[9]} {f[10]},{f[11]} Z"/>')
    return '<svg xmlns="http://www.w3.org/2000/svg">' + "".join(parts) + "</svg>"


def _cpu(fn: Any) -> tuple[float, Any]:
    import time

    t0 = time.process_time()
    out = fn()
    return time.process_time() - t0, out


def _same(arr: Any, old: Any) -> bool:
    """The same kinds, counts and poses (rotation modulo a full turn) within 1e-3.

    Not 1e-9: the older importer took every copy's pose from moments checked only to the
    flattening tolerance (on ``copies``: scale off by up to 9e-5 relative, rotation 1.5e-6),
    where the copy shortcut takes the transform itself (exact to 1e-15)."""
    if arr.counts() != old.counts() or [arr.kinds[k] for k in arr.kind] != [old.kinds[k] for k in old.kind]:
        return False
    turn = np.angle(np.exp(1j * (arr.rotation - old.rotation)))
    pos = np.c_[arr.x, arr.y, arr.scale] - np.c_[old.x, old.y, old.scale]
    return bool(np.abs(pos).max() <= 1e-3 * max(1.0, float(np.abs(np.c_[old.x, old.y]).max())) and np.abs(turn).max() <= 1e-3)


def scaling(opts: Any, old: Any) -> None:
    import math

    import strew
    from strew.io.svg import read_svg

    sizes = [mb for mb in (0.1, 1.0, 10.0, 50.0) if mb <= opts.max_mb]
    repeat = max(1, opts.repeat)  # medians of this many reads of each file (--repeat)
    bench = Bench("svg_import_scaling", "SVG import: seconds per MB from 0.1 to 10 MB (CPU time)",
                  baseline=f"importer in {opts.against}" if old is not None else "none", json_path=opts.json)
    read_svg(drawing(20)), read_svg(copies(20)), read_svg(baked(20))  # warm-up
    if old is not None:
        old.read_svg(drawing(20))
    makers = {"distinct polygons": (drawing, 109), "copies of one path text": (copies, 103), "baked copies (Inkscape)": (baked, 124), "clones of 3 symbols": (clones, 75)}
    with strew.limits(paths=1e7, file_size=1e9):
        for label, (make, per_object) in makers.items():
            if opts.only and not any(w in label for w in opts.only.split(",")):
                continue
            seen: list[tuple[float, float]] = []
            for mb in sizes:
                n = max(10, int(mb * 1e6 / per_object))
                text = make(n)
                with_old = old is not None and mb <= opts.old_max_mb
                runs_new, runs_old = [], []
                for _ in range(repeat):  # interleaved, so that load on the machine hits both alike
                    t, arr = _cpu(lambda: read_svg(text))
                    runs_new.append(t)
                    if with_old:
                        t, arr_old = _cpu(lambda: old.read_svg(text))
                        runs_old.append(t)
                t_new = float(np.median(runs_new))
                row: dict[str, Any] = {"MB": round(len(text) / 1e6, 3), "objects": len(arr), "kinds": len(arr.kinds), "cpu_s": t_new, "s_per_MB": t_new / (len(text) / 1e6)}
                if with_old:
                    t_old = float(np.median(runs_old))
                    row.update(old_s_per_MB=t_old / (len(text) / 1e6), ratio=t_new / t_old, same=_same(arr, arr_old))
                if seen:  # cost ~ size^exponent between this file and the previous one (1: linear)
                    row["exponent"] = math.log(t_new / seen[-1][1]) / math.log(len(text) / seen[-1][0])
                seen.append((len(text), t_new))
                bench.row(f"{label}, {len(text) / 1e6:.2g} MB", **row)
    bench.finish()


def _load_module(name: str, path: str) -> Any:
    import importlib.util
    import sys

    spec = importlib.util.spec_from_file_location(name, path)
    mod = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = mod  # dataclasses look their module up
    spec.loader.exec_module(mod)  # relative imports resolve in strew.io
    return mod


def _load_old(path: str) -> Any:
    """An older importer: a file (read with today's ``_svg_flatten``), or a git revision,
    whose reader modules are all loaded, lowest first (the whole reader as it was at that
    commit: ``_svg_flatten`` and ``_svg_import``, and since the split of issue 15.7
    ``_svg_match`` and ``_svg_tree``)."""
    import os
    import re
    import subprocess
    import tempfile

    if os.path.isfile(path):
        return _load_module("strew.io._svg_import_baseline", path)
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    tag = re.sub(r"\W", "_", path)
    folder = tempfile.mkdtemp(prefix="strew_svg_baseline_")
    listed = subprocess.run(["git", "ls-tree", "--name-only", path, "src/strew/io/"], cwd=root, capture_output=True, text=True, check=True).stdout.split()
    # the reader's modules, lowest first (before the split of issue 15.7 only the first and last)
    names = [n for n in ("_svg_flatten", "_svg_match", "_svg_tree", "_svg_import") if f"src/strew/io/{n}.py" in listed]
    mod = None
    for name in names:
        text = subprocess.run(["git", "show", f"{path}:src/strew/io/{name}.py"], cwd=root, capture_output=True, text=True, check=True).stdout
        for other in names:
            text = text.replace(f"from .{other} import", f"from .{other}_{tag} import")
        file = os.path.join(folder, f"{name}_{tag}.py")
        with open(file, "w") as f:
            f.write(text)
        mod = _load_module(f"strew.io.{name}_{tag}", file)
    return mod


def against(opts: Any) -> None:
    from strew.io.svg import read_svg

    old = _load_old(opts.against)
    n = 300 if opts.quick else 1000
    repeat = 1 if opts.quick else max(1, min(opts.repeat, 5))
    bench = Bench("svg_import_against", "SVG import, today against an older importer", baseline=f"importer in {opts.against}", json_path=opts.json)
    read_svg(drawing(20)), old.read_svg(drawing(20))  # warm-up
    for label, text in ((f"{n} distinct polygons", drawing(n)), (f"{n} copies of a curved path", copies(n)), (f"{5 * n} clones of 3 symbols", clones(5 * n))):
        runs_new, runs_old = [], []
        for _ in range(repeat):  # interleaved, so that load on the machine hits both alike
            t, arr = timed(lambda: read_svg(text))
            runs_new.append(t)
            t, arr_old = timed(lambda: old.read_svg(text))
            runs_old.append(t)
        t_new, t_old = float(np.median(runs_new)), float(np.median(runs_old))
        assert _same(arr, arr_old), label
        objects = len(arr)
        bench.row(f"{label} ({len(text) / 1e3:.0f} kB)", median_s=t_new, baseline_s=t_old, ratio=t_new / t_old,
                  ms_per_object=1e3 * t_new / objects, baseline_ms_per_object=1e3 * t_old / objects,
                  s_per_MB=t_new / (len(text) / 1e6), baseline_s_per_MB=t_old / (len(text) / 1e6))
    bench.finish()


def main() -> None:
    def extra(p: Any) -> None:
        p.add_argument("--against", default=None, help="an older _svg_import.py, or a git commit, to time against")
        p.add_argument("--scaling", action="store_true", help="seconds per MB on 0.1, 1 and 10 MB files")
        p.add_argument("--max-mb", type=float, default=10.0, help="largest file for --scaling")
        p.add_argument("--old-max-mb", type=float, default=1.0, help="largest file the older importer reads in --scaling")
        p.add_argument("--only", default=None, help="--scaling: only the kinds of file whose label holds one of these comma-separated words")

    opts = parse_args(__doc__, extra=extra)
    if opts.scaling:
        scaling(opts, _load_old(opts.against) if opts.against else None)
        return
    if opts.against:
        against(opts)
        return
    from strew.io import _svg_import as imp
    from strew.io.svg import read_svg

    sizes = (250, 500) if opts.quick else (500, 1000, 2000)
    repeat = 1 if opts.quick else max(1, min(opts.repeat, 3))
    bench = Bench("svg_import", "SVG import, n distinct shapes", baseline="all-pairs kind matching (no pre-filter)", json_path=opts.json)
    read_svg(drawing(20))  # warm-up: imports, shapely
    prefilter = imp._Reader.candidate_kinds
    for n in sizes:
        text = drawing(n)
        t_new, arr = median_time(lambda: read_svg(text), repeat=repeat, warmup=0)
        imp._Reader.candidate_kinds = lambda self, sig: np.arange(len(self.kinds))
        try:
            t_old, arr_old = median_time(lambda: read_svg(text), repeat=repeat, warmup=0)
        finally:
            imp._Reader.candidate_kinds = prefilter
        assert arr.kinds == arr_old.kinds and np.array_equal(arr.kind, arr_old.kind)
        bench.row(f"{n} shapes ({len(text) / 1e3:.0f} kB)", median_s=t_new, baseline_s=t_old, ratio=t_new / t_old,
                  ms_per_object=1e3 * t_new / n, baseline_ms_per_object=1e3 * t_old / n, kinds=len(arr.kinds))
    bench.finish()


if __name__ == "__main__":
    main()
