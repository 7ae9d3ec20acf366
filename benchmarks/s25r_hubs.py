"""Helper s25r: hub lattice of synth's output on a rings row against the exemplar and the oracle.

For each seed: pass/fail (judged as the audit, eq5 and local off), failing metrics, and the
inner hubs' (over 60 from the edge) nearest-hub distances: median of the 6 nearest, q01
and min of the nearest, plus tiles per hub and hubs/1e4.

    PYTHONPATH=src python benchmarks/s25r_hubs.py CLASS:LABEL 1-3 [--harder] [--oracle]

LABEL as ``fresh17_rows.py`` (p2s16) or ``h2s15`` with --harder (synth_variants HARDER sets).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _variants
import numpy as np
from scipy.spatial import cKDTree
from _runner import fidelity_suite
from fresh17_rows import exemplar
from synth_variants import run

from strew.metrics import fidelity


def hub_stats(a, tag):
    kn = np.asarray(a.kind_names)
    pos = np.asarray(a.xy)
    hub = pos[kn == "hub"]
    x0, y0, x1, y1 = a.region.bounds
    inner = (hub[:, 0] > x0 + 60) & (hub[:, 0] < x1 - 60) & (hub[:, 1] > y0 + 60) & (hub[:, 1] < y1 - 60)
    d, _ = cKDTree(hub).query(hub[inner], 7)
    area = (x1 - x0) * (y1 - y0)
    print(f"   {tag}: n {len(a)} hubs {len(hub)} ({1e4 * len(hub) / area:.3f}/1e4) tiles/hub {(kn != 'hub').sum() / len(hub):.2f}"
          f"  inner {inner.sum()}: 6nn median {np.median(d[:, 1:]):.2f} nn q01 {np.quantile(d[:, 1], 0.01):.2f}"
          f" q10 {np.quantile(d[:, 1], 0.1):.2f} min {d[:, 1].min():.2f}", flush=True)


def main():
    spec, seeds = sys.argv[1], _variants.ints(sys.argv[2])
    mk = fidelity_suite()
    cls, label = spec.split(":")
    if "--harder" in sys.argv:
        from synth_variants import _harder
        i, _, v = label[1:].partition("s")
        ex = mk.make_exemplar(cls, rng=int(v), **_harder()[cls][int(i)])
    else:
        ex = exemplar(mk, cls, label)
    hub_stats(ex, "exemplar")
    if "--oracle" in sys.argv and "--harder" not in sys.argv:
        from svar13i_oracle import big_params
        kw = (_variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, []))[int(label[1:].partition("s")[0])]
        hub_stats(mk.make_exemplar(cls, rng=int(label.split("s")[-1]), **big_params(cls, kw, 3.5)), "oracle")
    ok = 0
    for seed in seeds:
        out, _ = run(ex, 3.5, seed, None)
        rep = fidelity(ex, out, eq5=False, local=False)
        fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
        ok += int(rep.faithful)
        g = rep.metrics.get("g[tile,hub]")
        print(f"  synth {spec} seed {seed}: {'pass' if rep.faithful else 'FAIL'} g[tile,hub] {g.value:.3f}/{g.tolerance:.3f} {' '.join(fails)}", flush=True)
        hub_stats(out, f"seed {seed}")
    print(f"synth {spec} {ok}/{len(seeds)}")


if __name__ == "__main__":
    main()
