"""Direct counts of hierarchy's kinds by signed distance d / s to the nearest inner border
(negative: the earlier, finished tile's side), tiled against the untiled control, per
world and pooled (issue 19.4, helper w34h).

``python benchmarks/w34h_sides.py TILED:CTL[,TILED:CTL...] [--tiles 40,44,48,52,56] [--seed 19]
[--kinds vine,twig,flower,leaf]``

Worlds ``benchmarks/results/orn19m_TAG_sS_TT.npz`` (benchmarks/hie15_make.py); a pair
list is pooled over every tile size both tags have. Prints, per kind, counts inside the
world (orn19m_willow._world's ``inside``) in the bins -6..-3, -3..-2, -2..0, 0..+2,
+2..+3, +3..+6 s and the strip (|d| < 2 s) and interior (|d| >= 3 s) totals, tiled / control.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import orn19m_willow as W  # noqa: E402

R = HERE / "results"
EDGES = np.array([-6, -3, -2, 0, 2, 3, 6.0])


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("pairs")
    ap.add_argument("--tiles", default="40,44,48,52,56")
    ap.add_argument("--seed", type=int, default=19)
    ap.add_argument("--kinds", default="vine,twig,flower,leaf")
    a = ap.parse_args()
    kinds = a.kinds.split(",")
    acc = {k: {"t": np.zeros(len(EDGES) + 1, int), "c": np.zeros(len(EDGES) + 1, int)} for k in kinds}
    used = []
    for pair in a.pairs.split(","):
        t, c = pair.split(":")
        for T in a.tiles.split(","):
            ft, fc = R / f"orn19m_{t}_s{a.seed}_T{T}.npz", R / f"orn19m_{c}_s{a.seed}_T{T}.npz"
            if not (ft.exists() and fc.exists()):
                continue
            used.append(f"{t}/{c} T{T}")
            for lab, f in (("t", ft), ("c", fc)):
                w = W._world(f)
                names = np.array(w["kinds"])[w["kind"]]
                sd, d, ins = w["sd"], w["d"], w["inside"]
                for k in kinds:
                    m = (names == k) & ins
                    h = np.histogram(sd[m], EDGES)[0]
                    strip = int((m & (d < 2.0)).sum())
                    inner = int((m & (d >= 3.0)).sum())
                    acc[k][lab] += np.r_[h, strip, inner]
    print("worlds:", ", ".join(used))
    labels = [f"[{EDGES[i]:g},{EDGES[i + 1]:g})" for i in range(len(EDGES) - 1)] + ["strip|d|<2", "interior|d|>=3"]
    for k in kinds:
        tt, cc = acc[k]["t"], acc[k]["c"]
        print(f"{k:7s} " + "  ".join(f"{lab}:{x}/{y}" for lab, x, y in zip(labels, tt, cc)))


if __name__ == "__main__":
    main()
