"""Fidelity suite: do grow (Ijiri et al. 2008) and synth (Davison et al. 2018) continue
their exemplar? (issue 12)

The twelve exemplars of ``examples/fidelity/make.py`` (hexagonal lattice, noisy rows,
two-colour bricks, oriented scales, irregular stones, two sizes, clusters, three sizes
1:2:4, rings, stripes, sparse elements with voids, sticks) each fill a rectangle
``--scale`` times the exemplar's frame on each side (default 3.5: about 12x its area) by

- ``grow:fixed`` and, where orientation matters (lattices, scales, rings, sticks),
  ``grow:rotate``: ``strew.grow.grow(exemplar, region=..., mode=..., rng=seed)``;
- ``synth``: ``strew.synth.synthesize(exemplar, region, rng=seed)``;
- the baseline, ``copy``: the exemplar tiled over the same region (no method at all).
  Lattice, brick, scale, ring and cluster exemplars are one period of their texture, so
  their copies tile seamlessly and must pass; the others show seams where frames meet.

Each output is measured with ``strew.metrics.fidelity`` against its exemplar. The table
has one row per exemplar x method (x seed): the verdict, then for each metric family the
worst ``value/tolerance`` (a star marks a failure), and the seconds the method took. With
``--detail`` every metric is printed. Failures are expected today: this table is what
issues 13 (synth) and 14 (grow) must turn green. The JSON (every metric's value,
tolerance, exemplar and result statistics, the worst window) goes to
``benchmarks/results/fidelity.json``, and a contact sheet (exemplar, outputs with their
local fidelity maps) to ``docs/fidelity.png`` (full runs only; ``--sheet PATH`` for any).

    python benchmarks/fidelity.py [--quick] [--only NAME[,NAME]] [--method grow|synth|copy]
                                  [--seeds 1-5] [--scale 3.5] [--variant N] [--detail] [--sheet PATH]

``--variant N`` draws every exemplar from seed N instead of the default (seed 0), so that
a fix can be checked on exemplars nobody tuned on.

``--quick``: scale 2.5 (about 6x the area: a fast check, below the 10x of the full table), no
``grow:rotate``, no Eq. 5, no sheet, and without the rows of ``QUICK_SKIP`` (named when
skipped).
"""

from __future__ import annotations

import math
import sys
import time
from pathlib import Path
from typing import Any

import numpy as np
from _runner import Bench, parse_args

from strew import Arrangement, Region
from strew.arrangement import concat
from strew.metrics import fidelity

ROOT = Path(__file__).resolve().parents[1]
ROTATE = ("hex_lattice", "rows_noisy", "bricks", "scales", "rings", "sticks")
# rows quick mode leaves out, and why (the full table keeps them)
QUICK_SKIP = {("sticks", "synth"): "synth takes about 40 s on sticks at this size (run --only sticks --method synth)"}
FAMILIES = ("fraction", "density", "g", "nn", "regularity", "orientation", "empty_circle", "eq5")


def _suite() -> Any:
    from _runner import fidelity_suite

    return fidelity_suite()


def _seeds(text: str) -> list[int]:
    out: list[int] = []
    for part in text.split(","):
        if "-" in part:
            a, b = part.split("-")
            out.extend(range(int(a), int(b) + 1))
        else:
            out.append(int(part))
    return out


def tiled(ex: Arrangement, region: Region) -> Arrangement:
    """The exemplar repeated frame by frame over ``region``'s bounding box."""
    x0, y0, x1, y1 = ex.region.bounds
    w, h = x1 - x0, y1 - y0
    rx0, ry0, rx1, ry1 = region.bounds
    parts = []
    for i in range(int(math.ceil((rx1 - rx0) / w))):
        for j in range(int(math.ceil((ry1 - ry0) / h))):
            parts.append(Arrangement(ex.shapes, ex.kind, ex.x - x0 + rx0 + i * w, ex.y - y0 + ry0 + j * h, ex.rotation, ex.scale, columns=ex.columns))
    out = concat(parts)
    return out.select(region.contains(out.xy)).replace(region=region)


def run(method: str, ex: Arrangement, region: Region, seed: int) -> Arrangement:
    if method == "copy":
        return tiled(ex, region)
    if method.startswith("grow"):
        from strew.grow import grow

        return grow(ex, region=region, mode=method.split(":")[1], rng=seed)
    from strew.synth import synthesize

    return synthesize(ex, region, rng=seed)


