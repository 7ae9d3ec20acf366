"""Tiled synth: the density of each kind across the tile borders, out to 6 spacings
(issue 19 point 4; ``worlds_strips.py`` prints the same profile to 3 spacings).

A world of ``--side`` (default 2640) in tiles of 440 (two exemplar frames), synth on a
fidelity-suite exemplar, for each seed; the centres by signed distance to the nearest
inner border, positive into the tile of the later phase (strew.tiles' 2 x 2 colouring),
in bins of half a spacing ``s`` (``s = 1 / sqrt(density)``), along the inner tiles'
part of each border (``tests/worlds/world_stats.signed_profile``). Each kind's count per bin over its mean in the
bins 4-6 s from the border on both sides; and the strips' density and kind-fraction
ratios (centres within 1, 2, 3 s of an inner border against the rest, as
``worlds_strips.py`` defines them, no intervals). ``--untiled``: the same on one
untiled run (the control). CPU time per element of the runs.

    python benchmarks/synth_front_profile.py [--exemplar two_sizes] [--seeds 1,2] [--untiled]

Writes ``benchmarks/results/synth_front_profile.json``.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))
sys.path.insert(0, str(HERE.parent / "tests" / "worlds"))

TILE = 440.0
REACH = 6.0


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--exemplar", default="two_sizes")
    ap.add_argument("--seeds", default="1,2")
    ap.add_argument("--side", type=float, default=2640.0)
    ap.add_argument("--untiled", action="store_true")
    ap.add_argument("--out", default=str(HERE / "results" / "synth_front_profile.json"))
    ap.add_argument("--quick", action="store_true", help="one seed, a 3 x 3-tile world (a check of the script)")
    args = ap.parse_args()
    if args.quick:
        args.seeds, args.side = args.seeds.split(",")[0], 3 * TILE
    import strew
    from strew.synth import synthesize
    from strew.tiles import tiled
    from strew_testing import fidelity_suite
    from world_stats import signed_profile, strip_units

    ex = fidelity_suite().make_exemplar(args.exemplar)
    side = args.side
    tot, cpu, nel, s, units = None, 0.0, 0, None, {1: [], 2: [], 3: []}
    for seed in (int(v) for v in args.seeds.split(",")):
        t0 = time.process_time()
        if args.untiled:
            arr = synthesize(ex, strew.Region.rectangle(side, side), rng=seed, measure=False)
        else:
            arr = tiled("synth", ex, (side, side), tile_size=TILE, seed=seed, measure=False)
        cpu += time.process_time() - t0
        nel += len(arr)
        s = s or 1.0 / np.sqrt(len(arr) / side**2)
        c = signed_profile(arr, (side, side), TILE, s, REACH)["counts"].astype(float)
        tot = c if tot is None else tot + c
        for m in units:
            units[m].append(strip_units(arr, (side, side), TILE, m * s, max(110.0, 3 * s)))
    far = np.concatenate([tot[:, :4], tot[:, -4:]], axis=1).mean(axis=1)
    rel = tot / far[:, None]
    names = ["all", *arr.kinds]
    mode = "untiled" if args.untiled else "tiled"
    print(f"{args.exemplar} {mode} seeds {args.seeds} side {side:g}: {nel} el, {cpu:.1f} CPU s, {cpu / nel * 1e3:.3f} ms/el, s {s:.2f}")
    edges = (np.arange(-2 * REACH, 2 * REACH) * 0.5).tolist()
    print("bin from (s):", " ".join(f"{v:5.1f}" for v in edges))
    for name, row, f in zip(names, rel, far):
        print(f"{name:8s}", " ".join(f"{v:5.2f}" for v in row), f"(far {f:.0f} a bin)")
    strips = {}
    for m, us in units.items():
        u = {f: np.concatenate([w[f] for w in us]) for f in us[0] if f != "kinds"}
        d = (u["strip"].sum() / u["strip_area"].sum()) / (u["inner"].sum() / u["inner_area"].sum())
        sk, ik = u["strip_kind"].sum(0), u["inner_kind"].sum(0)
        kinds = {n: float((a / sk.sum()) / (b / ik.sum())) for n, a, b in zip(arr.kinds, sk, ik)}
        strips[f"{m}s"] = {"density_ratio": float(d), "kind_fraction_ratio": kinds}
        print(f"strips +-{m}s: density {d:.3f}; kinds " + ", ".join(f"{n} {v:.3f}" for n, v in kinds.items()))
    out = Path(args.out)
    out.parent.mkdir(exist_ok=True)
    res = {"benchmark": "synth_front_profile", "command": " ".join(["python benchmarks/synth_front_profile.py", *sys.argv[1:]]),
           "exemplar": args.exemplar, "mode": mode, "elements": nel, "cpu_s": cpu, "spacing": float(s), "bin_from_s": edges,
           "relative_density": {n: row.tolist() for n, row in zip(names, rel)}, "strips": strips}
    out.write_text(json.dumps(res, indent=1) + "\n")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
