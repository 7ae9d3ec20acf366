"""Helper g33s (issue 14 point 1): why grow fails sparse_voids / stones rows of the fresh draw 23,24.

    PYTHONPATH=src python benchmarks/g33s_probe.py CLASS:LABEL SEEDS [--oracle 2]

For each grow seed (as the audit: ``grow_variants.run``, fixed mode, 10x the exemplar):
the metric's two statistics (result, exemplar) for density / empty_circle, the apples'
(visible kind's) density per unit area in bands of distance from the frame and in rings
of distance from the growth seed, the visible kind's nearest-neighbour deciles
(in exemplar units s), and for empty_circle the largest empty circles of the result (where:
centre, distance to frame, to the grow start, and the placement order of the elements around).
``--oracle D``: the class's own generator drawn at the output's size, D draws (sparse_voids
with its dart counts scaled by the area: ``make.sparse_voids`` caps them at 400/800).
"""
from __future__ import annotations

import os
import sys
from types import SimpleNamespace

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "examples", "fidelity"))
from fresh17_rows import exemplar  # noqa: E402
from _runner import fidelity_suite  # noqa: E402
from grow_variants import run  # noqa: E402

from scipy.spatial import cKDTree, Voronoi  # noqa: E402

from strew.metrics import fidelity  # noqa: E402
from strew import Region  # noqa: E402


def vis(a):
    v = a.columns.get("void")
    return np.ones(len(a), bool) if v is None else ~np.asarray(v, bool)


def nn_s(a):
    xy = a.xy[vis(a)]
    d, _ = cKDTree(xy).query(xy, 2)
    return d[:, 1]


def dens_bands(a, edges):
    """visible elements per 10^4 area in bands of distance from the frame."""
    x0, y0, x1, y1 = a.region.bounds
    xy = a.xy[vis(a)]
    db = np.minimum.reduce([xy[:, 0] - x0, x1 - xy[:, 0], xy[:, 1] - y0, y1 - xy[:, 1]])
    out = []
    W, H = x1 - x0, y1 - y0
    for lo, hi in zip(edges[:-1], edges[1:]):
        hi = min(hi, min(W, H) / 2)
        area = (W - 2 * lo) * (H - 2 * lo) - max(W - 2 * hi, 0) * max(H - 2 * hi, 0)
        n = int(((db >= lo) & (db < hi)).sum())
        out.append((lo, hi, n, 1e4 * n / area if area > 0 else float("nan")))
    return out


def metrics(ex, out, names):
    rep = fidelity(ex, out, eq5=False, local=False)
    fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
    sel = {k: m for k, m in rep.metrics.items() if any(k.startswith(n) for n in names)}
    return rep, fails, sel


def sparse_oracle(kw, size, rng):
    import make

    g = np.random.default_rng(rng)
    spacing, apple, void, vs = (kw.get("spacing", 30.0), kw.get("apple", 5.0), kw.get("void", 4.0), kw.get("void_spacing", 11.0))
    f = (size / 200.0) ** 2
    na, nv = int(400 * f), int(800 * f)
    pa, ra = make._dart(g, (0, 0, size, size), np.full(na, 0.5 * spacing), na, tries=5000)
    pv, _ = make._dart(g, (0, 0, size, size), np.full(nv, 0.5 * vs), nv, tries=12000, placed=(pa, ra))
    ref = make.sparse_voids(0, spacing=spacing, apple=apple, void=void, void_spacing=vs)
    p = np.r_[pa, pv]
    kind = np.r_[np.zeros(len(pa), int), np.ones(len(pv), int)]
    rot = np.where(kind == 0, g.normal(0, 0.3, len(p)), 0.0)
    return make._finish("sparse_voids", ref.shapes, kind, p, rot, box=(0, 0, size, size), columns={"void": kind == 1}, params=dict(size=size))