def cell(report: Any, family: str) -> str:
    worst = None
    for name, m in report.metrics.items():
        if name.split("[")[0].split(".")[0] != family or not m.applicable:
            continue
        ratio = m.value / m.tolerance if m.tolerance > 0 else (math.inf if m.value > 0 else 0.0)
        if worst is None or ratio > worst[0]:
            worst = (ratio, m)
    if worst is None:
        return "-"
    m = worst[1]
    return f"{m.value:.3g}/{m.tolerance:.3g}{'' if m.passed else '*'}"


def contact_sheet(rows: list[tuple[str, Arrangement, list[tuple[str, Arrangement, Any]]]], path: Path) -> None:
    import io

    import matplotlib

    matplotlib.use("Agg", force=False)
    from matplotlib.figure import Figure

    from strew._fidelity import draw_arrangement, draw_local_map
    from strew.io import atomic_write

    cols = 1 + max(len(r[2]) for r in rows)
    fig = Figure(figsize=(3.0 * cols, 3.2 * len(rows) + 0.4), dpi=80)
    fig.suptitle("exemplar, then each output under its local fidelity map: window score 0 (green) .. 2 (red), above 1 fails; red box: worst window", fontsize=9)
    for i, (name, ex, outs) in enumerate(rows):
        ax = fig.add_subplot(len(rows), cols, i * cols + 1)
        draw_arrangement(ax, ex, title=f"{name}: exemplar")
        for j, (method, out, rep) in enumerate(outs):
            ax = fig.add_subplot(len(rows), cols, i * cols + 2 + j)
            verdict = "faithful" if rep.faithful else f"{len(rep.failures)} fail"
            draw_local_map(ax, rep, out, title=f"{method}: {verdict}", colorbar=False)
    fig.tight_layout(rect=(0, 0, 1, 1 - 0.4 / (3.2 * len(rows) + 0.4)), h_pad=1.2)
    buf = io.BytesIO()
    fig.savefig(buf, format="png")
    data = buf.getvalue()
    try:  # a 256-colour palette keeps the committed sheet small (Pillow: the test extra)
        from PIL import Image

        img = Image.open(io.BytesIO(data)).convert("RGB").quantize(colors=256, method=Image.Quantize.MEDIANCUT)
        small = io.BytesIO()
        img.save(small, format="PNG", optimize=True)
        data = small.getvalue()
    except ImportError:
        pass
    atomic_write(path, data)
    print(f"contact sheet written to {path}")


