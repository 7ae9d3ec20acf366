"""Helper seam17 (issue 13 point 2): the 50x worst-window audit for EVERY class of the
fidelity suite, synth against the exemplar's own generator drawn at 50x (the oracle).

Synth fills a region 7.07 x the frame's side (50x the area), as ``benchmarks/synth.py
--seams`` does (``synthesize(ex, region, rng=seed, measure=False)``, then
``fidelity(ex, out, region, eq5=False)``), and every failing window of the local map is
listed (row, column, metric, score, on the map's edge or not). The oracle is a fresh draw
of the class's generator at about 50x the exemplar's area: ``seam13m_oracle50``'s framed
draw with the exemplar's outlines for stones, two_sizes and three_sizes (other seeds draw
other outlines there), ``fidelity_calibration.larger`` for the others (generator seed 0 is
the exemplar's own seed with a larger frame; other seeds where they keep the outlines),
with ``make._dart`` replaced by ``seam13m_oracle50._fast_dart`` (the same darts, a k-d
tree for clearance) where it is not periodic. A window that fails for synth is a synth
failure only where the generator's own draws fail that window test clearly less often.

    python benchmarks/seam17_all50.py [--names hex_lattice,...] [--seeds 1,2]
        [--oracle-seeds 0,11] [--oracle-names three_sizes,...] [--json F]

``--oracle-names`` defaults to the classes with a failing synth window in this run.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path
from typing import Any

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import fidelity_calibration as FC
import seam13m_oracle50 as O
from _runner import SKIPPED, fidelity_suite

from strew import Region
from strew.metrics import fidelity

OUTLINED = ("stones", "two_sizes", "three_sizes")
_orig_dart = FC.suite._dart


def _dart(*a: Any, periodic: bool = False, **kw: Any) -> Any:
    return _orig_dart(*a, periodic=True, **kw) if periodic else O._fast_dart(*a, **kw)


FC.suite._dart = _dart


def failing(rep: Any) -> tuple[list[dict[str, Any]], int, float, str | None]:
    S = np.asarray(rep.local["score"], float)
    W = np.asarray(rep.local["worst_metric"], dtype=object)
    nr, nc = S.shape if S.ndim == 2 else (0, 0)
    rows = [dict(i=int(i), j=int(j), score=round(float(s), 4), metric=str(W[i, j]), edge=bool(i in (0, nr - 1) or j in (0, nc - 1)))
            for (i, j), s in np.ndenumerate(S) if np.isfinite(s) and s > 1.0]
    fin = S[np.isfinite(S)]
    w = rep.local["worst"] or {}
    return rows, int(fin.size), float(w.get("score", float("nan"))), w.get("metric")


def synth_row(mk: Any, name: str, seed: int, scale: float) -> dict[str, Any]:
    from strew.synth import synthesize

    ex = mk.make_exemplar(name)
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(scale * (x1 - x0), scale * (y1 - y0))
    t0 = time.perf_counter()
    out = synthesize(ex, region, rng=seed, measure=False)
    dt = time.perf_counter() - t0
    rep = fidelity(ex, out, region, eq5=False)
    fails, n, worst, wm = failing(rep)
    return dict(source="synth", name=name, seed=seed, n=len(out), windows=n, failing=len(fails), worst=round(worst, 4), worst_metric=wm,
                faithful=bool(rep.faithful), global_failures=list(rep.failures), fails=fails, synth_s=round(dt, 1))


def oracle_row(name: str, seed: int, outlines: dict[str, list[np.ndarray]]) -> dict[str, Any] | None:
    ex = FC.suite.make_exemplar(name)
    t0 = time.process_time()
    if name in OUTLINED:
        if name not in outlines:
            outlines[name] = O._outlines(name)
        arr, region, _ = O.oracle(name, seed, 50.0, "framed", 2.0, outlines[name])
        rep = fidelity(ex, arr, region, eq5=False)
    else:
        if seed != 0 and not FC.same_outlines(name, seed):
            return None
        arr = FC.larger(name, seed, 50.0)
        rep = fidelity(ex, arr, eq5=False)
    fails, n, worst, wm = failing(rep)
    return dict(source="generator", name=name, seed=seed, n=len(arr), windows=n, failing=len(fails), worst=round(worst, 4), worst_metric=wm,
                faithful=bool(rep.faithful), global_failures=list(rep.failures), fails=fails, cpu_s=round(time.process_time() - t0, 1))


def show(r: dict[str, Any]) -> None:
    desc = " ".join(f"({f['i']},{f['j']}){f['metric']}={f['score']:.3f}{'@edge' if f['edge'] else ''}" for f in r["fails"])
    print(f"{r['source']:9s} {r['name']:12s} s{r['seed']:<3d} n={r['n']:6d} failing {r['failing']:2d}/{r['windows']} worst {r['worst']:.3f} {r['worst_metric']} "
          f"global {'pass' if r['faithful'] else 'FAIL ' + ','.join(r['global_failures'])}  {desc}", flush=True)


def main() -> None:
    if "--quick" in sys.argv[1:]:
        print("seam17_all50: skipped: 50x canvases (minutes)")
        sys.exit(SKIPPED)
    mk = fidelity_suite()
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--names", default=",".join(mk.NAMES))
    ap.add_argument("--seeds", default="1,2")
    ap.add_argument("--oracle-seeds", default="0,11")
    ap.add_argument("--oracle-names", default=None, help="default: the classes with a failing synth window")
    ap.add_argument("--scale", type=float, default=7.07)
    ap.add_argument("--json", default="benchmarks/results/seam17_all50.json")
    a = ap.parse_args()
    seeds = [int(s) for s in a.seeds.split(",") if s]
    oseeds = [int(s) for s in a.oracle_seeds.split(",") if s]
    out: dict[str, Any] = {"benchmark": "seam17_all50", "scale": a.scale, "rows": []}

    def save() -> None:
        Path(a.json).write_text(json.dumps(out, indent=1))

    for name in a.names.split(","):
        for seed in seeds:
            r = synth_row(mk, name, seed, a.scale)
            out["rows"].append(r)
            show(r)
            save()
    onames = a.oracle_names.split(",") if a.oracle_names is not None else sorted({r["name"] for r in out["rows"] if r["failing"]})
    outlines: dict[str, list[np.ndarray]] = {}
    for name in [n for n in onames if n]:
        for seed in oseeds:
            r = oracle_row(name, seed, outlines)
            if r is None:
                continue
            out["rows"].append(r)
            show(r)
            save()
    for src in ("synth", "generator"):
        by: dict[str, list[int]] = {}
        for r in out["rows"]:
            if r["source"] == src:
                by.setdefault(r["name"], []).append(r["failing"])
        for name, v in by.items():
            print(f"{src:9s} {name:12s} failing windows per draw {v} = {sum(v)} over {len(v)} draws")
    save()
    print(f"figures written to {a.json}")


if __name__ == "__main__":
    main()
