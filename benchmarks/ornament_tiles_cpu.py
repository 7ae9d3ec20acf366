"""CPU per element of a tiled ornament world, this tree against a baseline tree (issue 19.4).

Each run is a fresh process (``PYTHONPATH`` set to the tree's ``src``) that makes
``strew.tiles.tiled("ornament", PATTERN, (W, W), tile_size=T, seed=S)`` in-process and
reports its CPU seconds (``time.process_time``) and elements; the two trees alternate,
``--repeat`` times each. Prints the medians and the ratio of CPU per element (this tree
over the baseline). Writes ``benchmarks/results/ornament_tiles_cpu.json``.

Run: ``python benchmarks/ornament_tiles_cpu.py --base /tmp/wt/src [--pattern flowers]
[--side 240] [--tile 120] [--repeat 2]``.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
CHILD = """
import json, sys, time
from strew.tiles import tiled
t0 = time.process_time()
a = tiled("ornament", sys.argv[1], (float(sys.argv[2]),) * 2, tile_size=float(sys.argv[3]), seed=int(sys.argv[4]))
print(json.dumps({"cpu": time.process_time() - t0, "n": len(a)}))
"""


def _run(src: str, args: argparse.Namespace) -> dict:
    env = {**os.environ, "PYTHONPATH": src}
    out = subprocess.run([sys.executable, "-c", CHILD, args.pattern, str(args.side), str(args.tile), str(args.seed)],
                         env=env, capture_output=True, text=True, check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--base", required="--quick" not in sys.argv, help="the baseline tree's src folder")
    ap.add_argument("--pattern", default="flowers")
    ap.add_argument("--side", type=float, default=240.0)
    ap.add_argument("--tile", type=float, default=120.0)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--repeat", type=int, default=2)
    ap.add_argument("--quick", action="store_true", help="run_all.py's check: skips without --base")
    args = ap.parse_args()
    if args.base is None:  # --quick without --base
        print("ornament_tiles_cpu: skipped: it times this tree against a baseline tree's src folder (--base PATH), which has no default")
        sys.exit(3)  # _runner.SKIPPED
    here = str(HERE.parent / "src")
    runs: dict[str, list[dict]] = {"base": [], "new": []}
    for _ in range(args.repeat):
        for name, src in (("base", args.base), ("new", here)):
            r = _run(src, args)
            runs[name].append(r)
            print(f"  {name}: {r['n']:,} el, {r['cpu']:.1f} CPU s, {1e6 * r['cpu'] / r['n']:.0f} us/el", flush=True)
    med = {k: statistics.median(r["cpu"] / r["n"] for r in v) for k, v in runs.items()}
    n = {k: v[0]["n"] for k, v in runs.items()}
    ratio = med["new"] / med["base"]
    print(f"{args.pattern} {args.side:g}^2 tiles {args.tile:g}: CPU per element new/base {ratio:.3f} "
          f"(medians {1e6 * med['new']:.0f} / {1e6 * med['base']:.0f} us/el); elements {n['new']:,} / {n['base']:,}")
    out = HERE / "results" / "ornament_tiles_cpu.json"
    out.parent.mkdir(exist_ok=True)
    out.write_text(json.dumps({"args": vars(args), "runs": runs, "median_cpu_per_element": med, "ratio": ratio}, indent=1))
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
