"""Helper g25o: why grow rotate loses regularity on a lattice exemplar (scales EDGE p2):
for each interior output element that misses the exemplar's pattern, say whether its
neighbour count is off, or its offsets miss in its own frame but match in a frame turned
to its neighbours' mean rotation (the element's own turn), or miss either way (position).

    PYTHONPATH=src python benchmarks/g25o_reg_diag.py [CLASS:LABEL=scales:p2s10] [SEEDS=1] [KEY=VALUE ...]
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _runner import fidelity_suite
from fresh17_rows import exemplar

from strew import Region, _fidelity
from strew.grow import grow

spec = sys.argv[1] if len(sys.argv) > 1 else "scales:p2s10"
seeds = [int(s) for s in (sys.argv[2] if len(sys.argv) > 2 else "1").split(",")]
kw = {k: eval(v, {"math": math}) for k, v in (a.split("=") for a in sys.argv[3:])}
mode = kw.pop("mode", "rotate")
cls, label = spec.split(":")
mk = fidelity_suite()
ex = exemplar(mk, cls, label)
calls = []
orig = _fidelity._lattice_match


def spy(sm, tree, s, template):
    calls.append((sm, tree, s, template))
    return orig(sm, tree, s, template)


_fidelity._lattice_match = spy
for seed in seeds:
    x0, y0, x1, y1 = ex.region.bounds
    scale = 3.5
    for _ in range(2):
        out = grow(ex, region=Region.rectangle(scale * (x1 - x0), scale * (y1 - y0)), mode=mode, rng=seed, **kw)
        if len(out) >= 10 * len(ex):
            break
        scale *= 1.05 * math.sqrt(10 * len(ex) / max(len(out), 1))
    calls.clear()
    rep = _fidelity.fidelity(ex, out, eq5=False, local=False)
    sm, tree, s, tpl = calls[-1]
    import shapely

    edge = shapely.distance(sm.region.boundary, shapely.points(sm.xy))
    inner = np.flatnonzero((edge >= _fidelity.LATTICE_REACH * s + 0.5 * s) & shapely.contains_xy(sm.window, sm.xy[:, 0], sm.xy[:, 1]))
    ok = orig(sm, tree, s, tpl)[inner]
    loc, cnt = _fidelity._local_offsets(sm, tree, s, tpl[0], inner)
    bad = inner[~ok]
    # neighbours' mean rotation (6 nearest)
    d, j = tree.query(sm.xy[bad], k=7)
    j = j[:, 1:]
    mean_rot = np.angle(np.mean(np.exp(1j * sm.rotation[j]), axis=1))
    turn = np.angle(np.exp(1j * (sm.rotation[bad] - mean_rot)))
    saved = sm.rotation.copy()
    sm.rotation = sm.rotation.copy()
    sm.rotation[bad] = mean_rot
    ok2 = orig(sm, tree, s, tpl)[bad]
    sm.rotation = saved
    cntb = cnt[~ok]
    m = rep.metrics["regularity"]
    print(f"seed {seed} n={len(out)} regularity {m.result:.4f} vs {m.exemplar} interior {len(inner)} miss {len(bad)}: "
          f"count off {int(np.sum(cntb != tpl[0]))} (fewer {int(np.sum(cntb < tpl[0]))}, more {int(np.sum(cntb > tpl[0]))}), "
          f"count ok & match when turned to neighbours' frame {int(np.sum((cntb == tpl[0]) & ok2))}, neither {int(np.sum((cntb == tpl[0]) & ~ok2))}")
    print(f"   |turn| of missing elements from neighbours' mean: median {np.median(np.abs(turn)):.4f}, of all interior "
          f"{np.median(np.abs(np.angle(np.exp(1j*(sm.rotation[inner]-np.angle(np.mean(np.exp(1j*sm.rotation[tree.query(sm.xy[inner],k=7)[1][:,1:]]),axis=1))))))):.4f}")
    print(f"   template count {tpl[0]} s {s:.2f} offsets {np.round(tpl[1],1).tolist()}")
    # worst slot mismatch of the count-ok misses
    sel = np.flatnonzero(cntb == tpl[0])
    if len(sel):
        L = loc[~ok][sel][:, : tpl[0]]
        dd = np.hypot(L[:, None, :, 0] - tpl[1][None, :, None, 0], L[:, None, :, 1] - tpl[1][None, :, None, 1])
        worst = np.nanmax(np.nanmin(dd, axis=2), axis=1) / s
        print(f"   count-ok misses: worst slot miss / s quantiles {np.round(np.quantile(worst,[0.1,0.5,0.9]),3).tolist()}")
    np.save(f"/tmp/g25o/bad_{seed}.npy", np.c_[sm.xy[bad], cnt[~ok]])
    # the extra neighbours of the count-over misses: their local offsets (units of s)
    over = np.flatnonzero(cntb > tpl[0])
    if len(over):
        L = loc[~ok][over]
        extra = []
        for row in L:
            row = row[np.isfinite(row[:, 0])]
            dd = np.hypot(row[:, None, 0] - tpl[1][None, :, 0], row[:, None, 1] - tpl[1][None, :, 1]).min(axis=1)
            extra.extend((row[dd > _fidelity.LATTICE_MATCH * s] / s).tolist())
        extra = np.array(extra)
        print(f"   extra neighbour offsets / s (x, y): {len(extra)}; |x|<0.5: {int(np.sum(np.abs(extra[:,0])<0.5))} (median |y| {np.median(np.abs(extra[np.abs(extra[:,0])<0.5,1])) if np.any(np.abs(extra[:,0])<0.5) else float('nan'):.3f}), |y|<0.5: {int(np.sum(np.abs(extra[:,1])<0.5))} (median |x| {np.median(np.abs(extra[np.abs(extra[:,1])<0.5,0])) if np.any(np.abs(extra[:,1])<0.5) else float('nan'):.3f})")
        xyb = sm.xy[bad][over]
        print(f"   over-count elements: x range {np.round(np.quantile(xyb[:,0],[0,.5,1]),0).tolist()} y range {np.round(np.quantile(xyb[:,1],[0,.5,1]),0).tolist()}; window bounds {np.round(sm.window.bounds,0).tolist()}")
