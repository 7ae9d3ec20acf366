"""Shared code of ``synth_variants.py`` and ``grow_variants.py``: a method on exemplars
nobody tuned on (issues 13 and 14, point 1).

Each case draws an exemplar with ``make_exemplar(name, rng=VARIANT, **variation)``
(``examples/fidelity/make.py``):

- ``v1``, ``v2`` ... the default parameters at other seeds (``--variants``);
- with ``--varied``, ``p0``, ``p1`` ... the parameter sets of ``VARIED`` then ``EDGE``
  below, each drawn at variant seeds 7 and 8 (``--varied-variants 9,10``: at other
  variant seeds, a held-out draw; labels ``p0s9``, ``p0s10`` ...; implies ``--varied``). ``VARIED`` holds the sets used before this
  audit (their labels and results stay comparable); ``EDGE`` pushes each class's knobs
  (size ratio, density, counts, spacing, noise, angle, cluster size) to the edges of what
  a user would plausibly draw, each still a valid exemplar of its class (checked: no two
  elements overlap, see ``exemplar_overlaps``).

The method fills a rectangle ``--scale`` times the frame's side for every seed and
``strew.metrics.fidelity`` (no Eq. 5, no local map) judges it. Printed: one line per run
(verdict, failing metrics as value/tolerance, CPU seconds), then the pass count per class
and in all, split into default variants / old varied sets / edge sets. JSON goes to
``benchmarks/results/<name>.json`` after every class; with ``--summary PATH`` a markdown
table per class (pass counts, failing metrics) is rewritten there after every class too.
"""

from __future__ import annotations

import json
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from _runner import Bench, fidelity_suite, parse_args

from strew import Arrangement
from strew.metrics import fidelity

__all__ = ["VARIED", "EDGE", "ints", "cases", "exemplar_overlaps", "audit"]

# other sizes, ratios, densities (drawn at variant seeds 7 and 8): none of these were
# used while changing synth (the sets before the audit; keep them, in this order)
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

