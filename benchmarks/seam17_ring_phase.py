"""Helper seam17 (issue 13 point 2): why rings at 50x keep windows failing
``orientation.relative`` while the generator's own 50x draws do not.

A ring of ten tiles may stand turned about its hub by any angle below 36 degrees (its
phase). The generator draws every ring's phase at random; synth copies whole exemplar
rings (§5.1), so its phases are the exemplar's few (the default exemplar holds 8 whole
rings of ten, 5 of them within one 9-degree band), and neighbouring rings come from the
same exemplar rings. A tile's six nearest neighbours include the facing tiles of the
next rings, so the relative rotations the metric counts depend on the phases of
neighbouring rings.

Printed, for the exemplar, a generator draw at 50x (``fidelity_calibration.larger``,
seed 0) and synth at 50x (``--seeds``): the histogram of whole rings' phases (4.5-degree
bins), and for synth, per window of the local map, the share of its rings in the window's
most common 9-degree phase band, the top windows, the median, and each failing window's
rank by that share (``fidelity(ex, out, region, eq5=False)``).

    python benchmarks/seam17_ring_phase.py [--seeds 5,8] [--json F]
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, str(Path(__file__).resolve().parent))
import fidelity_calibration as FC
from _runner import SKIPPED, fidelity_suite

from strew import Region
from strew.metrics import fidelity


def phases(xy: np.ndarray, kind: np.ndarray, kinds: list[str], tiles: int = 10) -> tuple[np.ndarray, np.ndarray]:
    """Hub positions and the phase (degrees, mod 360 / tiles) of each whole ring (NaN otherwise)."""
    t, h = kinds.index("tile"), kinds.index("hub")
    H, T = xy[kind == h], xy[kind == t]
    _, j = cKDTree(H).query(T)
    cnt = np.bincount(j, minlength=len(H))
    per = 360.0 / tiles
    ang = np.degrees(np.arctan2(*(T - H[j]).T[::-1])) % per
    ph = np.full(len(H), np.nan)
    for i in np.flatnonzero(cnt == tiles):
        a = np.radians(ang[j == i] * tiles)
        ph[i] = (np.degrees(np.arctan2(np.sin(a).mean(), np.cos(a).mean())) / tiles) % per
    return H, ph


def hist(ph: np.ndarray) -> list[int]:
    return np.histogram(ph[np.isfinite(ph)], bins=np.arange(0, 36.1, 4.5))[0].tolist()


def main() -> None:
    if "--quick" in sys.argv[1:]:
        print("seam17_ring_phase: skipped: 50x canvases (minutes)")
        sys.exit(SKIPPED)
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", default="5,8")
    ap.add_argument("--json", default="benchmarks/results/seam17_ring_phase.json")
    a = ap.parse_args()
    from strew.synth import synthesize

    mk = fidelity_suite()
    ex = mk.make_exemplar("rings")
    out: dict = {"benchmark": "seam17_ring_phase", "rows": []}
    H, ph = phases(ex.xy, np.asarray(ex.kind), list(ex.kinds))
    p = np.sort(ph[np.isfinite(ph)])
    print(f"exemplar whole rings {len(p)}, phases {np.round(p, 1).tolist()}, hist {hist(ph)}")
    out["exemplar"] = dict(phases=np.round(p, 2).tolist(), hist=hist(ph))
    g = FC.larger("rings", 0, 50.0)
    H, ph = phases(g.xy, np.asarray(g.kind), list(g.kinds))
    print(f"generator s0 whole rings {int(np.isfinite(ph).sum())}, hist {hist(ph)}")
    out["generator"] = dict(hist=hist(ph))
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(7.07 * (x1 - x0), 7.07 * (y1 - y0))
    for seed in [int(s) for s in a.seeds.split(",")]:
        res = synthesize(ex, region, rng=seed, measure=False)
        rep = fidelity(ex, res, region, eq5=False)
        L = rep.local
        S = np.asarray(L["score"], float)
        H, ph = phases(res.xy, np.asarray(res.kind), list(res.kinds))
        conc = np.full(S.shape, np.nan)
        for (i, j), s in np.ndenumerate(S):
            if not np.isfinite(s):
                continue
            wx, wy = L["x0"] + j * L["step"], L["y0"] + i * L["step"]
            m = np.isfinite(ph) & (H[:, 0] >= wx) & (H[:, 0] < wx + L["window"]) & (H[:, 1] >= wy) & (H[:, 1] < wy + L["window"])
            q = ph[m]
            if len(q):
                conc[i, j] = max(np.sum(((q - c) % 36.0) < 9.0) for c in np.arange(0.0, 36.0, 1.0)) / len(q)
        fin = np.isfinite(conc) & np.isfinite(S)
        order = np.argsort(-np.where(fin, conc, -1), axis=None)
        rank = {tuple(int(v) for v in np.unravel_index(f, S.shape)): r + 1 for r, f in enumerate(order)}
        fails = [(int(i), int(j), round(float(S[i, j]), 3), round(float(conc[i, j]), 2), rank[(int(i), int(j))]) for (i, j) in zip(*np.nonzero(np.where(fin, S, 0) > 1.0))]
        top = [(int(i), int(j), round(float(conc[i, j]), 2)) for i, j in (np.unravel_index(f, S.shape) for f in order[:5])]
        corr = float(np.corrcoef(conc[fin], S[fin])[0, 1])
        row = dict(seed=seed, n=len(res), hist=hist(ph), median_share=round(float(np.median(conc[fin])), 3), top=top, failing=fails,
                   corr_share_score=round(corr, 3), windows=int(fin.sum()))
        out["rows"].append(row)
        print(f"synth s{seed} n={len(res)} hist {row['hist']} window share in one 9-deg band: median {row['median_share']}, top {top}; "
              f"failing (i, j, score, share, rank) {fails}; corr(share, window score) {row['corr_share_score']}", flush=True)
    Path(a.json).write_text(json.dumps(out, indent=1))
    print(f"figures written to {a.json}")


if __name__ == "__main__":
    main()
