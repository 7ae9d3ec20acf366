"""g63v: flow mode's cost against its element count (issue 14 point 5).

The hexagonal lattice grown in flow mode along a field turning 90 degrees across the
region, relaxation on, with the passes after the growth (``benchmarks/grow.py
--against``'s ``hexflow``), in regions W x 2W/3 spacings for each W of ``--widths``
(default 20, 36, 63: about 281, 900 and 2,980 elements, a 10.6x range), of this tree and
(``--against REV``) of the tree at git revision REV (extracted with ``git archive``),
each size in a fresh process, the trees taken in turn.

In each process the first growth is the smallest width's (W = the least of
``--widths``): it loads (or compiles) every numba kernel flow mode uses and is reported
apart as ``first``; the timed growth follows, warm. Printed per size: CPU seconds per
1,000 elements (the best of ``--repeat``), and over all sizes the exponent ``b`` of
``CPU s ~ n^b`` (least squares on the logs; 1.0 is linear) and, with ``--against``,
each size's CPU ratio this/REV and whether the two outputs' digests (positions and
outlines' WKB, as ``benchmarks/grow_hashes.py``) are equal. ``--profile`` runs cProfile around the timed growth
(one run, its CPU seconds not used for the figures) and prints the share of the growth
of each function in :data:`WATCH` at each size, so what grows faster than the count
shows up. The figures go to ``benchmarks/results/g63v_flow_scaling.json`` (``--json``).

The machine may be shared: compare only the ratios and exponents of one run.

Run: ``PYTHONPATH=src:benchmarks python benchmarks/g63v_flow_scaling.py [--against main]
[--widths 20,36,63] [--repeat 1] [--profile] [--src DIR]``.
"""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))

from _runner import Bench, parse_args  # noqa: E402

#: functions whose share of the growth ``--profile`` prints (cumulative time)
WATCH = (
    "advance", "relax_network", "_relax_once", "_band_passes", "insert_stretched", "reshape_shear",
    "close_holes", "densify", "_settle_steps", "_push_apart", "_resolve", "_undo_worse", "_undo_gaps",
    "_undo_circles", "_undo_turn", "_six_share", "_turns", "_far_points", "_six_sites", "_far_circles",
    "_far_circles_at", "triangulation", "_place_all", "_place", "placed", "turned_ring", "element_geometry",
    "regrow_sheared", "_regrow", "factorized",
    "_contact_lengths", "memo", "_key", "_delaunay_bonds", "fitted_moves", "saved_moves", "undo_moves",
    "overlapping_many", "snapshot", "restore", "place", "choose", "relax_window", "flow_respace",
    "close_gaps", "fill_holes", "settle", "_relax_around", "relax_positions",
)

CODE = r"""
import sys, time, json
import numpy as np
from strew import Region
from strew.grow import analyze, grow
from strew.grow._exemplars import hex_exemplar
ref = analyze(hex_exemplar())
W, W0, prof = float(sys.argv[1]), float(sys.argv[2]), sys.argv[3] == "1"
sp = ref.mean_edge
def field_of(w):
    def field(p):
        a = np.radians(90.0) * np.clip(np.asarray(p)[:, 0] / w, 0, 1)
        return np.c_[np.cos(a), np.sin(a)]
    return field
def one(W):
    w = W * sp
    return grow(ref, rng=1, relax=True, region=Region.rectangle(w, W * 2 / 3 * sp), mode="flow", flow=field_of(w))
c = time.process_time()
first = one(W0)
first_s = time.process_time() - c
shares = {}
if prof:
    import cProfile, pstats
    pr = cProfile.Profile()
    c = time.process_time()
    pr.enable()
    out = one(W)
    pr.disable()
    g = time.process_time() - c
    st = pstats.Stats(pr).stats
    total = max(v[3] for v in st.values())
    for (f, line, name), v in st.items():
        if "strew" in f or name == "factorized":
            key = name
            shares[key] = shares.get(key, 0.0) + v[3] / total
else:
    c = time.process_time()
    out = one(W)
    g = time.process_time() - c
import hashlib, shapely
h = hashlib.sha256()
h.update(np.ascontiguousarray(out.xy, dtype=float).tobytes())
h.update(b"".join(shapely.to_wkb(np.asarray(out.geometry))))
print(json.dumps({"cpu": g, "n": len(out), "first_cpu": first_s, "first_n": len(first), "shares": shares, "digest": h.hexdigest()[:16]}))
"""


