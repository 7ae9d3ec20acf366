"""s46w: which part of s44w's (a) (_prepare._uncut_nn) moves a case.

S46W_OFF=eps,cover switches the eps / cover part off (raw nn there); S46W_KINDS=1,2
limits it to those kinds. ``fs3`` reruns test_synth_free_support's variant 3. The
figures in benchmarks/results/s46w_fs3_parts.txt were taken on s44w's ungated (a)
(before prepare applied it to one-size-class exemplars only); with the gate three
sizes never calls _uncut_nn, so fs3 gives the raw result whatever S46W_OFF says.
Usage: python benchmarks/s46w_parts.py [explain|fs3]
"""
from __future__ import annotations

import os
import sys

import numpy as np
import shapely
from scipy.spatial import cKDTree
from strew_testing import fidelity_suite

import strew.synth._prepare as P
from strew import Region
from strew.metrics import fidelity
from strew.synth import synthesize

OFF = set(filter(None, os.environ.get("S46W_OFF", "").split(",")))
KINDS = [int(x) for x in os.environ["S46W_KINDS"].split(",")] if os.environ.get("S46W_KINDS") else None
_orig = P._uncut_nn


def _patched(nn, depth, kind, upper=False, **kw):
    if (upper and "cover" in OFF) or (not upper and "eps" in OFF):
        return np.asarray(nn, float).copy()
    out = _orig(nn, depth, kind, upper=upper, **kw)
    if KINDS is not None:
        keep = ~np.isin(kind, KINDS)
        out[keep] = np.asarray(nn, float)[keep]
    return out


P._uncut_nn = _patched
suite = fidelity_suite()


def explain(name, rng):
    from strew.synth._api import as_selection
    ex = suite.make_exemplar(name, rng=rng) if rng is not None else suite.make_exemplar(name)
    prep = P.prepare(as_selection(ex), k=5)
    d, j = cKDTree(prep.pos).query(prep.pos, k=2)
    nn = d[:, 1]
    poly, _ = P.exemplar_domain(prep.pos, P._spacing(prep.pos))
    depth = shapely.distance(poly.exterior, shapely.points(prep.pos))
    cut = nn > depth
    up = _orig(nn, depth, prep.kind, upper=True)
    med = _orig(nn, depth, prep.kind)
    for k in np.unique(prep.kind):
        m = prep.kind == k
        ch = m & (up != nn)
        print(f"{name} rng={rng} kind {k}: n={m.sum()} r={prep.r[m].mean():.2f} cut={int((m & cut).sum())} changed={int(ch.sum())} "
              f"uncut max={nn[m & ~cut].max() if (m & ~cut).any() else float('nan'):.2f} med={np.median(nn[m & ~cut]) if (m & ~cut).any() else float('nan'):.2f}")
        for i in np.flatnonzero(ch):
            print(f"   e{i}: nn={nn[i]:.2f} depth={depth[i]:.2f} -> up {up[i]:.2f} med {med[i]:.2f}; nn partner kind {prep.kind[j[i,1]]} r={prep.r[j[i,1]]:.2f}")


def fs3(variant=3, seed=1):
    P.FREE_SUPPORT = 0.6
    ex = suite.make_exemplar("three_sizes", rng=variant)
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0))
    out = synthesize(ex, region, rng=seed, measure=False)
    rep = fidelity(ex, out, region, eq5=False)
    print("OFF", sorted(OFF), "KINDS", KINDS, "variant", variant, "seed", seed, "faithful", rep.faithful, rep.failures)


if __name__ == "__main__":
    what = sys.argv[1]
    if what == "explain":
        explain(sys.argv[2], int(sys.argv[3]) if len(sys.argv) > 3 else None)
    else:
        fs3(int(sys.argv[2]) if len(sys.argv) > 2 else 3)
