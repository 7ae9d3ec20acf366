"""Helper g3e: how evenly the grown large stones spread, exemplar vs output (three_sizes rows).

    PYTHONPATH=src python benchmarks/g3e_measure.py three_sizes:suite:0,three_sizes:3:12 1-2 [param=value ...]

For each row and seed: the verdict (fidelity, eq5 and local off, as grw14y_rows.py), the
failures, the density per 1e4 of each kind (output count / region area vs exemplar count
/ frame area; then the same >= 1.5 s from the frame: interior), and deciles (10..90 %) in units of the exemplar's median nn distance s of
nn[large>large], nn[small>large], nn[medium>large] and of the empty-space function of the
large kind (distance from grid points of the interior to the nearest large stone),
exemplar (E) vs output (O). ``param=value`` overrides GrowParams fields (eval'd).
With G3E_SAVE=DIR each (exemplar, output) is pickled there.
"""
import os
import pickle
import sys

sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import numpy as np
from grow_variants import HARDER, _harder_suite
from scipy.spatial import cKDTree

from strew import Region
from strew.grow import grow
from strew.metrics import fidelity

Q = np.linspace(0.1, 0.9, 9)


def stats(arr, box, s):
    xy = np.c_[arr.x, arr.y]
    names = np.asarray(arr.kind_names)
    x0, y0, x1, y1 = box
    edge = np.minimum.reduce([xy[:, 0] - x0, x1 - xy[:, 0], xy[:, 1] - y0, y1 - xy[:, 1]])
    il = np.flatnonzero(names == "large")
    t = cKDTree(xy[il])
    out = {}
    for a in ("large", "medium", "small"):
        ia = np.flatnonzero(names == a)
        d, j = t.query(xy[ia], k=2)
        dd = np.where(il[j[:, 0]] == ia, d[:, 1], d[:, 0])
        ok = dd <= edge[ia]
        out[f"{a[0]}>l"] = np.quantile(dd[ok], Q) / s
    # empty space function of the large kind: grid points whose nearest large is nearer than the frame
    g = np.stack(np.meshgrid(np.linspace(x0, x1, 120), np.linspace(y0, y1, 120)), -1).reshape(-1, 2)
    ge = np.minimum.reduce([g[:, 0] - x0, x1 - g[:, 0], g[:, 1] - y0, y1 - g[:, 1]])
    d, _ = t.query(g)
    ok = d <= ge
    out["F_l"] = np.quantile(d[ok], Q) / s
    area = (x1 - x0) * (y1 - y0)
    out["dens"] = {k: 1e4 * float((names == k).sum()) / area for k in ("small", "medium", "large")}
    # the interior, >= 1.5 s from the frame (the exemplar's frame is small: a deeper margin
    # would leave too few elements there)
    m = 1.5 * s
    inner = edge >= m
    ia = (x1 - x0 - 2 * m) * (y1 - y0 - 2 * m)
    out["idens"] = {k: 1e4 * float(((names == k) & inner).sum()) / ia for k in ("small", "medium", "large")}
    return out


def main():
    mk = _harder_suite()
    a, _, b = sys.argv[2].partition("-")
    seeds = range(int(a), int(b or a) + 1)
    kw = {}
    for s in sys.argv[3:]:
        k, v = s.split("=", 1)
        kw[k] = eval(v)
    if kw:
        from dataclasses import replace

        import strew.grow._growth as G

        _init = G._Grower.__init__

        def _patched(self, ref, params, *a, **k):
            _init(self, ref, replace(params, **kw), *a, **k)

        G._Grower.__init__ = _patched
    for c in sys.argv[1].split(","):
        cls, i, v = c.split(":")
        ex = mk.make_exemplar(cls, rng=int(v)) if i == "suite" else mk.make_exemplar(cls, rng=int(v), **HARDER[cls][int(i)])
        x0, y0, x1, y1 = ex.region.bounds
        exy = np.c_[ex.x, ex.y]
        s = np.median(cKDTree(exy).query(exy, k=2)[0][:, 1])
        se = stats(ex, ex.region.bounds, s)
        ok = 0
        for seed in seeds:
            out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed)
            rep = fidelity(ex, out, eq5=False, local=False)
            if os.environ.get("G3E_SAVE"):
                with open(os.path.join(os.environ["G3E_SAVE"], f"{c.replace(':', '_')}_{seed}_{'_'.join(sys.argv[3:])}.pkl"), "wb") as f:
                    pickle.dump((ex, out), f)
            fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
            so = stats(out, (0, 0, 3.5 * (x1 - x0), 3.5 * (y1 - y0)), s)
            ok += int(rep.faithful)
            nn = rep.metrics.get("nn[small>large]")
            print(f"{c} s{seed}: {'pass' if rep.faithful else 'FAIL'} {fails} nn[s>l]={nn.value if nn else float('nan'):.3g} "
                  + " ".join(f"{k} {so['dens'][k]:.2f}/{se['dens'][k]:.2f}" for k in se["dens"])
                  + " | interior " + " ".join(f"{k[0]} {so['idens'][k]:.2f}/{se['idens'][k]:.2f}" for k in se["idens"]), flush=True)
            for key in ("l>l", "m>l", "s>l", "F_l"):
                print(f"   {key:4} E " + " ".join(f"{x:5.2f}" for x in se[key]))
                print(f"   {'':4} O " + " ".join(f"{x:5.2f}" for x in so[key]), flush=True)
        print(f"{c} {ok}/{len(seeds)} {kw}", flush=True)


if __name__ == "__main__":
    main()
