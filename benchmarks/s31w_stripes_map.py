"""Helper s31w (issue 13 point 2): stripes at 50x, the bars' median nearest-bar distance in
each window of the local fidelity map, averaged over seeds, with the mean window score,
and the same statistics' mean, sd and maximum over the windows of each draw, for synth
and (``--oracle``) the generator drawn at 50x (``fidelity_calibration.larger``).

    PYTHONPATH=src python benchmarks/s31w_stripes_map.py [--seeds 1-8] [--oracle 0,11] [--kind bar]
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, str(Path(__file__).resolve().parent))
import fidelity_calibration as FC
import seam17_all50  # noqa: F401  (its fast dart for the generator)
from _runner import fidelity_suite

from strew import Region
from strew.metrics import fidelity
from strew.synth import synthesize


def window_medians(out, L, kind: str) -> np.ndarray:
    names = np.asarray(out.kind_names)
    p = out.xy[names == kind]
    d = cKDTree(p).query(p, k=2)[0][:, 1]
    side, step = float(L["window"]), float(L["step"])
    S = np.asarray(L["score"], float)
    M = np.full(S.shape, np.nan)
    for (i, j), s in np.ndenumerate(S):
        if not np.isfinite(s):
            continue
        bx, by = L["x0"] + j * step, L["y0"] + i * step
        m = (p[:, 0] >= bx) & (p[:, 0] < bx + side) & (p[:, 1] >= by) & (p[:, 1] < by + side)
        M[i, j] = np.median(d[m])
    return M


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--name", default="stripes")
    ap.add_argument("--seeds", default="1-8")
    ap.add_argument("--oracle", default="0,11")
    ap.add_argument("--kind", default="bar")
    a = ap.parse_args()
    lo, _, hi = a.seeds.partition("-")
    ex = fidelity_suite().make_exemplar(a.name)
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(7.07 * (x1 - x0), 7.07 * (y1 - y0))
    e = ex.xy[np.asarray(ex.kind_names) == a.kind]
    print(f"exemplar {a.kind} nn median {np.median(cKDTree(e).query(e, k=2)[0][:, 1]):.2f}")
    Ms, Ss = [], []
    for s in range(int(lo), int(hi or lo) + 1):
        out = synthesize(ex, region, rng=s, measure=False)
        L = fidelity(ex, out, region, eq5=False).local
        M = window_medians(out, L, a.kind)
        Ms.append(M)
        Ss.append(np.asarray(L["score"], float))
        print(f"synth s{s}: window medians mean {np.nanmean(M):.2f} sd {np.nanstd(M):.3f} max {np.nanmax(M):.2f} (z {(np.nanmax(M) - np.nanmean(M)) / np.nanstd(M):.1f}); worst score {np.nanmax(Ss[-1]):.3f}", flush=True)
    np.set_printoptions(linewidth=200)
    print("synth: mean over seeds of each window's median (row 0 = lowest y)")
    print(np.round(np.nanmean(Ms, axis=0), 2))
    print("synth: mean score")
    print(np.round(np.nanmean(Ss, axis=0), 2))
    for s in [int(t) for t in a.oracle.split(",") if t]:
        arr = FC.larger(a.name, s, 50.0)
        L = fidelity(ex, arr, eq5=False).local
        M = window_medians(arr, L, a.kind)
        print(f"generator s{s}: window medians mean {np.nanmean(M):.2f} sd {np.nanstd(M):.3f} max {np.nanmax(M):.2f} (z {(np.nanmax(M) - np.nanmean(M)) / np.nanstd(M):.1f}); worst score {np.nanmax(np.asarray(L['score'], float)):.3f}", flush=True)


if __name__ == "__main__":
    main()