def main():
    spec, seeds = sys.argv[1], [int(s) for s in sys.argv[2].split(",")]
    ndraw = int(sys.argv[sys.argv.index("--oracle") + 1]) if "--oracle" in sys.argv else 0
    cls, label = spec.split(":")
    mk = fidelity_suite()
    ex = exemplar(mk, cls, label)
    names = ["density", "empty_circle", "nn", "g["]
    s_ex = float(np.median(nn_s(ex)))
    print(f"{spec}: exemplar n={len(ex)} visible={int(vis(ex).sum())} frame={ex.region.bounds} s={s_ex:.2f} params={ex.meta.get('params')}")
    print("  exemplar bands (dist from frame, n, per 1e4):", " ".join(f"[{lo:.0f},{hi:.0f}) {n} {d:.2f}" for lo, hi, n, d in dens_bands(ex, [0, 10, 20, 40, 1e9])))
    print("  exemplar nn deciles/s:", np.round(np.quantile(nn_s(ex), np.linspace(0.1, 0.9, 9)) / s_ex, 3))
    args = SimpleNamespace(mode="fixed", times=10.0)
    last = None
    for seed in seeds:
        out, sc = run(ex, 3.5, seed, args)
        rep, fails, sel = metrics(ex, out, names)
        print(f"\n seed {seed}: n={len(out)} visible={int(vis(out).sum())} scale={sc:.3f} frame={tuple(round(b, 1) for b in out.region.bounds)} {'pass' if rep.faithful else 'FAIL'} {' '.join(fails)}")
        for k, m in sel.items():
            if k.startswith(("density", "empty")):
                print(f"   {k}: value {m.value:.3f}/{m.tolerance:.3f} result {m.result} exemplar {m.exemplar}")
        print("   bands (dist from frame, n, per 1e4):", " ".join(f"[{lo:.0f},{hi:.0f}) {n} {d:.2f}" for lo, hi, n, d in dens_bands(out, [0, 10, 20, 40, 80, 1e9])))
        print("   nn deciles/s:", np.round(np.quantile(nn_s(out), np.linspace(0.1, 0.9, 9)) / s_ex, 3))
        # placement order: grow's output order is its placement order (index), first element the seed
        xy = out.xy[vis(out)]
        idx = np.flatnonzero(vis(out))
        c0 = out.xy[0]
        r = np.hypot(*(xy - c0).T)
        q = np.quantile(r, [0, 0.25, 0.5, 0.75, 1.0])
        x0, y0, x1, y1 = out.region.bounds
        db = np.minimum.reduce([xy[:, 0] - x0, x1 - xy[:, 0], xy[:, 1] - y0, y1 - xy[:, 1]])
        inner = db > 40
        rr = r[inner]
        qq = np.quantile(rr, np.linspace(0, 1, 5))
        parts = []
        for lo, hi in zip(qq[:-1], qq[1:]):
            m = (rr >= lo) & (rr <= hi)
            # density in the annulus clipped to the interior: use nn-based estimate 1/(mean Voronoi) ~ crude: count / annulus area fraction
            parts.append(f"r[{lo:.0f},{hi:.0f}) n={int(m.sum())} nn_med/s={np.median(nn_s_sub(xy[inner][m], xy)) / s_ex:.3f}")
        print("   rings from grow start (interior >40 from frame):", " | ".join(parts))
        order = np.argsort(idx)
        k4 = np.array_split(np.arange(len(idx)), 4)
        print("   placement quarters nn_med/s:", [round(float(np.median(nn_s_sub(xy[k], xy)) / s_ex), 3) for k in k4], "start", np.round(c0, 1))
        print(f"   hidden/visible ratio {(~vis(out)).sum() / vis(out).sum():.3f} (exemplar {(~vis(ex)).sum() / vis(ex).sum():.3f})")
        empty(out, ex, s_ex)
        last = out
    if ndraw and cls == "sparse_voids":
        size = last.region.bounds[2] - last.region.bounds[0]
        kw = ex.meta.get("params") or {}
        v = int(label.split("s")[-1]) if "s" in label else int(label[1:])
        for d in range(ndraw):
            o = sparse_oracle(kw, size, v + 1000 * (d + 1))
            rep, fails, sel = metrics(ex, o, names)
            m = sel["density[apple]"]
            print(f"\n oracle draw {d} size {size:.0f}: visible={int(vis(o).sum())} {'pass' if rep.faithful else 'FAIL'} {' '.join(fails)}  density {m.value:.3f} result {m.result} exemplar {m.exemplar}")
            print("   bands:", " ".join(f"[{lo:.0f},{hi:.0f}) {n} {dd:.2f}" for lo, hi, n, dd in dens_bands(o, [0, 10, 20, 40, 80, 1e9])))
            print("   nn deciles/s:", np.round(np.quantile(nn_s(o), np.linspace(0.1, 0.9, 9)) / s_ex, 3))
            print(f"   hidden/visible ratio {(~vis(o)).sum() / vis(o).sum():.3f}")
            empty(o, ex, s_ex, ranks=False)


def nn_s_sub(pts, allpts):
    d, _ = cKDTree(allpts).query(pts, 2)
    return d[:, 1]


def empty(out, ex, s_ex, ranks=True):
    """largest empty circles of the visible centres (Voronoi vertices inside the frame)."""
    xy = out.xy[vis(out)]
    x0, y0, x1, y1 = out.region.bounds
    vor = Voronoi(xy)
    V = vor.vertices
    ok = (V[:, 0] > x0) & (V[:, 0] < x1) & (V[:, 1] > y0) & (V[:, 1] < y1)
    V = V[ok]
    t = cKDTree(xy)
    d, j = t.query(V, 3)
    db = np.minimum.reduce([V[:, 0] - x0, x1 - V[:, 0], V[:, 1] - y0, y1 - V[:, 1]])
    top = np.argsort(-d[:, 0])[: 6 if ranks else 0]
    c0 = out.xy[0]
    vi = np.flatnonzero(vis(out))
    n = len(xy)
    print("   largest empty circles (r/s, centre, dist to frame, dist to start, placement ranks of its 3 elements / n):")
    for k in top:
        print(f"     r={d[k, 0] / s_ex:.2f} at ({V[k, 0]:.0f},{V[k, 1]:.0f}) frame {db[k]:.0f} start {np.hypot(*(V[k] - c0)):.0f} ranks {[round(int(vi[i]) / len(out), 3) for i in j[k]]}")
    exy = ex.xy[vis(ex)]
    ev = Voronoi(exy).vertices
    ex0, ey0, ex1, ey1 = ex.region.bounds
    okk = (ev[:, 0] > ex0) & (ev[:, 0] < ex1) & (ev[:, 1] > ey0) & (ev[:, 1] < ey1)
    de, _ = cKDTree(exy).query(ev[okk], 1)
    print("   exemplar empty-circle radii quantiles (0.5,0.9,0.95,0.99,max)/s:", np.round(np.quantile(de, [0.5, 0.9, 0.95, 0.99, 1]) / s_ex, 3))
    print("   result   empty-circle radii quantiles (0.5,0.9,0.95,0.99,max)/s:", np.round(np.quantile(d[:, 0], [0.5, 0.9, 0.95, 0.99, 1]) / s_ex, 3))


if __name__ == "__main__":
    main()