def run(src: str, W: float, W0: float, prof: bool) -> dict:
    env = dict(os.environ, PYTHONPATH=src)
    out = subprocess.run([sys.executable, "-c", CODE, str(W), str(W0), "1" if prof else "0"], env=env, capture_output=True, text=True, check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def exponent(ns: list[int], cpus: list[float]) -> float:
    """The slope ``b`` of ``log cpu = a + b log n`` (least squares)."""
    x = [math.log(v) for v in ns]
    y = [math.log(v) for v in cpus]
    mx, my = sum(x) / len(x), sum(y) / len(y)
    return sum((a - mx) * (b - my) for a, b in zip(x, y)) / sum((a - mx) ** 2 for a in x)


def main() -> None:
    def extra(p):
        p.add_argument("--against", metavar="REV", default=None, help="also time the tree at git revision REV")
        p.add_argument("--widths", default="20,36,63", help="region widths in spacings (comma-separated)")
        p.add_argument("--profile", action="store_true", help="cProfile shares per size (one run, no timings)")
        p.add_argument("--src", default=None, help="the src folder timed as this tree (default: this checkout's)")

    args = parse_args(__doc__, extra)
    widths = [float(v) for v in args.widths.split(",")]
    W0 = min(widths)
    root = Path(__file__).resolve().parents[1]
    json_path = args.json or str(root / "benchmarks" / "results" / ("g63v_flow_scaling_profile.json" if args.profile else "g63v_flow_scaling.json"))
    with tempfile.TemporaryDirectory() as tmp:
        trees = {"this": str(Path(args.src).resolve() if args.src else root / "src")}
        if args.against:
            archive = subprocess.run(["git", "archive", args.against, "src"], cwd=root, capture_output=True, check=True).stdout
            subprocess.run(["tar", "-x", "-C", tmp], input=archive, check=True)
            trees[args.against] = str(Path(tmp) / "src")
        bench = Bench("g63v_flow_scaling", "flow mode (hexflow) CPU s per 1,000 elements against the count", baseline=args.against or "the smallest size", json_path=json_path)
        got: dict[str, dict[float, list[dict]]] = {k: {W: [] for W in widths} for k in trees}
        for W in widths:
            for _ in range(1 if args.profile else max(1, args.repeat)):
                for k, src in trees.items():
                    got[k][W].append(run(src, W, W0, args.profile))
                    r = got[k][W][-1]
                    print(f"  {k} W={W:g}: {r['n']} el, {r['cpu']:.2f} CPU s, digest {r['digest']}; first (W={W0:g}, {r['first_n']} el) {r['first_cpu']:.2f} CPU s", flush=True)
        best = {k: {W: min(got[k][W], key=lambda r: r["cpu"]) for W in widths} for k in trees}
        for k in trees:
            ns = [best[k][W]["n"] for W in widths]
            cpus = [best[k][W]["cpu"] for W in widths]
            for W, n, c in zip(widths, ns, cpus):
                row = dict(n=n, cpu_s=c, cpu_s_per_1000=1000.0 * c / n, el_per_cpu_s=n / c,
                           first_cpu_s=min(r["first_cpu"] for r in got[k][W]), all_cpu_s=[round(r["cpu"], 3) for r in got[k][W]],
                           digest=got[k][W][0]["digest"])
                if args.against and k == "this":
                    row["cpu_ratio"] = (c / n) / (best[args.against][W]["cpu"] / best[args.against][W]["n"])
                    row["same_digest"] = got[k][W][0]["digest"] == got[args.against][W][0]["digest"]
                bench.row(f"{k} W={W:g}", **row)
            bench.row(f"{k} exponent", exponent=exponent(ns, cpus), per_1000_growth=(cpus[-1] / ns[-1]) / (cpus[0] / ns[0]), n_growth=ns[-1] / ns[0])
        if args.profile:
            for k in trees:
                names = sorted(WATCH, key=lambda f: -best[k][widths[-1]]["shares"].get(f, 0.0))
                print(f"\nshares of the growth ({k}), by width {widths}:")
                for f in names:
                    s = [best[k][W]["shares"].get(f, 0.0) for W in widths]
                    if max(s) >= 0.005:
                        print(f"  {f:20s} " + "  ".join(f"{v:6.3f}" for v in s))
            with open(json_path.replace(".json", "_shares.json"), "w") as fh:
                json.dump({k: {str(W): best[k][W]["shares"] for W in widths} for k in trees}, fh, indent=1, sort_keys=True)
        bench.finish()


if __name__ == "__main__":
    main()
