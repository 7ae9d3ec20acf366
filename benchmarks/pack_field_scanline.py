"""pack's field on the shared scanline (issue 15 point 5): CPU time and bytes against a base.

Runs ``benchmarks/pack.py``'s fill-gap cases (a)-(j) (seeds 1-3, CPU seconds summed over
the seeds) in fresh processes, alternating this tree's ``src`` and a base tree's
(``--base``, e.g. a ``git worktree`` of the commit before), ``--repeat`` passes each,
and prints the median CPU time per case and the ratio new / base. Each pass also hashes
every packing's coordinates, and the two trees' hashes must agree (the field only
proposes candidates, but a changed pixel would change which are drawn).

Figures of ``--base`` d7f7ef9 ``--repeat 9`` (2-core machine loaded by other jobs):
total CPU 0.962 s against 0.969 s, ratio 0.993; cases 0.979-1.04 (the largest, (g), is
a 15 ms case); every case's bytes equal.

Run: ``python benchmarks/pack_field_scanline.py --base /tmp/wt_base`` (``--quick``:
seed 1 only, 2 passes).
"""

from __future__ import annotations

import json
import os
import statistics
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from _runner import SKIPPED, Bench, parse_args  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]

CHILD = r'''
import hashlib, json, sys, time
from pathlib import Path
import shapely
from strew import Region, load_shapes
from strew.pack import pack
ex = Path(sys.argv[1]) / "examples" / "pack"
sh = Path(sys.argv[1]) / "examples" / "shapes"
seeds = json.loads(sys.argv[2])
region = Region.rectangle(600, 520)
l_shape = Region(shapely.Polygon([(0, 0), (400, 0), (400, 200), (200, 200), (200, 400), (0, 400)]))
c3 = {}
for n in ("concave", "tree", "elongated"):
    c3.update(load_shapes(sh / f"{n}.svg"))
fit = {"scale_choice": "fit"}
configs = [("(a) elongated", "leaf.json", region, {}), ("(b) concave", "hook.json", region, {"scale": (0.75, 0.75)}),
           ("(c) three kinds", "mix.json", region, {}), ("(d) trees 0.2-1.0", "trees.json", region, {"scale": (0.2, 1.0)}),
           ("(f) L concave3 0.25", c3, l_shape, {"scale": (0.25, 0.25)}), ("(g) L concave3 1", c3, l_shape, {"scale": (1.0, 1.0)}),
           ("(h) L concave3 .12-.24 cov", c3, l_shape, {"scale": (0.12, 0.24), **fit}),
           ("(i) stones 0.5-1 cov", "stones.json", region, {"scale": (0.5, 1.0), **fit}),
           ("(j) mix 0.5-1 cov", "mix.json", region, {"scale": (0.5, 1.0), **fit})]
pack(load_shapes(ex / "hook.json"), Region.rectangle(100, 100), rng=0)  # compile / load the kernels
out = {}
for lab, f, dom, kw in configs:
    shapes = load_shapes(ex / f) if isinstance(f, str) else f
    t, h = 0.0, hashlib.sha256()
    for seed in seeds:
        c0 = time.process_time()
        arr = pack(shapes, dom, rng=seed, **kw)
        t += time.process_time() - c0
        h.update(shapely.get_coordinates(arr.geometry).tobytes())
    out[lab] = [t, h.hexdigest()[:16]]
print(json.dumps(out))
'''


def _pass(src: Path, seeds: list[int]) -> dict:
    env = dict(os.environ, PYTHONPATH=str(src))
    res = subprocess.run([sys.executable, "-c", CHILD, str(ROOT), json.dumps(seeds)], env=env, check=True,
                         capture_output=True, text=True, timeout=900)
    return json.loads(res.stdout.strip().splitlines()[-1])


def main() -> None:
    args = parse_args(__doc__.splitlines()[0], lambda p: p.add_argument(
        "--base", required="--quick" not in sys.argv, help="root of a checkout of the code before (its src/ is timed as the base)"))
    if args.base is None:  # --quick without --base
        print("pack_field_scanline: skipped: it times this tree against a checkout of the code before (--base PATH), which has no default")
        sys.exit(SKIPPED)
    seeds = [1] if args.quick else [1, 2, 3]
    passes = 2 if args.quick else args.repeat
    base, new = [], []
    for _ in range(passes):
        base.append(_pass(Path(args.base) / "src", seeds))
        new.append(_pass(ROOT / "src", seeds))
    bench = Bench("pack_field_scanline", "pack fill-gap CPU time: field on the shared scanline vs base",
                  baseline=f"{args.base} (same run, alternating processes)", json_path=args.json)
    for case in base[0]:
        tb = statistics.median(p[case][0] for p in base)
        tn = statistics.median(p[case][0] for p in new)
        same = all(p[case][1] == base[0][case][1] for p in base + new)
        bench.row(case, base_cpu_s=tb, cpu_s=tn, ratio=tn / tb, same_bytes=same)
    tb = sum(statistics.median(p[c][0] for p in base) for c in base[0])
    tn = sum(statistics.median(p[c][0] for p in new) for c in base[0])
    print(f"total CPU {tn:.3f} s against {tb:.3f} s: ratio {tn / tb:.3f} (target <= 1.10)")
    bench.row("total", base_cpu_s=tb, cpu_s=tn, ratio=tn / tb)
    bench.finish()


if __name__ == "__main__":
    main()
