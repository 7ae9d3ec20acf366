"""Helper s31c: where clusters p4s22's output (synth, 3.5x) differs from its generator in count.

    PYTHONPATH=src python benchmarks/s31c_where.py [CLASS:LABEL] [SEEDS] [--draws N]

For the exemplar (one torus period), ``N`` generator draws at the output's size (same
parameters, other layout seeds) and synth's output at each seed: discs and dots per 10^4
area over the region shrunk by 2 cluster spacings ("inner") and the band outside it
("edge"); dots per disc (each dot to its nearest disc within 1.3 ring radii, else an
orphan); quantiles of the disc-disc nearest distance; and quantiles of the empty space
(distance from a grid of inner points to the nearest disc centre), in units of the
cluster spacing.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import numpy as np
import shapely
from scipy.spatial import cKDTree

import _variants
from _runner import fidelity_suite
from fresh17_rows import exemplar
from strew.metrics import fidelity


def stats(arr, sp, ring_r, periodic=False):
    kn = np.asarray(arr.kind_names)
    xy = np.asarray(arr.xy, float)
    x0, y0, x1, y1 = arr.region.bounds
    d, t = xy[kn == "disc"], xy[kn == "dot"]
    if periodic:
        box = np.array([x1 - x0, y1 - y0])
        td = cKDTree(d - [x0, y0], boxsize=box)
        nn = td.query(d - [x0, y0], 2)[0][:, 1]
        dd, j = td.query(t - [x0, y0])
        a = (x1 - x0) * (y1 - y0)
        res = dict(disc_in=len(d) / a * 1e4, dot_in=len(t) / a * 1e4, disc_edge=np.nan, dot_edge=np.nan)
        g = np.stack(np.meshgrid(np.linspace(x0, x1, 100, endpoint=False), np.linspace(y0, y1, 100, endpoint=False)), -1).reshape(-1, 2)
        es = td.query(g - [x0, y0])[0]
    else:
        m = 1.0 * sp
        inner = shapely.box(x0 + m, y0 + m, x1 - m, y1 - m)
        ind = shapely.contains_xy(inner, d[:, 0], d[:, 1])
        intt = shapely.contains_xy(inner, t[:, 0], t[:, 1])
        ai = inner.area
        ae = (x1 - x0) * (y1 - y0) - ai
        res = dict(disc_in=ind.sum() / ai * 1e4, dot_in=intt.sum() / ai * 1e4, disc_edge=(~ind).sum() / ae * 1e4, dot_edge=(~intt).sum() / ae * 1e4)
        td = cKDTree(d)
        nn = td.query(d[ind], 2)[0][:, 1]
        dd, j = td.query(t)
        g = np.stack(np.meshgrid(np.linspace(x0 + m, x1 - m, 300), np.linspace(y0 + m, y1 - m, 300)), -1).reshape(-1, 2)
        es = td.query(g)[0]
    own = dd <= 1.3 * ring_r
    per = np.bincount(j[own], minlength=len(d))
    res["orphans"] = float(np.mean(~own))
    res["dots_per_disc"] = float(per.mean())
    res["ring_hist"] = np.bincount(per, minlength=12)[:12].tolist()
    res["nn_q"] = np.round(np.quantile(nn, [0.05, 0.25, 0.5, 0.75, 0.95]) / sp, 3).tolist()
    res["empty_q"] = np.round(np.quantile(es, [0.5, 0.9, 0.99, 1.0]) / sp, 3).tolist()
    # discs that would still fit (greedy, on the grid) clearing every disc by the cluster spacing
    free = g[es >= sp]
    add = 0
    while len(free):
        add += 1
        free = free[np.hypot(*(free - free[0]).T) >= sp]
    res["room"] = add / len(g)
    return res


def show(tag, r):
    print(f"{tag}: disc in {r['disc_in']:.3f} edge {r['disc_edge']:.3f} | dot in {r['dot_in']:.3f} edge {r['dot_edge']:.3f} | "
          f"dots/disc {r['dots_per_disc']:.2f} orphans {r['orphans']:.3f} | disc nn q05..q95 {r['nn_q']} | empty q50,90,99 {r['empty_q']} | room {r['room']:.4f} | rings {r['ring_hist']}", flush=True)


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    spec = args[0] if args else "clusters:p4s22"
    seeds = _variants.ints(args[1]) if len(args) > 1 else [1, 2]
    draws = int(sys.argv[sys.argv.index("--draws") + 1]) if "--draws" in sys.argv else 2
    mk = fidelity_suite()
    cls, label = spec.split(":")
    ex = exemplar(mk, cls, label)
    p = dict(ex.params) if getattr(ex, "params", None) else {}
    i, _, v = label[1:].partition("s")
    sets = _variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, [])
    kw = dict(sets[int(i)])
    sp = kw.get("cluster_spacing", 56.0)
    ring_r = kw.get("large", 8.0) + kw.get("small", 3.0) + kw.get("ring_gap", 1.5)
    show("exemplar", stats(ex, sp, ring_r, periodic=True))
    size = 3.5 * 300.0
    for dr in range(draws):
        big = mk.make_exemplar(cls, rng=int(v) + 1000 * (dr + 1), **dict(kw, size=size))
        rep = fidelity(ex, big, eq5=False, local=False)
        show(f"generator {dr} {'pass' if rep.faithful else 'FAIL'} dens disc {rep.metrics['density[disc]'].value:.3f} dot {rep.metrics['density[dot]'].value:.3f}",
             stats(big, sp, ring_r))
    if "--no-synth" in sys.argv:
        return
    from synth_variants import run

    for seed in seeds:
        out, _ = run(ex, 3.5, seed, None)
        rep = fidelity(ex, out, eq5=False, local=False)
        show(f"synth seed {seed} {'pass' if rep.faithful else 'FAIL'} dens disc {rep.metrics['density[disc]'].value:.3f} dot {rep.metrics['density[dot]'].value:.3f}",
             stats(out, sp, ring_r))


if __name__ == "__main__":
    main()
