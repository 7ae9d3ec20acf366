"""Scaling of the planar map (issue 19.6): time and peak memory against segment count.

Induces the planar map of n random segments of fixed length in a square whose area grows
with n (the density of crossings stays the same), for n over a 10x range; prints n, CPU
seconds, the number of cells, the peak memory traced by ``tracemalloc`` per segment (the
Python heap: numpy arrays and Python objects; GEOS' own C allocations are not traced)
and the exponent fitted to log time against log n. Targets: exponent at most 1.15, under
2 KB per segment.

Run: ``python benchmarks/program_scaling.py [--quick]``.
"""

from __future__ import annotations

import sys
import time
import tracemalloc
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from _runner import Bench, parse_args  # noqa: E402

from strew.program import Curve, Curves, induce  # noqa: E402


def random_segments(n: int, seed: int = 0) -> Curves:
    rng = np.random.default_rng(seed)
    side = 20.0 * np.sqrt(n)  # about the same crossings per segment at every n
    p = rng.uniform(0, side, (n, 2))
    ang = rng.uniform(0, 2 * np.pi, n)
    q = p + 30.0 * np.c_[np.cos(ang), np.sin(ang)]
    return Curves(tuple(Curve(np.stack([a, b])) for a, b in zip(p, q)))


def main() -> None:
    args = parse_args(__doc__.splitlines()[0])
    ns = [2000, 6000, 20000] if args.quick else [4000, 12000, 40000]
    induce(random_segments(200))
    bench = Bench("program_scaling", "planar map of n random segments: time and memory vs n", baseline="targets: exponent 1.15, 2 KB/segment", json_path=args.json)
    ts = []
    for n in ns:
        curves = random_segments(n)
        t0 = time.process_time()
        pm = induce(curves)
        t = time.process_time() - t0
        ts.append(t)
        del pm
        tracemalloc.start()
        pm = induce(curves)
        _, peak = tracemalloc.get_traced_memory()
        tracemalloc.stop()
        kb = peak / n / 1024
        bench.row(f"n {n}", cpu_s=t, vertices=pm.n_vertices, edges=pm.n_edges, faces=pm.n_faces, peak_kb_per_segment=kb)
        print(f"n {n:7d}  cpu {t:7.2f} s  V {pm.n_vertices}  E {pm.n_edges}  F {pm.n_faces}  peak {kb:.2f} KB/segment", flush=True)
        del pm
    k = np.polyfit(np.log(ns), np.log(ts), 1)[0]
    print(f"fitted exponent (log cpu time vs log n, n {ns[0]}..{ns[-1]}): {k:.3f}  (target <= 1.15)")
    bench.row("fit", exponent=float(k))
    bench.finish()


if __name__ == "__main__":
    main()
