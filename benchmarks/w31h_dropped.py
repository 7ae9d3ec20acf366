"""Where the finished tile's border flowers go (issue 19.4, helper w31h): per bin of signed
distance d / s to the nearest inner border (negative: the finished, earlier tile's side),
each kind's count in the tiled world, in its untiled control, and among the rows the tiles
grew and dropped (``orn19m_willow.make`` records them), split into those dropped by the
tile holding them (``own``: the finished tile cutting its own side) and by another tile.

``python benchmarks/w31h_dropped.py TILED:CONTROL --seeds 19 --tiles 40,44,48,52,56 [--kinds vine,twig,flower]``
"""
import argparse
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import orn19m_willow as W  # noqa: E402

EDGES = np.arange(-3, 3.01, 0.5)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("pairs", nargs="+")
    ap.add_argument("--seeds", default="19")
    ap.add_argument("--tiles", default="40,44,48,52,56")
    ap.add_argument("--kinds", default="vine,twig,flower,leaf")
    a = ap.parse_args()
    nb = len(EDGES) - 1
    for pair in a.pairs:
        tt, cc = pair.split(":")
        kinds = a.kinds.split(",")
        tot = {k: np.zeros((4, nb)) for k in kinds}  # control, tiled, dropped own, dropped other
        for s in a.seeds.split(","):
            for T in a.tiles.split(","):
                w = W._world(HERE / "results" / f"orn19m_{tt}_s{s}_T{T}.npz")
                c = W._world(HERE / "results" / f"orn19m_{cc}_s{s}_T{T}.npz")
                for k in kinds:
                    for row, (ww, sd, d, kk, ins, extra) in enumerate([
                        (c, c["sd"], c["d"], c["kind"], c["inside"], None),
                        (w, w["sd"], w["d"], w["kind"], w["inside"], None),
                        (w, w["dsd"], w["dd"], w["dkind"], w["dinside"], "own"),
                        (w, w["dsd"], w["dd"], w["dkind"], w["dinside"], "other"),
                    ]):
                        if k not in ww["kinds"]:
                            continue
                        m = ins & (kk == ww["kinds"].index(k)) & (d < 3)
                        if extra is not None:
                            z = np.load(HERE / "results" / f"orn19m_{tt}_s{s}_T{T}.npz")
                            own = z["dtile"] == ww["dunit"]
                            m &= own if extra == "own" else ~own
                        b = np.clip(np.digitize(sd[m], EDGES) - 1, 0, nb - 1)
                        tot[k][row] += np.bincount(b, minlength=nb)
        print(f"== {tt} vs {cc}, seeds {a.seeds}, tiles {a.tiles}")
        print("bin(d/s) " + "  ".join(f"{k:>24s}" for k in kinds))
        print("         " + "  ".join(f"{'ctl  tiled dOwn dOth':>24s}" for k in kinds))
        for i in range(nb):
            print(f"{EDGES[i]:+.1f}..{EDGES[i+1]:+.1f} " + "  ".join(
                f"{int(tot[k][0, i]):5d} {int(tot[k][1, i]):5d} {int(tot[k][2, i]):5d} {int(tot[k][3, i]):5d}" for k in kinds))


if __name__ == "__main__":
    main()
