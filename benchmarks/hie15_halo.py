"""Where a finished hierarchy tile's vines phase grows past its border, by distance past
it in halos (issue 19.4, helper hie15).

``python benchmarks/hie15_halo.py TAG [--tiles 48,52,56,60,64,68] [--seeds 1]`` reads
``hie15_tries_TAG_sS_TT.npz`` and ``orn19m_TAG_sS_TT.npz`` (benchmarks/hie15_make.py) and
prints, per bin of signed distance to the nearest inner border in halos (negative on the
finished side), the vines phase's successful tries per unit area against the interior's
(|d| >= 3 s), split by the run: ``own`` (the tile holding the circle's centre) and
``across`` (a neighbour's run through its halo); and the same for the flowers phase.
A tile's region ends a halo past its border, and §4.1 discards a circle the region's
boundary stops before it reaches an element: near that edge only circles that meet an
element first are grown into.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
RES = HERE / "results"
sys.path.insert(0, str(HERE))
EDGES = np.arange(-1.25, 1.2501, 0.25)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("tags", nargs="+")
    ap.add_argument("--tiles", default="48,52,56,60,64,68")
    ap.add_argument("--seeds", default="1")
    args = ap.parse_args()
    import orn19m_willow as W
    from hie15_tries import _seeds

    for tag in args.tags:
        nb = len(EDGES) - 1
        acc = {k: np.zeros(nb) for k in ("area", "v_own", "v_across", "f_own", "f_across")}
        inner = np.zeros(3)
        for tile in args.tiles.split(","):
            for s in _seeds(args.seeds):
                p = RES / f"hie15_tries_{tag}_s{s}_T{tile}.npz"
                if not p.exists():
                    continue
                w = W._world(RES / f"orn19m_{tag}_s{s}_T{tile}.npz")
                n = np.load(p)["num"]
                ph, x, y, run, ok = n[:, 0], n[:, 1], n[:, 2], n[:, 5], n[:, 7]
                halo = float(np.load(RES / f"orn19m_{tag}_s{s}_T{tile}.npz")["meta"][2])
                d, sd = W._sd(x, y, w["side"], w["tile"])
                m = w["margin"]
                ins = (x >= m) & (x <= w["side"] - m) & (y >= m) & (y <= w["side"] - m)
                order = [(c, r) for q in ((0, 0), (1, 0), (0, 1), (1, 1)) for r in (q[1], q[1] + 2) for c in (q[0], q[0] + 2)]
                rt = np.array([order[int(k)][1] * 4 + order[int(k)][0] for k in run])
                unit = (np.clip(np.floor(y / w["tile"]), 0, 3) * 4 + np.clip(np.floor(x / w["tile"]), 0, 3)).astype(np.int64)
                own = rt == unit
                b = np.digitize(sd / halo, EDGES) - 1
                good = ins & (b >= 0) & (b < nb) & (ok == 1)
                gb = np.digitize(w["gsd"] * w["s"] / halo, EDGES) - 1
                gok = (gb >= 0) & (gb < nb)
                acc["area"] += np.bincount(gb[gok], minlength=nb)[:nb] * w["garea"]
                for ph_k, pre in ((0, "v"), (1, "f")):
                    for who, sel in (("own", own), ("across", ~own)):
                        q = good & (ph == ph_k) & sel
                        acc[f"{pre}_{who}"] += np.bincount(b[q], minlength=nb)[:nb]
                iq = ins & (ok == 1) & (d / w["s"] >= 3.0)
                inner += [(w["gd"] >= 3.0).sum() * w["garea"], (iq & (ph == 0)).sum(), (iq & (ph == 1)).sum()]
        if not inner[0]:
            continue
        rv, rf = inner[1] / inner[0], inner[2] / inner[0]
        print(f"\n== {tag}: successful tries per unit area / interior's (vines {rv:.4f}, flowers {rf:.4f} per unit area); bins of d / halo, finished side negative")
        print("   bin            vines own  across   flowers own  across   (counts v own/across, f own/across)")
        for k in range(nb):
            a = acc["area"][k]
            print(f"   {EDGES[k]:+.2f}..{EDGES[k + 1]:+.2f}   {acc['v_own'][k] / a / rv:9.2f} {acc['v_across'][k] / a / rv:7.2f}"
                  f"   {acc['f_own'][k] / a / rf:11.2f} {acc['f_across'][k] / a / rf:7.2f}   ({int(acc['v_own'][k])}/{int(acc['v_across'][k])}, "
                  f"{int(acc['f_own'][k])}/{int(acc['f_across'][k])})")


if __name__ == "__main__":
    main()
