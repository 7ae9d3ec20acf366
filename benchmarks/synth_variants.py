"""Issue 13 point 1 on exemplars nobody tuned on: synth on untuned variants of the
fidelity suite's classes.

Each case draws an exemplar with ``make_exemplar(name, rng=VARIANT, **variation)``
(``examples/fidelity/make.py``): the default parameters at other seeds (``--variants``),
and, with ``--varied``, other sizes, ratios, densities and counts (``VARIED`` below). Each
fills a rectangle ``--scale`` times the frame's side (default 3.5: about 12x the area, as
``benchmarks/fidelity.py``) for every seed, and ``strew.metrics.fidelity`` judges it.
Printed: one line per run (verdict, failing metrics as value/tolerance), then the pass
count per class and in all. There is no baseline method: the figure is the pass rate,
compared before/after a change by running this script on both.

    python benchmarks/synth_variants.py [--only NAME,...] [--variants 1-3] [--seeds 1-2]
                                        [--varied] [--scale 3.5]
"""

from __future__ import annotations

import time
from pathlib import Path
from typing import Any

from _runner import Bench, parse_args

from strew import Region
from strew.metrics import fidelity
from strew.synth import synthesize

ROOT = Path(__file__).resolve().parents[1]

# other sizes, ratios, densities (drawn at variant seeds 7 and 8): none of these were
# used while changing synth
VARIED: dict[str, list[dict[str, Any]]] = {
    "hex_lattice": [dict(spacing=9.0, fill=0.8)],
    "rows_noisy": [dict(spacing=14.0, noise=0.08)],
    "bricks": [dict(length=30.0, height=8.0)],
    "scales": [dict(width=10.0, length=12.0)],
    "stones": [dict(radius=5.0, spread=0.3, count=220)],
    "two_sizes": [dict(ratio=0.4, n_large=60, n_small=160), dict(ratio=0.25, n_small=300)],
    "clusters": [dict(cluster_spacing=48.0, ring_min=3, ring_max=5), dict(large=10.0, small=2.5, cluster_spacing=64.0)],
    "three_sizes": [dict(ratios=(1.0, 2.5, 5.0), counts=(140, 50, 18)), dict(counts=(220, 50, 26))],
    "rings": [dict(tiles=8, hub=6.0), dict(radius=12.0, spacing=34.0)],
    "stripes": [dict(band=22.0, angle=0.8)],
    "sparse_voids": [dict(spacing=24.0, apple=4.0)],
}


def _suite() -> Any:
    from _runner import fidelity_suite

    return fidelity_suite()


def _ints(text: str) -> list[int]:
    out: list[int] = []
    for part in text.split(","):
        a, _, b = part.partition("-")
        out.extend(range(int(a), int(b or a) + 1))
    return out


def main() -> None:
    def extra(p: Any) -> None:
        p.add_argument("--only", default=None, help="class names, comma-separated (default: all but sticks)")
        p.add_argument("--variants", default="1-3", help="exemplar seeds at default parameters, e.g. 1-3 ('' for none)")
        p.add_argument("--seeds", default="1-2", help="synth seeds")
        p.add_argument("--varied", action="store_true", help="also the VARIED parameter sets (variant seeds 7, 8)")
        p.add_argument("--scale", type=float, default=3.5, help="region side / exemplar frame side")

    args = parse_args(__doc__.splitlines()[0], extra)
    mk = _suite()
    names = [n for n in mk.NAMES if n != "sticks"] if not args.only else args.only.split(",")
    seeds = _ints(args.seeds)
    bench = Bench("synth_variants", f"synth on untuned variants, region {args.scale:g}x the frame's side", baseline="none: pass rate", json_path=args.json)
    tally: dict[str, list[int]] = {}
    for name in names:
        cases: list[tuple[str, int, dict]] = [(f"v{v}", v, {}) for v in (_ints(args.variants) if args.variants else [])]
        if args.varied:
            cases += [(f"p{i}s{s}", s, kw) for i, kw in enumerate(VARIED.get(name, [])) for s in (7, 8)]
        for label, v, kw in cases:
            ex = mk.make_exemplar(name, rng=v, **kw)
            x0, y0, x1, y1 = ex.region.bounds
            region = Region.rectangle(args.scale * (x1 - x0), args.scale * (y1 - y0))
            for seed in seeds:
                t0 = time.perf_counter()
                out = synthesize(ex, region, rng=seed, measure=False)
                dt = time.perf_counter() - t0
                rep = fidelity(ex, out, eq5=False, local=False)
                fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
                tally.setdefault(name, [0, 0])
                tally[name][0] += int(rep.faithful)
                tally[name][1] += 1
                bench.rows.append({"case": name, "variant": label, "seed": seed, "n": len(out), "faithful": rep.faithful, "failures": fails, "s": round(dt, 2)})
                print(f"  {name:13s} {label:6s} seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} {dt:.1f}s {' '.join(fails)}", flush=True)
    total = [sum(t[0] for t in tally.values()), sum(t[1] for t in tally.values())]
    print("\n" + ", ".join(f"{n} {p}/{m}" for n, (p, m) in tally.items()))
    print(f"total {total[0]}/{total[1]} faithful")
    bench.rows.append({"case": "summary", **{n: f"{p}/{m}" for n, (p, m) in tally.items()}, "total": f"{total[0]}/{total[1]}"})
    import json

    bench.json_path.parent.mkdir(parents=True, exist_ok=True)
    bench.json_path.write_text(json.dumps({"benchmark": bench.name, "title": bench.title, "rows": bench.rows}, indent=1, default=str) + "\n")


if __name__ == "__main__":
    main()
