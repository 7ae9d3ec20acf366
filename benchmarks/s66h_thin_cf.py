"""Helper s66h: counterfactual on main's output (ring cap off) for --harder clusters h4: drop ring dots at
random (rng seeded, rings of >= 7 dots only, never below 6) until dots per disc equals a target, and judge
again. Tells how much of empty_circle's rise under the ring cap comes from fewer ring dots alone (discs kept).

    PYTHONPATH=src:benchmarks python benchmarks/s66h_thin_cf.py VARIANT SEEDS TARGET[,TARGET...]
"""
import sys

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from grow_variants import _harder_suite
from synth_variants import _harder, run

import strew.synth._grow as G
from strew.metrics import fidelity

G.RING_CAP = False
v = int(sys.argv[1])
assert v <= 38
ex = _harder_suite().make_exemplar("clusters", rng=v, **_harder()["clusters"][4])
for seed in _variants.ints(sys.argv[2]):
    out, _ = run(ex, 3.5, seed, None)
    k = np.asarray(out.kind)
    xy = np.c_[out.x, out.y]
    rep = fidelity(ex, out, eq5=False, local=False)
    line = [f"h4s{v} seed {seed} main: n={len(out)} dots/disc {np.sum(k == 1) / np.sum(k == 0):.2f} empty_circle {rep.metrics['empty_circle'].value:.3f}/{rep.metrics['empty_circle'].tolerance:.3f} {'pass' if rep.faithful else 'FAIL'}"]
    di, do = np.flatnonzero(k == 0), np.flatnonzero(k == 1)
    d, j = cKDTree(xy[di]).query(xy[do])
    for tgt in (float(t) for t in sys.argv[3].split(",")):
        g = np.random.default_rng(seed)
        drop = max(0, round(len(do) - tgt * len(di)))
        per = np.bincount(j[d < 25], minlength=len(di))
        keep = np.ones(len(out), bool)
        cand = do[(d < 25) & (per[j] >= 7)]
        g.shuffle(cand)
        gone = 0
        for c in cand:
            if gone >= drop:
                break
            r = j[np.searchsorted(do, c)]
            if per[r] > 6:
                keep[c] = False
                per[r] -= 1
                gone += 1
        sub = type(out)(out.shapes, k[keep], out.x[keep], out.y[keep], rotation=np.asarray(out.rotation)[keep], scale=np.asarray(out.scale)[keep], region=out.region)
        r2 = fidelity(ex, sub, eq5=False, local=False)
        m = r2.metrics["empty_circle"]
        line.append(f"-> {tgt:.2f} dots/disc (dropped {gone}): empty_circle {m.value:.3f} {'pass' if r2.faithful else 'FAIL'}")
    print(" ".join(line), flush=True)
