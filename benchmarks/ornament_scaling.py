"""Scaling of ornament's largest-empty-circle engine (issue 19.6): time against element count.

Grows ``dots`` (at min_radius 1) and ``flowers`` in squares of increasing side, each over
about 1k-10k and 2k-20k elements (the
raster's cell stays the same, so the raster grows with the panel), prints n, CPU seconds,
milliseconds per element, and per pattern the exponent fitted to log CPU time against
log n. Target: at most 1.15 over a 10x range of n. CPU time, not wall time: the machine
is shared.

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
from strew.ornament import grow_elements, load_pattern  # noqa: E402


CASES = {
    # pattern: (min_radius, sides full, sides quick); dots at min_radius 1 have no
    # failures (the raster's waves dominate), flowers have many (the exclude list and
    # the proxy queries dominate)
    "dots": (1.0, [150.0, 270.0, 480.0], [60.0, 110.0, 190.0]),
    "flowers": (None, [100.0, 180.0, 320.0], [60.0, 110.0, 190.0]),
    # the upper decade, 2k-20k elements (dots were 1.15 there last session)
    "dots 2k-20k": (1.0, [200.0, 360.0, 640.0], []),
    "flowers 2k-20k": (None, [150.0, 270.0, 470.0], []),
}


def main() -> None:
    args = parse_args(__doc__.splitlines()[0])
    grow_elements("dots", Region.rectangle(20, 20), rng=0)  # compile the kernels first
    bench = Bench("ornament_scaling", "growth in squares of growing side: CPU time vs n", baseline="exponent target 1.15", json_path=args.json)
    for case, (mr, full, quick) in CASES.items():
        pat = case.split()[0]
        if args.quick and not quick:
            continue
        ns, ts = [], []
        for s in quick if args.quick else full:
            t0 = time.process_time()
            # cells of half the minimum radius at every size (the default resolution is
            # at least 256 cells, finer in small panels)
            res = int(round(s / (0.5 * (mr or load_pattern(pat).min_radius))))
            orn = grow_elements(pat, Region.rectangle(s, s), rng=0, min_radius=mr, resolution=res)
            t = time.process_time() - t0
            n = len(orn.elements)
            ns.append(n)
            ts.append(t)
            bench.row(f"{case} side {s:g}", n=n, cpu_s=t, ms_per_el=1e3 * t / n, failures=orn.stats["failures"], resolution=orn.stats["resolution"])
            print(f"{pat:8s} side {s:5.0f}  n {n:7d}  cpu {t:8.2f} s  {1e3 * t / n:6.3f} ms/el", flush=True)
        k = float(np.polyfit(np.log(ns), np.log(ts), 1)[0])
        print(f"{case}: fitted exponent (log CPU time vs log n, n {ns[0]}..{ns[-1]}, {ns[-1] / ns[0]:.1f}x): {k:.3f}  (target <= 1.15)", flush=True)
        bench.row(f"{case} fit", exponent=k, n_range=ns[-1] / ns[0])
    bench.finish()


if __name__ == "__main__":
    main()
