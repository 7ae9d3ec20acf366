"""Helper s60w (issue 13 point 2): every window's ratio (discrepancy / window tolerance)
for every metric of the local map, for a synth output kept by ``s60w_dump50.py`` or for a
fresh 50x draw of the class's generator (``seam17_all50.py``'s oracle), so that the spread
of each metric over windows compares synth with the generator, not only the worst window.

    python benchmarks/s60w_window_ratios.py synth OUT.npz NAME RES.npz
    python benchmarks/s60w_window_ratios.py generator SEED NAME RES.npz
"""
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import fidelity_calibration as FC
import seam13m_oracle50 as O
import seam17_all50 as S17
from _runner import SKIPPED, fidelity_suite

import strew._fidelity as F
from strew import Arrangement, Region

if "--quick" in sys.argv[1:] or len(sys.argv) < 5:
    print("s60w_window_ratios.py: skipped: 50x canvases (minutes); usage: synth OUT.npz NAME RES.npz | generator SEED NAME RES.npz")
    sys.exit(SKIPPED)
src, arg, name, path = sys.argv[1:5]
ex = fidelity_suite().make_exemplar(name)
if src == "synth":
    d = np.load(arg, allow_pickle=True)
    sh = ex.shapes
    kinds = list(d["kinds"])
    sr = np.array([sh[k].radius for k in kinds])
    k = d["kind"]
    out = Arrangement(sh, [kinds[i] for i in k], d["xy"][:, 0], d["xy"][:, 1], d["rot"], d["rad"] / sr[k])
    b = d["bounds"]
    region = Region.rectangle(b[2] - b[0], b[3] - b[1])
else:
    seed = int(arg)
    if name in S17.OUTLINED:
        out, region, _ = O.oracle(name, seed, 50.0, "framed", 2.0, O._outlines(name))
    else:
        out, region = FC.larger(name, seed, 50.0), None
rec: list = []
cap: dict = {}
orig_d, orig_map = F._window_discrepancies, F._local_map


def hook_d(st, *a, **kw):
    r = orig_d(st, *a, **kw)
    if cap.get("in_map"):  # the result's windows only (the exemplar's noise windows call it too)
        rec.append((r, None))
    return r


def hook_map(res, raw, ex_stats, metrics, kinds, s, ex_win, res_win, flags, noise=None):
    cap.update(metrics=metrics, ex_area=ex_win.area, noise=noise or {}, in_map=True)
    try:
        return orig_map(res, raw, ex_stats, metrics, kinds, s, ex_win, res_win, flags, noise)
    finally:
        cap["in_map"] = False


F._window_discrepancies, F._local_map = hook_d, hook_map
rep = F.fidelity(ex, out, region, eq5=False)
Sc = np.asarray(rep.local["score"], float)
side = rep.local["window"]
names = sorted({n for r, _ in rec for n in r})
R = np.full((len(rec), len(names)), np.nan)
for i, (r, _) in enumerate(rec):
    for j, n in enumerate(names):
        m = cap["metrics"].get(n)
        v = r.get(n)
        if m is None or v is None or not m.applicable or not np.isfinite(v) or not (m.tolerance > 0):
            continue
        # whole windows (the map's interior): area side^2
        R[i, j] = v / F._window_tolerance(m, side * side, cap["ex_area"], cap["noise"].get(n))
np.savez(path, R=R, names=np.array(names), score=Sc)
fin = Sc[np.isfinite(Sc)]
print(f"{src} {arg} {name}: n={len(out)} windows={fin.size} failing={int((fin > 1).sum())} worst={fin.max():.3f}")
for j, n in enumerate(names):
    c = R[:, j][np.isfinite(R[:, j])]
    if len(c):
        print(f"  {n:22s} mean {c.mean():.3f} q90 {np.quantile(c, 0.9):.3f} max {c.max():.3f} >1: {(c > 1).sum()}")
