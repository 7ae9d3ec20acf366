"""Helper s26r: ring membership of synth's output on a rings row, against the exemplar and the oracle.

Per arrangement: hubs, tiles, tiles per hub; tiles whose nearest hub is off the ring radius
(|d - radius| > 2) split into near (< radius) and far; inner hubs (over 60 from the edge)
with k ring tiles (histogram of k); and the tiles' distance to the nearest hub, quantiles.

    PYTHONPATH=src python benchmarks/s26r_rings.py CLASS:LABEL 1-2 [--oracle]
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _variants
import numpy as np
from _runner import fidelity_suite
from fresh17_rows import exemplar
from scipy.spatial import cKDTree
from synth_variants import run

from strew.metrics import fidelity


def ring_stats(a, tag, radius):
    kn = np.asarray(a.kind_names)
    pos = np.asarray(a.xy)
    hub, tile = pos[kn == "hub"], pos[kn != "hub"]
    x0, y0, x1, y1 = a.region.bounds
    d, j = cKDTree(hub).query(tile)
    off = np.abs(d - radius) > 2
    innert = (tile[:, 0] > x0 + 30) & (tile[:, 0] < x1 - 30) & (tile[:, 1] > y0 + 30) & (tile[:, 1] < y1 - 30)
    inner = (hub[:, 0] > x0 + 60) & (hub[:, 0] < x1 - 60) & (hub[:, 1] > y0 + 60) & (hub[:, 1] < y1 - 60)
    k = np.bincount(j[~off], minlength=len(hub))[inner]
    hist = np.bincount(k)
    counts = {i: int(c) for i, c in enumerate(hist) if c}
    print(f"   {tag}: hubs {len(hub)} tiles {len(tile)} ({len(tile) / len(hub):.2f}/hub); off-ring tiles {off.sum()}"
          f" (inner {(off & innert).sum()}: near {(off & innert & (d < radius)).sum()}, far {(off & innert & (d > radius)).sum()})"
          f"; inner hubs {inner.sum()} ring-tile counts {counts}"
          f"; tile-hub d q01/q50/q99 {np.quantile(d, 0.01):.2f}/{np.median(d):.2f}/{np.quantile(d, 0.99):.2f}", flush=True)
    if (off & innert).any():
        print("      inner off-ring tile d:", np.round(np.sort(d[off & innert]), 1)[:30])
    return a


def main():
    spec, seeds = sys.argv[1], _variants.ints(sys.argv[2])
    mk = fidelity_suite()
    cls, label = spec.split(":")
    ex = exemplar(mk, cls, label)
    kw = (_variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, []))[int(label[1:].partition("s")[0])]
    radius = kw.get("radius", 10.0)
    ring_stats(ex, "exemplar", radius)
    if "--oracle" in sys.argv:
        from svar13i_oracle import big_params
        ring_stats(mk.make_exemplar(cls, rng=int(label.split("s")[-1]), **big_params(cls, kw, 3.5)), "oracle", radius)
    for seed in seeds:
        out, _ = run(ex, 3.5, seed, None)
        rep = fidelity(ex, out, eq5=False, local=False)
        g = rep.metrics.get("g[tile,hub]")
        print(f"  synth {spec} seed {seed}: {'pass' if rep.faithful else 'FAIL'} g[tile,hub] {g.value:.3f}/{g.tolerance:.3f}", flush=True)
        ring_stats(out, f"seed {seed}", radius)


if __name__ == "__main__":
    main()