# the audit's edge cases (issues 13/14 preamble: hidden exemplars of the same classes;
# vary sizes, ratios, densities, seeds). Defaults in brackets.
EDGE: dict[str, list[dict[str, Any]]] = {
    "hex_lattice": [
        dict(spacing=16.0, fill=0.96),  # tiles nearly touching [0.86]
        dict(spacing=10.0, fill=0.55, angle=0.5),  # sparse tiles, lattice turned 29 degrees
        dict(nx=6, ny=6),  # a small patch: 36 tiles [132]
    ],
    "rows_noisy": [
        dict(noise=0.1, tile=0.55),  # twice the noise [0.05], smaller tiles so they never touch
        dict(tile=0.85, noise=0.03, row_angle=0.4),  # tight tiles, rows turned 23 degrees
        dict(spacing=8.0, nx=22, ny=6),  # a long thin strip of rows
    ],
    "bricks": [
        dict(length=44.0, height=7.0, mortar=1.0),  # long thin bricks (6:1) [22 x 9]
        dict(length=12.0, height=10.0, mortar=3.0, noise=0.4),  # near-square bricks, wide mortar, noisier
        dict(rows=8, per_row=4),  # a small wall: 32 bricks
    ],
    "scales": [
        dict(row_angle=0.6),  # rows and scales turned 34 degrees
        dict(width=16.0, length=7.0, gap=2.5, noise=0.06),  # wide flat scales, wider gaps, noisier
        dict(rows=6, per_row=6),  # a small patch: 36 scales
    ],
    "stones": [
        dict(radius=9.0, spread=0.45, count=400),  # large, very mixed sizes, saturated dart throwing
        dict(radius=4.0, count=60, gap=4.0),  # sparse small stones
        dict(size=120.0, count=40),  # a small exemplar: about 40 stones
    ],
    "two_sizes": [
        dict(ratio=0.15, n_large=50, n_small=500),  # grit between stones (1:6.7)
        dict(ratio=0.6, n_large=40, n_small=120),  # close sizes (1:1.7)
        dict(ratio=0.35, n_large=120, n_small=35),  # pebbles a minority (about 0.45)
    ],
    "clusters": [
        dict(cluster_spacing=90.0, ring_gap=3.0, ring_min=6, ring_max=7),  # far apart, full rings
        dict(cluster_spacing=38.0, large=6.0, small=3.5, ring_min=3, ring_max=4),  # crowded small clusters
        dict(large=12.0, small=2.0, ring_gap=0.5, ring_min=7, ring_max=9, cluster_spacing=70.0),  # big discs, tight rings of grit
    ],
    "three_sizes": [
        dict(ratios=(1.0, 1.6, 2.6), counts=(150, 90, 40)),  # close sizes
        dict(small=2.0, ratios=(1.0, 3.0, 7.0), counts=(300, 30, 8)),  # wide range, few boulders
        dict(counts=(60, 60, 26)),  # small stones no longer the majority
    ],
    "rings": [
        dict(tiles=14, radius=20.0, hub=8.0, spacing=52.0),  # large rings of many tiles
        dict(tiles=6, radius=11.0, hub=4.0, spacing=32.0),  # small rings of six
        dict(noise=0.03, spacing=46.0),  # hubs off the lattice (3x the noise)
    ],
    "stripes": [
        dict(band=14.0, angle=0.0),  # narrow horizontal bands
        dict(band=45.0, angle=1.4, dot=2.5, bar=(12.0, 2.5)),  # wide near-vertical bands, long bars
        dict(count=500, gap=0.6),  # dense (gap 0.6) [2.2]
    ],
    "sparse_voids": [
        dict(spacing=48.0, apple=6.0),  # very sparse
        dict(spacing=18.0, apple=5.5, void=3.0, void_spacing=8.0),  # crowded apples, small voids
    ],
    "sticks": [
        dict(length=36.0, width=2.0, count=80),  # long thin sticks
        dict(length=12.0, width=3.5, count=250),  # short dense sticks
    ],
}


def ints(text: str) -> list[int]:
    """``"1-3,5"`` -> ``[1, 2, 3, 5]``; ``""`` -> ``[]``."""
    out: list[int] = []
    for part in text.split(","):
        if not part.strip():
            continue
        a, _, b = part.partition("-")
        out.extend(range(int(a), int(b or a) + 1))
    return out


# the variant seeds the VARIED and EDGE sets are drawn at; ``--varied-variants`` sets it
# (helper fresh17: a held-out draw nobody tuned on; labels keep the form p{set}s{seed})
VARIED_SEEDS: tuple[int, ...] = (7, 8)


def cases(name: str, variants: list[int], varied: bool) -> list[tuple[str, str, int, dict[str, Any]]]:
    """(label, set, variant seed, variation) of one class: ``set`` is default, varied or edge."""
    out: list[tuple[str, str, int, dict[str, Any]]] = [(f"v{v}", "default", v, {}) for v in variants]
    if varied:
        sets = [("varied", kw) for kw in VARIED.get(name, [])] + [("edge", kw) for kw in EDGE.get(name, [])]
        out += [(f"p{i}s{s}", tag, s, kw) for i, (tag, kw) in enumerate(sets) for s in VARIED_SEEDS]
    return out


def exemplar_overlaps(ex: Arrangement) -> int:
    """Pairs of the exemplar's elements that overlap (a valid exemplar has none)."""
    from strew.metrics import overlaps

    return len(overlaps(ex)[0])


