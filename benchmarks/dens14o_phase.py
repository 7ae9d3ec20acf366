"""Issue 14 point 5: where flow mode's CPU time goes as the pattern grows (the hexagonal
exemplar filling a region W x 2W/3 spacings along a field turning 90 degrees, as
``benchmarks/grow.py --against REV --cases hexflow`` at W = 30), and the cost of the
densify pass (:mod:`strew.grow._flow_densify`): its rounds, the insertions made and
kept, and the CPU seconds of its network relaxations, snapshots and rounds.

    PYTHONPATH=src python benchmarks/dens14o_phase.py [--widths 20,30,45,60] [--json F]

Timed in this process (one run per width after a warm-up grow): run it once per tree
(PYTHONPATH) and compare the two runs' ratios, not their seconds, on a shared machine.
The exponent is log(CPU s ratio) / log(element ratio) between consecutive widths.
"""

from __future__ import annotations

import argparse
import functools
import math
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))

from _runner import Bench


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument(
        "--widths",
        default="20,30,45,60",
        help="region widths in spacings (comma-separated)",
    )
    ap.add_argument("--json", default=None)
    a = ap.parse_args()

    import strew
    import strew.grow._flow_densify as FD
    import strew.grow._growth as G
    from strew import Region
    from strew.grow import analyze, grow
    from strew.grow._exemplars import hex_exemplar

    acc: dict[str, float] = {}
    cnt: dict[str, int] = {}

    def wrap(mod, name):
        f = getattr(mod, name)

        @functools.wraps(f)
        def w(*args, **kw):
            t = time.process_time()
            try:
                return f(*args, **kw)
            finally:
                acc[name] = acc.get(name, 0.0) + time.process_time() - t
                cnt[name] = cnt.get(name, 0) + 1

        setattr(mod, name, w)

    for name in ("relax_network", "snapshot", "restore", "_round", "_score"):
        wrap(FD, name)
    made = []
    dens = G.densify

    def densify(g, target):
        t = time.process_time()
        k = dens(g, target)
        made.append((k, time.process_time() - t))
        return k

    G.densify = densify
    bench = Bench(
        "dens14o_phase",
        f"strew.grow flow mode: densify's cost by size ({Path(strew.__file__).parents[1]})",
        baseline="none (figures only)",
        json_path=a.json,
    )
    ref = analyze(hex_exemplar())
    grow(ref, count=50, rng=1)
    sp = ref.mean_edge
    last = None
    for W in (float(v) for v in a.widths.split(",")):
        w = W * sp

        def field(p, w=w):
            ang = np.radians(90.0) * np.clip(np.asarray(p)[:, 0] / w, 0, 1)
            return np.c_[np.cos(ang), np.sin(ang)]

        acc.clear()
        cnt.clear()
        made.clear()
        c = time.process_time()
        out = grow(
            ref,
            rng=1,
            relax=True,
            region=Region.rectangle(w, W * 2 / 3 * sp),
            mode="flow",
            flow=field,
        )
        cpu = time.process_time() - c
        n = len(out)
        expo = math.log(cpu / last[1]) / math.log(n / last[0]) if last else float("nan")
        last = (n, cpu)
        bench.row(
            f"{W:.0f} x {W * 2 / 3:.0f} spacings",
            n=n,
            cpu_s=cpu,
            el_per_cpu_s=n / cpu,
            exponent=expo,
            densify_s=sum(t for _, t in made),
            densify_rounds=cnt.get("_round", 0),
            densify_kept=sum(k for k, _ in made),
            relax_calls=cnt.get("relax_network", 0),
            relax_s=acc.get("relax_network", 0.0),
            snapshot_s=acc.get("snapshot", 0.0),
            round_s=acc.get("_round", 0.0),
            restores=cnt.get("restore", 0),
        )
    bench.finish()


if __name__ == "__main__":
    main()
