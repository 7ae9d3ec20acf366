"""Scaling of pack's fill-gap (issue 19.6): CPU time against element count.

Packs the leaf of benchmarks/pack.py's case (a) (examples/pack/leaf.json) with fill-gap in squares of growing
side at a fixed element scale, so n grows about 10x over the range; prints n, CPU
seconds, milliseconds per element, and the exponent fitted to log CPU time against
log n. Target: at most 1.15 over a 10x range of n. CPU time, not wall time: the
machine is shared. One warm-up packing compiles (or loads) every kernel first.

Figures (2-core shared machine, CPU s; n 10^4 -> 10^5, sides 2800 / 5000 / 8900):

=======================  ==================  ====================  ========
code                     n                   CPU s                 exponent
=======================  ==================  ====================  ========
ec095b0 (before)         9,957 / 30,575 /    1.13 / 3.49 / 19.0    1.24
                         97,257
issue 19.6 fix           10,056 / 31,833 /   1.24 / 3.11 / 9.93    0.91
                         100,439
=======================  ==================  ====================  ========

Before, the default distance field was coarsened to 400,000 pixels (14 units a pixel
at side 8900 against 4.4 at 2800: fewer poses pruned by the field, 2.0 against 1.1 us
a pose), and at a fixed cell each round drew Q from the whole field for a fixed P
candidates (resolution 4.43: 1.1 / 8.0 / 47 s). Now the field is coarsened only above
4,000,000 pixels, and a field of k x 400,000 pixels tries k P candidates per round
(``strew.pack._pack._fill_gap``); fields up to 400,000 pixels are unchanged bit for bit.

Run: ``python benchmarks/pack_scaling.py [--quick] [--profile]`` (``--profile`` prints
a cProfile of the largest case).
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from _runner import Bench, parse_args  # noqa: E402

from strew import Region, load_shapes  # noqa: E402
from strew.pack import pack  # noqa: E402

EXAMPLES = Path(__file__).resolve().parent.parent / "examples" / "pack"
SIDES = [2800.0, 5000.0, 8900.0]
SIDES_QUICK = [600.0, 1100.0, 1900.0]


def _run(shapes: dict, side: float) -> int:
    arr = pack(shapes, Region.rectangle(side, side), rng=1)
    return len(arr)


def main() -> None:
    args = parse_args(__doc__.splitlines()[0], extra=lambda p: p.add_argument("--profile", action="store_true"))
    shapes = load_shapes(EXAMPLES / "leaf.json")
    _run(shapes, 150.0)  # compile the kernels first
    bench = Bench("pack_scaling", "fill-gap in squares of growing side: CPU time vs n", baseline="exponent target 1.15", json_path=args.json)
    ns, ts = [], []
    sides = SIDES_QUICK if args.quick else SIDES
    for s in sides:
        t0 = time.process_time()
        n = _run(shapes, s)
        t = time.process_time() - t0
        ns.append(n)
        ts.append(t)
        bench.row(f"leaf side {s:g}", n=n, cpu_s=t, ms_per_el=1e3 * t / n)
        print(f"side {s:5.0f}  n {n:7d}  cpu {t:8.2f} s  {1e3 * t / n:6.3f} ms/el", flush=True)
    k = float(np.polyfit(np.log(ns), np.log(ts), 1)[0])
    print(f"fitted exponent (log CPU time vs log n, n {ns[0]}..{ns[-1]}, {ns[-1] / ns[0]:.1f}x): {k:.3f}  (target <= 1.15)", flush=True)
    bench.row("fit", exponent=k, n_range=ns[-1] / ns[0])
    if args.profile:
        import cProfile
        import pstats
        pr = cProfile.Profile()
        pr.enable()
        _run(shapes, sides[-1])
        pr.disable()
        pstats.Stats(pr).sort_stats("cumulative").print_stats(25)
    bench.finish()


if __name__ == "__main__":
    main()