def main() -> int:
    def extra(p: Any) -> None:
        p.add_argument("--only", default=None, help="exemplar names, comma-separated")
        p.add_argument("--method", default=None, choices=["grow", "synth", "copy"], help="one method only (grow: fixed and rotate)")
        p.add_argument("--seeds", default="1", help="seeds, e.g. 1-5 or 1,3")
        p.add_argument("--scale", type=float, default=None, help="region side / exemplar frame side (default 3.5; quick 2.5)")
        p.add_argument("--variant", type=int, default=None, help="draw each exemplar with this seed (a variant nobody tuned on) instead of the default")
        p.add_argument("--detail", action="store_true", help="print every metric")
        p.add_argument("--sheet", default=None, help="contact sheet PNG (full runs write docs/fidelity.png)")

    args = parse_args(__doc__.splitlines()[0], extra)
    suite = _suite()
    names = list(suite.NAMES) if not args.only else [n.strip() for n in args.only.split(",")]
    unknown = [n for n in names if n not in suite.NAMES]
    if unknown:
        print(f"unknown exemplar(s): {', '.join(unknown)}; use {', '.join(suite.NAMES)}", file=sys.stderr)
        return 2
    scale = args.scale if args.scale is not None else (2.5 if args.quick else 3.5)
    seeds = _seeds(args.seeds)
    eq5 = not args.quick
    # a partial run (some exemplars, seeds, one method, a variant) must not overwrite the
    # committed figures of the full suite: it writes fidelity-partial.json unless told
    partial = bool(args.quick or args.only or args.method or args.variant is not None)
    json_path = args.json or (str(Path(__file__).parent / "results" / "fidelity-partial.json") if partial else None)
    bench = Bench("fidelity", f"fidelity of grow and synth to their exemplar, region {scale:g}x the frame's side", baseline="copy: the exemplar tiled", json_path=json_path)
    sheet_rows = []
    totals: dict[str, list[int]] = {}
    t_all = time.perf_counter()
    for name in names:
        ex = suite.make_exemplar(name, rng=args.variant)
        x0, y0, x1, y1 = ex.region.bounds
        region = Region.rectangle(scale * (x1 - x0), scale * (y1 - y0))
        methods = ["copy", "grow:fixed"] + (["grow:rotate"] if name in ROTATE and not args.quick else []) + ["synth"]
        if args.method:
            methods = [m for m in methods if m.split(":")[0] == args.method]
        outs = []
        for method in methods:
            why = QUICK_SKIP.get((name, method.split(":")[0])) if args.quick else None
            if why:
                print(f"  {name:13s} {method:12s} skipped in quick mode: {why}", flush=True)
                bench.row(name, method=method, verdict="skipped", report={"skipped": why})
                continue
            for seed in seeds if method != "copy" else seeds[:1]:
                t0 = time.perf_counter()
                out = run(method, ex, region, seed)
                dt = time.perf_counter() - t0
                rep = fidelity(ex, out, eq5=eq5)
                row: dict[str, Any] = {"method": method, "seed": seed, "n": len(out), "verdict": "pass" if rep.faithful else f"FAIL {len(rep.failures)}"}
                for fam in FAMILIES:
                    if fam == "eq5" and not eq5:
                        continue
                    row[fam] = cell(rep, fam)
                row["s"] = round(dt, 2)
                bench.row(name, **row)
                bench.rows[-1]["report"] = rep.to_dict() | {"local": {"worst": rep.local["worst"]}}
                totals.setdefault(method, [0, 0])
                totals[method][0] += int(rep.faithful)
                totals[method][1] += 1
                if args.detail:
                    print(f"\n{name} / {method} / seed {seed}: {'faithful' if rep.faithful else 'not faithful'}")
                    for r in rep.table():
                        print("   " + "  ".join(f"{c:>14s}" if k else f"{c:<26s}" for k, c in enumerate(r)))
                if seed == seeds[0]:
                    outs.append((method, out, rep))
                print(f"  {name:13s} {method:12s} seed {seed}: {row['verdict']:7s} ({len(out)} elements, {dt:.1f} s)", flush=True)
        sheet_rows.append((name, ex, [o for o in outs if o[0] != "copy"]))
    speed = _speed(suite, repeat=1 if args.quick else 3)
    # the reports are long: the table shows the cells, the JSON keeps everything
    reports = [r.pop("report") for r in bench.rows]
    print()
    print(bench.table())
    for r, rep in zip(bench.rows, reports):
        r["report"] = rep
    summary = ", ".join(f"{m} {p}/{n} faithful" for m, (p, n) in totals.items())
    print(f"\n{summary}; cells: worst value/tolerance of the family, * = fails; total {time.perf_counter() - t_all:.0f} s")
    print(f"speed: fidelity on {speed['n']} elements {speed['full_s']:.2f} s (target < 2 s; without Eq. 5 and the local map {speed['core_s']:.2f} s, ratio {speed['full_s'] / speed['core_s']:.2f}; median of {speed['repeat']})")
    bench.rows.append({"case": "summary", **{m: f"{p}/{n}" for m, (p, n) in totals.items()}})
    bench.rows.append({"case": "speed", **speed})
    import json

    bench.json_path.parent.mkdir(parents=True, exist_ok=True)
    bench.json_path.write_text(json.dumps({"benchmark": bench.name, "title": bench.title, "baseline": bench.baseline, "scale": scale, "seeds": seeds, "eq5": eq5, "rows": bench.rows}, indent=1, default=_jsonable) + "\n")
    print(f"figures written to {bench.json_path}")
    # the committed sheet (docs/fidelity.png) is the full table's; a partial run writes one only when asked
    full = not (args.quick or args.only or args.method or args.variant is not None)
    if sheet_rows and any(r[2] for r in sheet_rows) and (args.sheet or full):
        contact_sheet(sheet_rows, Path(args.sheet) if args.sheet else ROOT / "docs" / "fidelity.png")
    return 0


def _speed(suite: Any, repeat: int) -> dict[str, Any]:
    """Median seconds of fidelity() on about 10,000 elements (the clusters exemplar tiled
    10 x 10), in full and without Eq. 5 and the local map (the baseline)."""
    from _runner import median_time

    ex = suite.make_exemplar("clusters")
    x0, y0, x1, y1 = ex.region.bounds
    big = tiled(ex, Region.rectangle(10 * (x1 - x0), 10 * (y1 - y0)))
    full, _ = median_time(lambda: fidelity(ex, big), repeat=repeat)
    core, _ = median_time(lambda: fidelity(ex, big, eq5=False, local=False), repeat=repeat)
    return {"n": len(big), "full_s": round(full, 3), "core_s": round(core, 3), "repeat": repeat}


def _jsonable(v: Any) -> Any:
    if isinstance(v, np.generic):
        return v.item()
    if isinstance(v, np.ndarray):
        return v.tolist()
    raise TypeError(type(v).__name__)


if __name__ == "__main__":
    sys.exit(main())
