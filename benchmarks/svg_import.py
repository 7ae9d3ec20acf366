"""SVG import of drawings of many distinct shapes, against the importer without its
kind pre-filter (every object fully matched against every kind found so far).

Distinct shapes are the worst case of kind detection: each new object is compared with
every kind already found. The pre-filter compares similarity invariants on arrays of all
kinds at once and fully matches only the kinds that can match. Printed: seconds per
file and the ratio pre-filter / all-pairs (< 1 is good), and ms per object, whose
growth with n shows how far from linear the import is.

    python benchmarks/svg_import.py [--quick] [--repeat N]

With ``--against FILE`` (an older ``_svg_import.py``, e.g. from
``git show COMMIT:src/strew/io/_svg_import.py > /tmp/old_import.py``) it instead times
that importer and today's on the same files in one run: n distinct polygons, n copies of
one curved path under transforms, and n ``<use>`` clones of three symbols (as strew's own
exports look). Both must give the same arrangement.
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


def against(opts: Any) -> None:
    import importlib.util
    import sys

    from strew.io.svg import read_svg

    spec = importlib.util.spec_from_file_location("strew.io._svg_import_baseline", opts.against)
    old = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = old  # dataclasses look their module up
    spec.loader.exec_module(old)  # relative imports resolve in strew.io
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
        assert arr.kinds == arr_old.kinds and np.array_equal(arr.kind, arr_old.kind) and np.array_equal(arr.x, arr_old.x)
        assert np.array_equal(arr.rotation, arr_old.rotation) and np.array_equal(arr.scale, arr_old.scale)
        objects = len(arr)
        bench.row(f"{label} ({len(text) / 1e3:.0f} kB)", median_s=t_new, baseline_s=t_old, ratio=t_new / t_old,
                  ms_per_object=1e3 * t_new / objects, baseline_ms_per_object=1e3 * t_old / objects,
                  s_per_MB=t_new / (len(text) / 1e6), baseline_s_per_MB=t_old / (len(text) / 1e6))
    bench.finish()


def main() -> None:
    opts = parse_args(__doc__, extra=lambda p: p.add_argument("--against", default=None, help="an older _svg_import.py to time against"))
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
