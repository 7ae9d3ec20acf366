"""Issue 14 point 1 (helper gsz14k): where grow's nearest-neighbour deciles depart from the
exemplar's on the harder audit's uneven-share rows. For each set (``--sets two_sizes:11,
three_sizes:1``; variant seeds 7, 8) and grow seed: the failing metrics and, for every
nn[a>b] failing or given by ``--pairs``, the nine deciles (in units of the exemplar's
median nn distance s) of the output against the exemplar, and kind counts.

    python benchmarks/gsz14k_diag.py --sets three_sizes:1,three_sizes:7 [--seeds 1-2] [--pairs large>medium]
"""

from __future__ import annotations

import argparse
import pickle
import time
from pathlib import Path

import numpy as np
from grow_variants import HARDER, _harder_suite

from strew import Region, _fidelity
from strew.grow import grow

_seen: list = []
_orig = _fidelity._discrepancies


def _spy(a, b, kinds, s, **kw):
    if not _seen:
        _seen.append((a, b, list(kinds), s))
    return _orig(a, b, kinds, s, **kw)


_fidelity._discrepancies = _spy


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--sets", default="three_sizes:1,three_sizes:7,three_sizes:9,three_sizes:10,three_sizes:12,two_sizes:11")
    ap.add_argument("--variants", default="7,8")
    ap.add_argument("--seeds", default="1-2")
    ap.add_argument("--pairs", default="")
    ap.add_argument("--save", default="")
    a = ap.parse_args()
    lo, _, hi = a.seeds.partition("-")
    seeds = range(int(lo), int(hi or lo) + 1)
    mk = _harder_suite()
    extra = [p for p in a.pairs.split(",") if p]
    for item in a.sets.split(","):
        name, i = item.split(":")
        kw = HARDER[name][int(i)]
        for v in (int(x) for x in a.variants.split(",")):
            ex = mk.make_exemplar(name, rng=v, **kw)
            x0, y0, x1, y1 = ex.region.bounds
            for seed in seeds:
                t = time.process_time()
                out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed)
                dt = time.process_time() - t
                _seen.clear()
                rep = _fidelity.fidelity(ex, out, eq5=False, local=False)
                res, exs, kinds, s = _seen[0]
                fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
                cnt_ex = {k: int(np.sum(ex.kind == ex.kinds.index(k))) for k in kinds}
                cnt_out = {k: int(np.sum(out.kind == out.kinds.index(k))) for k in kinds if k in out.kinds}
                print(f"{name} h{i}s{v} seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} cpu {dt:.1f}s {' '.join(fails)}")
                print(f"   counts ex {cnt_ex} out {cnt_out} (out/ex*{len(ex)}/{len(out)}: " + ", ".join(f"{k} {cnt_out.get(k, 0) / len(out) / (cnt_ex[k] / len(ex)):.2f}" for k in kinds) + ")")
                names = [f.split("=")[0] for f in fails if f.startswith("nn[")] + extra
                for nm in dict.fromkeys(names):
                    p, q = nm.strip("nn[]").split(">") if nm.startswith("nn[") else nm.split(">")
                    ip, iq = kinds.index(p), kinds.index(q)
                    e, o = exs.nn[ip, iq] / s, res.nn[ip, iq] / s
                    print(f"   nn[{p}>{q}] ex  " + " ".join(f"{x:5.2f}" for x in e))
                    print(f"   nn[{p}>{q}] out " + " ".join(f"{x:5.2f}" for x in o) + "   diff " + " ".join(f"{x:+5.2f}" for x in o - e))
                if a.save:
                    Path(a.save).mkdir(parents=True, exist_ok=True)
                    with open(Path(a.save) / f"{name}_h{i}s{v}_{seed}.pkl", "wb") as fh:
                        pickle.dump((ex, out), fh)


if __name__ == "__main__":
    main()
