"""Helper s31w (issue 13 point 2): prototype of a source-spread preference in synth's growth,
measured at 50x without touching src. Within the ratio test's passing candidates of a seed
(§5.1), the one whose exemplar position lies furthest against the local mean exemplar
position of the copies already around the seed goes first (costs swapped with the best
one, so the ratio test's bound and passing set do not change), where that local mean
strays more than ``--tau`` half-sides from the exemplar's centre. Counters k-coherence's
walk (growth toward -y copies the exemplar's lower part: s31w_source_bias.py).

    PYTHONPATH=src python benchmarks/s31w_spread_proto.py NAME SEEDS [--tau 0.1] [--radius 0.5] [--off]
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _runner import fidelity_suite

import strew.synth._grow as G
from strew import Region
from strew.metrics import fidelity
from strew.synth import synthesize

A = argparse.Namespace()


def _prefer_spread(state, seeds, cands, costs, slack, c) -> None:
    prep = state.prep
    if len(seeds) == 0 or costs.shape[1] < 2 or state.fixed.any():
        return
    lo = np.array([d.bounds[:2] for d in prep.domains])
    hi = np.array([d.bounds[2:] for d in prep.domains])
    cen, half = 0.5 * (lo + hi), 0.5 * (hi - lo)
    srcx = prep.source[state.src[seeds]]
    side = np.sqrt(np.prod(hi - lo, axis=1))
    n = state.n
    u = (prep.pos[state.src[:n]] - cen[prep.source[state.src[:n]]]) / half[prep.source[state.src[:n]]]
    tree = cKDTree(state.pos[:n])
    lists = tree.query_ball_point(state.pos[seeds], A.radius * side[srcx])
    sub = np.arange(len(seeds))
    cs, cd, fin, _d0, okc = G._ratio_test(costs, cands, sub, slack, c)
    for i, lst in enumerate(lists):
        if okc[i].sum() < 2 or len(lst) < 10:
            continue
        same = np.asarray(lst)[prep.source[state.src[np.asarray(lst)]] == srcx[i]]
        if len(same) < 10:
            continue
        m = u[same].mean(axis=0)
        if np.hypot(*m) <= A.tau:
            continue
        ok = np.flatnonzero(okc[i])
        v = (prep.pos[cd[i, ok]] - cen[srcx[i]]) / half[srcx[i]]
        pick = ok[np.argmin(v @ m)]
        best = int(np.argmin(np.where(fin[i], cs[i], np.inf)))
        if pick != best:
            costs[i, pick], costs[i, best] = costs[i, best], costs[i, pick]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("name")
    ap.add_argument("seeds")
    ap.add_argument("--tau", type=float, default=0.1)
    ap.add_argument("--radius", type=float, default=0.5)
    ap.add_argument("--scale", type=float, default=7.07)
    ap.add_argument("--off", action="store_true")
    a = ap.parse_args()
    A.__dict__.update(vars(a))
    if not a.off:
        orig = G._prefer_balanced

        def both(state, seeds, cands, costs, slack, c):
            orig(state, seeds, cands, costs, slack, c)
            _prefer_spread(state, seeds, cands, costs, slack, c)

        G._prefer_balanced = both
    ex = fidelity_suite().make_exemplar(a.name)
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(a.scale * (x1 - x0), a.scale * (y1 - y0))
    for s in [int(t) for t in a.seeds.split(",")]:
        out = synthesize(ex, region, rng=s, measure=False)
        rep = fidelity(ex, out, region, eq5=False)
        S = np.asarray(rep.local["score"], float)
        bad = [(i, j, round(float(v), 3), rep.local["worst_metric"][i][j]) for (i, j), v in np.ndenumerate(S) if np.isfinite(v) and v > 1.0]
        nm = np.asarray(out.kind_names)
        c = out.xy.mean(0)
        grad = []
        for k in np.unique(nm):
            p = out.xy[nm == k]
            d = cKDTree(p).query(p, k=2)[0][:, 1]
            lo_ = p[:, 1] < c[1]
            grad.append(f"{k} y lo/hi {np.median(d[lo_]):.2f}/{np.median(d[~lo_]):.2f}")
        print(f"{a.name} s{s} {'off' if a.off else 'spread'} n={len(out)} global {'pass' if rep.faithful else 'FAIL ' + ','.join(rep.failures)} worst {np.nanmax(S):.3f} failing {len(bad)} {bad} | {'; '.join(grad)}", flush=True)


if __name__ == "__main__":
    main()