def _metric_counts(rows: list[dict[str, Any]]) -> dict[str, list[Any]]:
    """metric -> [runs failing it, worst value/tolerance ratio, its text]."""
    out: dict[str, list[Any]] = {}
    for r in rows:
        for f in r["failures"]:
            key, _, vt = f.partition("=")
            v, _, t = vt.partition("/")
            ratio = float(v) / float(t) if float(t) else float("inf")
            if ratio != ratio:  # nan: the result has too few elements to measure
                ratio = float("inf")
            c = out.setdefault(key, [0, 0.0, ""])
            c[0] += 1
            if ratio > c[1]:
                c[1], c[2] = ratio, vt
    return out


def _write_summary(path: Path, key: str, title: str, rows: list[dict[str, Any]], done: bool) -> None:
    """Rewrite block ``key`` of ``path`` (markdown): per class, pass counts by set and the failing metrics."""
    lines = [f"### {title} ({'complete' if done else 'running'}, {time.strftime('%H:%M UTC', time.gmtime())})", ""]
    lines.append("| class | all | default v | varied (old) | edge (new) | failing metrics: runs, worst value/tol | failing cases |")
    lines.append("|---|---|---|---|---|---|---|")
    names = list(dict.fromkeys(r["case"] for r in rows))
    tot = [0, 0]
    for n in names:
        rs = [r for r in rows if r["case"] == n]

        def cnt(tag: str | None, rs: list[dict[str, Any]] = rs) -> str:
            sel = [r for r in rs if tag is None or r["set"] == tag]
            return f"{sum(r['faithful'] for r in sel)}/{len(sel)}" if sel else "-"

        tot[0] += sum(r["faithful"] for r in rs)
        tot[1] += len(rs)
        mc = _metric_counts(rs)
        metrics = ", ".join(f"{k}: {c[0]}, {c[2]}" for k, c in sorted(mc.items(), key=lambda kv: -kv[1][0]))
        failing = " ".join(sorted({r["variant"] for r in rs if not r["faithful"]}))
        lines.append(f"| {n} | {cnt(None)} | {cnt('default')} | {cnt('varied')} | {cnt('edge')} | {metrics or '-'} | {failing or '-'} |")
    lines.append(f"| **total** | **{tot[0]}/{tot[1]}** | | | | | |")
    # the table replaces its own block in the file; the rest (other tables, notes) stays
    start, end = f"<!-- {key} -->", f"<!-- /{key} -->"
    block = "\n".join([start, *lines, end])
    text = path.read_text() if path.exists() else ""
    if start in text and end in text:
        text = text[: text.index(start)] + block + text[text.index(end) + len(end) :]
    else:
        text = text.rstrip("\n") + ("\n\n" if text else "") + block + "\n"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)


