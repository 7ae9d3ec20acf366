"""Helper g33s: sparse_voids rows with grow's void-hole pass off / its gate lowered (measurement only).

    PYTHONPATH=src python benchmarks/g33s_ab.py CLASS:LABEL SEEDS VARIANT

VARIANT: ``main`` (as is), ``off`` (the pass's limit patched to 0: it fills nothing), ``minN[xM]`` (monkeypatched
``strew.grow._void_holes.MIN_CIRCLES = N``: the pass fills holes with fewer whole exemplar
circles; ``xM``: the limit times M). Prints per seed the audit's verdict, density[apple] (result/exemplar), apples,
voids, apple pairs nearer than the exemplar's least apple distance, and the fill limit.
"""
import os
import sys
import math

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _runner import fidelity_suite  # noqa: E402
from fresh17_rows import exemplar  # noqa: E402

import strew.grow._void_holes as vh  # noqa: E402
from strew import Region  # noqa: E402
from strew.grow import grow  # noqa: E402
from strew.metrics import fidelity  # noqa: E402


def main():
    spec, seeds, var = sys.argv[1], [int(s) for s in sys.argv[2].split(",")], sys.argv[3]
    kw = {}
    mult = 1.0
    if var.startswith("min"):
        a, _, b = var[3:].partition("x")
        vh.MIN_CIRCLES = int(a)
        mult = float(b) if b else 1.0
    lims = []
    orig = vh.reference_visible_gap

    def spy(g):
        r = 0.0 if var == "off" else mult * orig(g)
        lims.append(r)
        return r

    vh.reference_visible_gap = spy
    import strew.grow._growth as gr

    made = []
    ofill = gr.fill_void_holes

    def fspy(g, *a, **k):
        n = ofill(g, *a, **k)
        made.append(n)
        return n

    gr.fill_void_holes = fspy
    ex = exemplar(fidelity_suite(), spec.split(":")[0], spec.split(":")[1])
    h = np.asarray(ex.columns["void"], bool) if "void" in ex.columns else np.zeros(len(ex), bool)
    dmin = float(cKDTree(ex.xy[~h]).query(ex.xy[~h], 2)[0][:, 1].min())
    for seed in seeds:
        x0, y0, x1, y1 = ex.region.bounds
        sc = 3.5
        for _ in range(2):  # as grow_variants.run
            out = grow(ex, region=Region.rectangle(sc * (x1 - x0), sc * (y1 - y0)), mode="fixed", rng=seed, **kw)
            if len(out) >= 10 * len(ex):
                break
            sc *= 1.05 * math.sqrt(10 * len(ex) / max(len(out), 1))
        nfill, made[:] = list(made), []
        rep = fidelity(ex, out, eq5=False, local=False)
        m = rep.metrics[f"density[{ex.kinds[0]}]"]
        e = rep.metrics["empty_circle"]
        ho = np.asarray(out.columns["void"], bool) if "void" in out.columns else np.zeros(len(out), bool)
        d = cKDTree(out.xy[~ho]).query(out.xy[~ho], 2)[0][:, 1]
        fails = [f"{k}={x.value:.3g}/{x.tolerance:.3g}" for k, x in rep.metrics.items() if x.applicable and not x.passed]
        print(f"  {spec} {var} seed {seed}: {'pass' if rep.faithful else 'FAIL'} density {m.value:.3f} ({m.result / m.exemplar if m.exemplar else math.nan:.3f}x) empty_circle {e.value:.3f} ({e.result / e.exemplar if e.exemplar else math.nan:.3f}x) apples {int((~ho).sum())} voids {int(ho.sum())} apples nearer than {dmin:.1f}: {int((d < dmin - 1e-6).sum())} fill lim {lims[-1] if lims else None} filled {nfill} {' '.join(fails)}", flush=True)


if __name__ == "__main__":
    main()
