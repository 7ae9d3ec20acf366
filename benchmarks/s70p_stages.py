"""Helper s70p: per synth stage, visible elements of each kind in the whole output and the
raw (uncorrected) nearest-pebble deciles of pebbles inside the inner frame (units: output
elements' own positions, no border correction), on a --varied two_sizes row.

    PYTHONPATH=src:benchmarks python benchmarks/s70p_stages.py two_sizes:p4s43 1-3 [--skip NAME]
"""
import sys

import numpy as np
import shapely
from scipy.spatial import cKDTree

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from _runner import fidelity_suite
from synth_variants import run

import strew.synth._displace as DP
import strew.synth._farmix as FM
import strew.synth._grow as G
import strew.synth._pebbles as PB
import strew.synth._shell as SH
import strew.synth._swap as SW
import strew.synth._thin as TH
from strew.metrics import fidelity

LOG = []
args = sys.argv[1:]
SKIP = args[args.index("--skip") + 1] if "--skip" in args else None


def snap(state):
    prep = state.prep
    vis = np.flatnonzero(~prep.void[state.src])
    k = prep.skind[state.src[vis]]
    p = state.pos[vis]
    inner = state.region.geometry.buffer(-2.0 * float(prep.rc.max()))
    ins = shapely.contains_xy(inner, p[:, 0], p[:, 1])
    peb = p[k == 1]
    d = cKDTree(peb).query(peb[shapely.contains_xy(inner, peb[:, 0], peb[:, 1])], k=2)[0][:, 1] if len(peb) > 2 else np.array([np.nan])
    return np.bincount(k, minlength=2), np.quantile(d, [0.1, 0.3, 0.5, 0.7, 0.9])


def wrap(mod, name):
    f = getattr(mod, name)

    def g(state, *a, **k):
        if name == "_complete_anchor_rings":
            LOG.append(("growth", snap(state)))
        r = None if name == SKIP else f(state, *a, **k)
        LOG.append((name, snap(state)))
        return r

    setattr(mod, name, g)


for mod, names in ((G, ["_complete_anchor_rings", "fill_room", "fill_holes", "fill_hub_rooms"]),
                   (DP, ["fill_displaced"]), (SH, ["fill_beside_largest", "fill_beside_far_small"]),
                   (FM, ["trade_far_small", "trade_far_top"]), (PB, ["fill_partners"]), (SW, ["fill_swapped"]),
                   (TH, ["thin_small", "thin_orphans", "thin_crowded", "thin_edge_strays"])):
    for n in names:
        if hasattr(mod, n):
            wrap(mod, n)
np.set_printoptions(precision=2, suppress=True, linewidth=220)
mk = fidelity_suite()
cls, label = args[0].split(":")
i, _, v = label[1:].partition("s")
kw = (_variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, []))[int(i)]
ex = mk.make_exemplar(cls, rng=int(v), **kw)
print(f"== {args[0]} kinds {ex.kinds} skip {SKIP}")
for seed in _variants.ints(args[1]):
    LOG.clear()
    out, _ = run(ex, 3.5, seed, None)
    rep = fidelity(ex, out, eq5=False, local=False)
    print(f" seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} nn[pebble>pebble] {rep.metrics['nn[pebble>pebble]'].value:.3f}")
    for lab, (c, q) in LOG:
        print(f"   {lab:22s} counts {c} pebble nn q10..q90 {q}")
    sys.stdout.flush()
