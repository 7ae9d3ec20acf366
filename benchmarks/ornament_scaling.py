"""Scaling of ornament's largest-empty-circle engine (issue 19.6): time against element count.

Grows the ``dots`` pattern in squares of increasing side at a fixed ``min_radius`` (the
raster's cell is then fixed too, so the raster grows with the panel), prints n, seconds,
seconds per 1,000 elements, and the exponent fitted to log time against log n. Target:
at most 1.15 over a 10x range of n.

Run: ``python benchmarks/ornament_scaling.py [--quick]``.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from _runner import Bench, parse_args  # noqa: E402

from strew import Region  # noqa: E402
from strew.ornament import grow_elements  # noqa: E402


def main() -> None:
    args = parse_args(__doc__.splitlines()[0])
    sides = [60.0, 110.0, 190.0] if args.quick else [60.0, 95.0, 150.0, 240.0]
    grow_elements("dots", Region.rectangle(20, 20), rng=0)  # compile the kernels first
    bench = Bench("ornament_scaling", "dots in squares of growing side: time vs n", baseline="exponent target 1.15", json_path=args.json)
    ns, ts = [], []
    for s in sides:
        t0 = time.process_time()
        orn = grow_elements("dots", Region.rectangle(s, s), rng=0, min_radius=1.0)
        t = time.process_time() - t0
        n = len(orn.elements)
        ns.append(n)
        ts.append(t)
        bench.row(f"side {s:g}", n=n, cpu_s=t, ms_per_1k=1e3 * t / n * 1e3 / 1e3, resolution=orn.stats["resolution"])
        print(f"side {s:6.0f}  n {n:7d}  cpu {t:8.2f} s  {1e3 * t / n:6.3f} ms/el", flush=True)
    k = np.polyfit(np.log(ns), np.log(ts), 1)[0]
    print(f"fitted exponent (log cpu time vs log n, n {ns[0]}..{ns[-1]}, {ns[-1] / ns[0]:.1f}x): {k:.3f}  (target <= 1.15)")
    bench.row("fit", exponent=float(k), n_range=ns[-1] / ns[0])
    bench.finish()


if __name__ == "__main__":
    main()
