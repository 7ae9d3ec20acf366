"""Helper s42t: size-class shares of exemplar and synth output, whole against the judge's
counted interior (beyond the frame's wall reach, strew._fidelity._wall_reach).

    PYTHONPATH=src:benchmarks python benchmarks/s42t_shares.py three_sizes:h3s28:1 three_sizes:p4s27:1
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
import shapely
from fresh17_rows import exemplar
from _runner import fidelity_suite
from grow_variants import _harder_suite
from synth_variants import _harder, run

from strew._fidelity import _wall_reach
from strew.metrics import fidelity


def shares(arr):
    xy = np.asarray(arr.xy); kn = np.asarray(arr.kind_names)
    names = sorted(set(kn))
    kind = np.array([names.index(k) for k in kn])
    rad = np.asarray(arr.radii) if hasattr(arr, "radii") else None
    if rad is None:
        rad = np.array([shapely.minimum_bounding_radius(g) for g in arr.shapes])
    g = arr.region.geometry
    wr = _wall_reach(xy, kind, rad, g)
    edge = shapely.distance(g.boundary, shapely.points(xy))
    c = edge >= wr
    w = np.bincount(kind, minlength=len(names)) / len(kind)
    i = np.bincount(kind[c], minlength=len(names)) / max(c.sum(), 1)
    return names, w, i, wr, len(kind), int(c.sum())


for spec in sys.argv[1:]:
    cls, label, seeds = spec.split(":")
    if label.startswith("h"):
        i, _, v = label[1:].partition("s")
        ex = _harder_suite().make_exemplar(cls, rng=int(v), **_harder()[cls][int(i)])
    else:
        ex = exemplar(fidelity_suite(), cls, label)
    names, w, i_, wr, n, nc = shares(ex)
    print(f"{cls} {label} exemplar n={n} counted={nc} wall={wr:.1f} {names} whole {np.round(w, 4)} interior {np.round(i_, 4)}")
    for seed in [int(s) for s in seeds.split(",")]:
        out, _ = run(ex, 3.5, seed, None)
        rep = fidelity(ex, out, eq5=False, local=False)
        names, w, i_, wr, n, nc = shares(out)
        fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
        print(f"   seed {seed} {'pass' if rep.faithful else 'FAIL'} out n={n} wall={wr:.1f} whole {np.round(w, 4)} interior {np.round(i_, 4)} {' '.join(fails)}", flush=True)