def audit(
    bench_name: str | Callable[[Any], str],
    method: str | Callable[[Any], str],
    run: Callable[[Arrangement, float, int, Any], tuple[Arrangement, float]],
    doc: str,
    *,
    options: Callable[[Any], None] | None = None,
    default_skip: tuple[str, ...] = (),
) -> None:
    """The variant audit of one method.

    ``run(exemplar, scale, seed, args) -> (output, scale used)`` fills a rectangle
    ``scale`` times the exemplar frame's side (the method may enlarge it; it says by how
    much). ``options(parser)`` adds the method's own flags; ``bench_name`` and ``method``
    may be functions of the parsed ``args``. ``default_skip``: classes left out unless
    named by ``--only``.
    """

    def extra(p: Any) -> None:
        p.add_argument("--only", default=None, help=f"class names, comma-separated (default: all{' but ' + ', '.join(default_skip) if default_skip else ''})")
        p.add_argument("--variants", default="1-3", help="exemplar seeds at default parameters, e.g. 1-3 ('' for none)")
        p.add_argument("--seeds", default="1-2", help=f"{method} seeds")
        p.add_argument("--varied", action="store_true", help="also the VARIED and EDGE parameter sets (variant seeds 7, 8)")
        p.add_argument("--varied-variants", default=None, help="variant seeds the VARIED and EDGE sets are drawn at (default 7,8; implies --varied), e.g. 9,10 for a held-out draw")
        p.add_argument("--scale", type=float, default=3.5, help="region side / exemplar frame side")
        p.add_argument("--summary", default=None, help="markdown file whose block for this run is rewritten after every class (pass counts, failing metrics)")
        if options is not None:
            options(p)

    args = parse_args(doc.splitlines()[0], extra)
    global VARIED_SEEDS
    if args.varied_variants is not None:
        VARIED_SEEDS = tuple(ints(args.varied_variants))
        args.varied = True
    bench_name = bench_name(args) if callable(bench_name) else bench_name
    method = method(args) if callable(method) else method
    mk = fidelity_suite()
    names = [n for n in mk.NAMES if n not in default_skip] if not args.only else args.only.split(",")
    seeds = ints(args.seeds)
    variants = ints(args.variants)
    title = f"{method} on untuned variants, region {args.scale:g}x the frame's side"
    bench = Bench(bench_name, title, baseline="none: pass rate", json_path=args.json)
    tally: dict[str, list[int]] = {}

    def write(done: bool) -> None:
        rows = list(bench.rows)
        if done:
            total = [sum(t[0] for t in tally.values()), sum(t[1] for t in tally.values())]
            rows.append({"case": "summary", **{n: f"{p}/{m}" for n, (p, m) in tally.items()}, "total": f"{total[0]}/{total[1]}"})
        bench.json_path.parent.mkdir(parents=True, exist_ok=True)
        meta = {"variants": variants, "seeds": seeds, "varied": args.varied, "scale": args.scale, "complete": done}
        if args.varied_variants is not None:
            meta["varied_variants"] = list(VARIED_SEEDS)
        bench.json_path.write_text(json.dumps({"benchmark": bench.name, "title": bench.title, **meta, "rows": rows}, indent=1, default=str) + "\n")
        if args.summary:
            _write_summary(Path(args.summary), bench.json_path.stem, f"{bench_name}: {title}", bench.rows, done)

    for name in names:
        for label, tag, v, kw in cases(name, variants, args.varied):
            ex = mk.make_exemplar(name, rng=v, **kw)
            bad = exemplar_overlaps(ex)
            if bad:  # not a valid exemplar of its class: say so, judge it anyway
                print(f"  {name:13s} {label:6s} WARNING: {bad} overlapping pairs in the exemplar", flush=True)
            for seed in seeds:
                t0 = time.process_time()
                out, scale = run(ex, args.scale, seed, args)
                dt = time.process_time() - t0
                rep = fidelity(ex, out, eq5=False, local=False)
                fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
                tally.setdefault(name, [0, 0])
                tally[name][0] += int(rep.faithful)
                tally[name][1] += 1
                growth = len(out) / max(len(ex), 1)
                bench.rows.append({"case": name, "variant": label, "set": tag, "params": kw, "seed": seed, "n_exemplar": len(ex), "n": len(out), "x_count": round(growth, 1), "scale": round(scale, 3), "exemplar_overlaps": bad, "faithful": rep.faithful, "failures": fails, "cpu_s": round(dt, 2)})
                print(f"  {name:13s} {label:6s} seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} ({growth:.1f}x) {dt:.1f}s cpu {' '.join(fails)}", flush=True)
        write(False)
    total = [sum(t[0] for t in tally.values()), sum(t[1] for t in tally.values())]
    for tag in ("default", "varied", "edge"):
        sel = [r for r in bench.rows if r["set"] == tag]
        if sel:
            print(f"{tag}: " + ", ".join(f"{n} {sum(r['faithful'] for r in sel if r['case'] == n)}/{sum(r['case'] == n for r in sel)}" for n in dict.fromkeys(r["case"] for r in sel)))
    print("\n" + ", ".join(f"{n} {p}/{m}" for n, (p, m) in tally.items()))
    print(f"total {total[0]}/{total[1]} faithful")
    write(True)
    print(f"figures written to {bench.json_path}")
