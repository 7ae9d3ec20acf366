"""Per world (orn19m npz + hie19x_diag npz): the vines in the +-1 s / +-2 s strips by side,
with what the finished tiles grew there and dropped (pooled: near the corners two of them), and the later tile's own vines on the
later side split by parent (context element or its own), their goal radius and whether
their circle saw the context (clearance >= radius - 1 cell). Issue 19.4, helper hie19x.
``python benchmarks/hie19x_band.py TAG [TAG ...]``"""

import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import orn19m_willow as W  # noqa: E402


def main(tags):
    for tag in tags:
        for p in sorted((HERE / "results").glob(f"orn19m_{tag}_T*.npz")):
            w = W._world(p)
            s = w["s"]
            ga = w["garea"] / s**2
            kv = w["kinds"].index("vine")
            v = w["inside"] & (w["kind"] == kv)
            a_i = (w["gd"] >= 3).sum() * ga
            iv = (v & (w["d"] >= 3)).sum() / a_i
            dv = w["dinside"] & (w["dkind"] == kv)
            z = np.load(p)
            # dropped by a tile whose own rectangle is not where the vine lies: the finished tile's cut past the border
            dother = z["dtile"] != w["dunit"]
            for width in (1.0, 2.0):
                gn = w["gd"] < width
                a_f, a_l = (gn & (w["gsd"] < 0)).sum() * ga, (gn & (w["gsd"] > 0)).sum() * ga
                near, dnear = w["d"] < width, w["dd"] < width
                l_k = (v & near & (w["sd"] > 0) & w["other"]).sum() / a_l / iv
                l_o = (v & near & (w["sd"] > 0) & ~w["other"]).sum() / a_l / iv
                l_d = (dv & dnear & (w["dsd"] > 0) & dother).sum() / a_l / iv
                f_k = (v & near & (w["sd"] < 0) & ~w["other"]).sum() / a_f / iv
                f_r = (v & near & (w["sd"] < 0) & w["other"]).sum() / a_f / iv
                f_d = (dv & dnear & (w["dsd"] < 0) & ~dother).sum() / a_f / iv
                print(f"{p.name} +-{width:g}s: later side: finished tiles kept {l_k:.3f}, dropped {l_d:.3f} (every finished tile whose halo reaches there, hie19x_across.py splits them); "
                      f"later own {l_o:.3f}; sum {l_k + l_o:.3f} | finished side: kept {f_k:.3f} dropped {f_d:.3f} refill {f_r:.3f}")
            q = HERE / "results" / p.name.replace("orn19m_", "hie19x_diag_")
            if not q.exists():
                continue
            g = np.load(q)
            side, tile = w["side"], w["tile"]
            qd, qsd = W._sd(g["qx"], g["qy"], side, tile)
            qd, qsd = qd / s, qsd / s
            h = float(g["h"][0]) if len(g["h"]) else 1.0
            saw = g["clear"] >= g["r"] - 1.5 * h
            m = w["margin"]
            ins = (g["qx"] >= m) & (g["qx"] <= side - m) & (g["qy"] >= m) & (g["qy"] <= side - m)
            for width in (1.0, 2.0):
                sel = ins & (qd < width) & (qsd > 0)
                n = sel.sum()
                print(f"  later tiles' vines centred on the later side within {width:g} s: {n}, parent a context element {int((sel & g['pctx']).sum())}, "
                      f"circle clear of the context {int((sel & saw).sum())}/{n} (min clear - r {np.min(g['clear'][sel] - g['r'][sel]) if n else np.nan:.2f}), "
                      f"goal r mean {np.mean(g['r'][sel]) if n else np.nan:.2f} median {np.median(g['r'][sel]) if n else np.nan:.2f}")
            sel = ins & (qd >= 3)
            print(f"  later tiles' vines beyond 3 s: {sel.sum()}, goal r mean {np.mean(g['r'][sel]):.2f} median {np.median(g['r'][sel]):.2f}, all clear {int((sel & saw).sum())}")


if __name__ == "__main__":
    main(sys.argv[1:])
