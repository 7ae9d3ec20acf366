"""Scaling of ornament's largest-empty-circle engine (issue 19.6): time against element count.

Grows ``dots`` (at min_radius 1) and ``flowers`` in squares of increasing side, each over
about 1k-10k and 2k-20k elements (the
raster's cell stays the same, so the raster grows with the panel), prints n, CPU seconds,
milliseconds per element, and per pattern the exponent fitted to log CPU time against
log n. Target: at most 1.15 over a 10x range of n. CPU time, not wall time: the machine
is shared.

``--runs N`` measures every case N times (each run fits its own exponent; the median
exponent and the median time per size are reported). ``--baseline SRC`` measures the
code under ``SRC`` (a ``src`` folder, e.g. of ``git worktree add /tmp/wt <commit>``) in
the same run, alternating with the current code case by case, in a subprocess, and
prints the ratios. ``--cases`` picks cases by name (comma separated).

Run: ``python benchmarks/ornament_scaling.py [--quick] [--runs 3] [--baseline /tmp/wt/src]``.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from _runner import Bench, parse_args  # noqa: E402


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


def measure(case: str, sides: list[float]) -> list[tuple[int, float, int, int]]:
    """(n, CPU seconds, failures, resolution) for each side, in this process."""
    from strew import Region
    from strew.ornament import grow_elements, load_pattern

    pat = case.split()[0]
    mr = CASES[case][0]
    out = []
    for s in sides:
        # cells of half the minimum radius at every size (the default resolution is at
        # least 256 cells, finer in small panels)
        res = int(round(s / (0.5 * (mr or load_pattern(pat).min_radius))))
        t0 = time.process_time()
        orn = grow_elements(pat, Region.rectangle(s, s), rng=0, min_radius=mr, resolution=res)
        out.append((len(orn.elements), time.process_time() - t0, int(orn.stats["failures"]), int(orn.stats["resolution"])))
    return out


def warm() -> None:
    """Compile (or load) every kernel first: dots grow without failures, flowers with."""
    from strew import Region
    from strew.ornament import grow_elements

    grow_elements("dots", Region.rectangle(20, 20), rng=0)
    grow_elements("flowers", Region.rectangle(40, 40), rng=0)


def child() -> None:
    """``--child CASE SIDE...``: measure in this process (the baseline's code) and print JSON."""
    i = sys.argv.index("--child")
    case, sides = sys.argv[i + 1], [float(x) for x in sys.argv[i + 2 :]]
    warm()
    print(json.dumps(measure(case, sides)))


def main() -> None:
    if "--child" in sys.argv:
        child()
        return

    def extra(p):  # type: ignore[no-untyped-def]
        p.add_argument("--runs", type=int, default=1, help="times each case is measured (median exponent reported)")
        p.add_argument("--baseline", default=None, help="a src folder of older code, measured in the same run")
        p.add_argument("--cases", default=None, help="comma-separated case names (default: all)")

    args = parse_args(__doc__.splitlines()[0], extra)
    warm()
    base = f"code under {args.baseline}" if args.baseline else "exponent target 1.15"
    bench = Bench("ornament_scaling", "growth in squares of growing side: CPU time vs n", baseline=base, json_path=args.json)
    names = [c.strip() for c in args.cases.split(",")] if args.cases else list(CASES)
    for case in names:
        full, quick = CASES[case][1], CASES[case][2]
        sides = quick if args.quick else full
        if not sides:
            continue
        runs: dict[str, list] = {"new": [], "baseline": []}
        for r in range(max(1, args.runs)):
            runs["new"].append(measure(case, sides))
            if args.baseline:
                env = dict(os.environ, PYTHONPATH=str(Path(args.baseline).resolve()))
                cmd = [sys.executable, __file__, "--child", case, *map(str, sides)]
                o = subprocess.run(cmd, env=env, capture_output=True, text=True, check=True)
                runs["baseline"].append(json.loads(o.stdout.strip().splitlines()[-1]))
            for k in ("new", "baseline"):
                if runs[k]:
                    rr = runs[k][-1]
                    kk = float(np.polyfit(np.log([x[0] for x in rr]), np.log([x[1] for x in rr]), 1)[0])
                    desc = "  ".join(f"n {x[0]:6d} {1e3 * x[1] / x[0]:6.3f} ms/el" for x in rr)
                    print(f"{case:15s} run {r + 1} {k:8s} {desc}  exponent {kk:.3f}", flush=True)
        summary = {}
        for k, rs in runs.items():
            if not rs:
                continue
            a = np.array(rs, dtype=float)  # runs, sides, 4
            ns = a[0, :, 0]
            ts = np.median(a[:, :, 1], axis=0)
            ks = [float(np.polyfit(np.log(ns), np.log(a[r, :, 1]), 1)[0]) for r in range(len(rs))]
            summary[k] = (ts, ns, ks)
            for s, n, t, fl, res in zip(sides, ns, ts, a[0, :, 2], a[0, :, 3]):
                bench.row(f"{case} side {s:g} {k}", n=int(n), cpu_s=float(t), ms_per_el=1e3 * float(t) / n, failures=int(fl), resolution=int(res))
            bench.row(f"{case} fit {k}", exponent=float(np.median(ks)), exponents=ks, n_range=float(ns[-1] / ns[0]))
            print(
                f"{case}: {k}: fitted exponent (log CPU time vs log n, n {int(ns[0])}..{int(ns[-1])}, {ns[-1] / ns[0]:.1f}x): "
                f"median {np.median(ks):.3f} of {', '.join(f'{x:.3f}' for x in ks)}  (target <= 1.15); "
                f"median ms/el {', '.join(f'{1e3 * t / n:.3f}' for t, n in zip(ts, ns))}",
                flush=True,
            )
        if "baseline" in summary:
            tn, tb = summary["new"][0], summary["baseline"][0]
            print(f"{case}: CPU time new / baseline per size: {', '.join(f'{x:.2f}' for x in tn / tb)}", flush=True)
            bench.row(f"{case} ratio", ratios=[float(x) for x in tn / tb])
    bench.finish()


if __name__ == "__main__":
    main()
