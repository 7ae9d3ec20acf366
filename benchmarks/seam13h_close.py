"""Helper seam13h diagnostic (issue 13 point 2): what ``_grow.owed_here`` does on the
three sizes variants, close sizes (p2: ratios 1 : 1.6 : 2.6) against the default.

For each exemplar variant and seed, synth at ``--scale`` (3.5, as synth_variants.py)
with the rule as it is and with ``--set`` constants; printed per run: nn[small>small]
value/tolerance, the counts per kind, how many copies the rule marked owed (of large
copies tested), how many small stones they displaced, and the deciles of the output's
small>small nearest-neighbour distance against the exemplar's.

    python benchmarks/seam13h_close.py [--cases three_sizes:p2s7,three_sizes:p2s8]
        [--seeds 1-6] [--set NAME=VALUE ...] [--json PATH]
"""
import argparse
import json
import os
import sys
import time

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _variants import EDGE, VARIED, ints  # noqa: E402
from _runner import fidelity_suite  # noqa: E402

import strew.synth._grow as G  # noqa: E402
from strew import Region  # noqa: E402
from strew.metrics import fidelity  # noqa: E402
from strew.synth import synthesize  # noqa: E402


def variant(name, label):
    if label.startswith("v"):
        return int(label[1:]), {}
    i, s = label[1:].split("s")
    sets = list(VARIED.get(name, [])) + list(EDGE.get(name, []))
    return int(s), sets[int(i)]


def nn_deciles(xy):
    if len(xy) < 3:
        return np.full(9, np.nan)
    d = cKDTree(xy).query(xy, k=2)[0][:, 1]
    return np.quantile(d, np.linspace(0.1, 0.9, 9))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--cases", default="three_sizes:p2s7,three_sizes:p2s8")
    p.add_argument("--seeds", default="1-6")
    p.add_argument("--scale", type=float, default=3.5)
    p.add_argument("--set", action="append", default=[])
    p.add_argument("--json", default=None)
    a = p.parse_args()
    for kv in a.set:
        k, v = kv.split("=")
        setattr(G, k, type(getattr(G, k))(float(v)) if not isinstance(getattr(G, k), int) else int(v))
    mk = fidelity_suite()
    stats = dict(tested=0, owed=0, evicted=np.zeros(8, int))
    real_owed, real_evict = G.owed_here, G._evict

    def owed(state, pts, src):
        r = real_owed(state, pts, src)
        top = state.prep.size_class[src] == state.prep.size_class.max()
        stats["tested"] += int(top.sum())
        stats["owed"] += int(r.sum())
        return r

    def evict(state, new, *, voids):
        before = np.bincount(state.prep.size_class[state.src[: state.n]], minlength=8)
        real_evict(state, new, voids=voids)
        after = np.bincount(state.prep.size_class[state.src[: state.n]], minlength=8)
        stats["evicted"] += np.maximum(before - after, 0)

    G.owed_here, G._evict = owed, evict
    rows = []
    for case in a.cases.split(","):
        name, label = case.split(":")
        v, kw = variant(name, label)
        ex = mk.make_exemplar(name, rng=v, **kw)
        kinds = list(ex.kinds)
        si = kinds.index("small")
        exd = nn_deciles(ex.xy[np.asarray(ex.kind) == si])
        vals = []
        for seed in ints(a.seeds):
            stats.update(tested=0, owed=0, evicted=np.zeros(8, int))
            x0, y0, x1, y1 = ex.region.bounds
            region = Region.rectangle(a.scale * (x1 - x0), a.scale * (y1 - y0))
            t0 = time.process_time()
            out = synthesize(ex, region, rng=seed, measure=False)
            dt = time.process_time() - t0
            rep = fidelity(ex, out, eq5=False, local=False)
            m = rep.metrics["nn[small>small]"]
            k = np.asarray(out.kind)
            cnt = np.bincount(k, minlength=len(kinds)).tolist()
            od = nn_deciles(out.xy[k == si])
            vals.append(m.value)
            row = dict(case=case, seed=seed, nn_ss=m.value, tol=m.tolerance, faithful=bool(rep.faithful),
                       fails=[f"{n}={x.value:.3g}/{x.tolerance:.3g}" for n, x in rep.metrics.items() if x.applicable and not x.passed],
                       counts=cnt, tested=stats["tested"], owed=stats["owed"], evicted=stats["evicted"][:3].tolist(),
                       deciles_ratio=(od / exd).round(3).tolist(), cpu=dt)
            rows.append(row)
            print(f"{case} s{seed}: nn[s>s] {m.value:.4f}/{m.tolerance:.4f} {'ok' if rep.faithful else 'FAIL ' + ' '.join(row['fails'])} counts {cnt} "
                  f"owed {row['owed']}/{row['tested']} evicted {row['evicted']} dec out/ex {np.round(od / exd, 3).tolist()} cpu {dt:.1f}", flush=True)
        print(f"{case}: nn[small>small] mean {np.mean(vals):.4f}", flush=True)
    if a.json:
        with open(a.json, "w") as f:
            json.dump(dict(sets=a.set, rows=rows), f, indent=1, default=str)


if __name__ == "__main__":
    main()
