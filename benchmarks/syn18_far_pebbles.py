"""Helper syn18 (issue 13 point 1): two_sizes h5s11's pebbles, synth against the generator's own big draw (the exemplar's
outlines): pebble-pebble nn deciles (/s, metric's border filter), and for pebbles whose nearest pebble is farther than the
exemplar's 90 % decile, how many stones touch them (within stone+pebble radius + 0.25 s) and their share.

    PYTHONPATH=TREE/src python benchmarks/syn18_far_pebbles.py [SEEDS]
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
import shapely
from grow_variants import _harder_suite
from scipy.spatial import cKDTree
from svar13i_oracle import big_params
from syn13z_rows import nnq
from synth_variants import _harder, run

from strew.metrics import fidelity

name, i, v = "two_sizes", 5, 11
kw = _harder()[name][i]
mk = _harder_suite()
ex = mk.make_exemplar(name, rng=v, **kw)
s = fidelity(ex, ex, eq5=False, local=False).s
q90 = nnq(ex, "pebble", "pebble")[-1]


def far(arr, label):
    xy = np.asarray(arr.xy); kn = np.asarray(arr.kind_names)
    pp, ps = xy[kn == "pebble"], xy[kn == "stone"]
    d = cKDTree(pp).query(pp, k=2)[0][:, 1]
    edge = shapely.distance(arr.region.geometry.boundary, shapely.points(pp))
    ok = d <= edge
    f = ok & (d > q90)
    ns = np.array([len(x) for x in cKDTree(ps).query_ball_point(pp, 1.6 * s)])
    print(f"{label}: pebbles {len(pp)} stones {len(ps)} per pebble {len(ps)/len(pp):.3f}; dec/s {np.round(nnq(arr, 'pebble', 'pebble') / s, 3)}; "
          f"far (> ex q90 {q90 / s:.3f} s) {f.sum()}/{ok.sum()} = {f.sum() / ok.sum():.3f}; stones within 1.6 s: far {ns[f].mean():.2f}, others {ns[ok & ~f].mean():.2f}", flush=True)


far(ex, "exemplar")
orig = mk._stone
sg = np.random.default_rng(v)
mk._stone = lambda g, *x, **y: orig(sg, *x, **y)
try:
    big = mk.make_exemplar(name, rng=v + 1000, **big_params(name, kw, 3.5))
finally:
    mk._stone = orig
far(big, "generator 3.5x")
for seed in map(int, (sys.argv[1] if len(sys.argv) > 1 else "1,2").split(",")):
    out, _ = run(ex, 3.5, seed, None)
    far(out, f"synth seed {seed}")
