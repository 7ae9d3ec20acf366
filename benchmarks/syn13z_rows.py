"""diag: python diag.py class:i:v:seeds[:a:b] ... -> verdict, failing metrics, nn[a>b] signed decile error/s, counts per kind away from frame."""
import sys
import time

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
import shapely
from grow_variants import _harder_suite
from scipy.spatial import cKDTree
from synth_variants import _harder, run

from strew.metrics import fidelity


def nnq(arr, a, b):
    xy = np.asarray(arr.xy); kn = np.asarray(arr.kind_names)
    g = arr.region.geometry
    pa = xy[kn == a]; pb = xy[kn == b]
    k = 2 if a == b else 1
    d = cKDTree(pb).query(pa, k=k)[0]
    d = d[:, 1] if a == b else d
    edge = shapely.distance(g.boundary, shapely.points(pa))
    d = d[d <= edge]
    return np.quantile(d, np.arange(1, 10) / 10)

def counts(arr, margin):
    g = arr.region.geometry.buffer(-margin)
    xy = np.asarray(arr.xy); kn = np.asarray(arr.kind_names)
    ins = shapely.contains_xy(g, xy[:, 0], xy[:, 1])
    return {k: round(float(np.sum(ins & (kn == k)) / g.area * 1e4), 2) for k in sorted(set(kn))}

for spec in (sys.argv[1:] if __name__ == '__main__' else []):
    p = spec.split(":")
    name, i, v, seeds = p[0], int(p[1]), int(p[2]), p[3]
    ab = p[4:6] if len(p) > 4 else None
    ex = _harder_suite().make_exemplar(name, rng=v, **_harder()[name][i])
    for seed in [int(x) for x in seeds.split(",")]:
        t0 = time.process_time()
        out, _ = run(ex, 3.5, seed, None)
        dt = time.process_time() - t0
        rep = fidelity(ex, out, eq5=False, local=False)
        fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
        extra = ""
        if ab:
            key = f"nn[{ab[0]}>{ab[1]}]"; m = rep.metrics[key]
            e = nnq(ex, *ab); o = nnq(out, *ab)
            extra = f" {key}={m.value:.4f}/{m.tolerance:.4f} dec(out-ex)/s {np.round((o - e) / rep.s, 2)}"
        dk = {k: (round(m.value, 3), round(m.tolerance, 3)) for k, m in rep.metrics.items() if k.startswith("density")}
        print(f"{name} h{i}s{v} seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} cpu {dt:.1f} {' '.join(fails)}{extra} dens {dk} per1e4 ex {counts(ex, 0)} out {counts(out, 20)}", flush=True)
