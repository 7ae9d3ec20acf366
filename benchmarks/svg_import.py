"""SVG import of drawings of many distinct shapes, against the importer without its
kind pre-filter (every object fully matched against every kind found so far).

Distinct shapes are the worst case of kind detection: each new object is compared with
every kind already found. The pre-filter compares similarity invariants on arrays of all
kinds at once and fully matches only the kinds that can match. Printed: seconds per
file and the ratio pre-filter / all-pairs (< 1 is good), and ms per object, whose
growth with n shows how far from linear the import is.

    python benchmarks/svg_import.py [--quick] [--repeat N]
"""

from __future__ import annotations

import numpy as np
from _runner import Bench, median_time, parse_args


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


def main() -> None:
    opts = parse_args(__doc__)
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
