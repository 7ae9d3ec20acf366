"""Where the tiled vase world's elements are missing against its untiled control (issue 19.4, vas19u).

``python benchmarks/vas19u_deficit.py TILED CONTROL [--tiles 84] [--out F.json]`` reads the
worlds of ``benchmarks/orn19m_willow.py make --pattern vase --tag TILED --tiles T`` (and
``--tag CONTROL --untiled``) and prints, per tile size, the absolute density (elements per
unit area, not a strip / interior ratio) of each kind, tiled / control, by the signed
distance to the nearest inner tile border in half-spacing bins (negative on the earlier,
finished tile's side), in the world's edge band, and in the interior (|d| > 3 s), and by
the tile's phase (the 2 x 2 order in which tiles run).
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
RES = HERE / "results"
sys.path.insert(0, str(HERE))
EDGES = np.array([-6.0, -3.0, -2.0, -1.5, -1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0, 3.0, 6.0])


def _cells(w, side, tile):
    from orn19m_willow import _sd

    g = np.arange(0.125, side, 0.25)
    gx, gy = np.meshgrid(g, g)
    return gx.ravel(), gy.ravel()


def _profile(path: Path, s: float) -> dict:
    from orn19m_willow import _sd

    z = np.load(path)
    side, tile, halo, _ = z["meta"]
    x, y, kind = z["x"], z["y"], z["kind"]
    kinds = [str(k) for k in z["kinds"]]
    margin = max(halo, 3.0 * s)
    gx, gy = _cells(None, side, tile)

    def lab(a, b):
        inside = (a >= margin) & (a <= side - margin) & (b >= margin) & (b <= side - margin)
        _, sd = _sd(a, b, side, tile)
        sd = sd / s
        binv = np.digitize(sd, EDGES) - 1  # -1 below -6 s ... len-1 above +6 s
        binv = np.clip(binv, -1, len(EDGES) - 1)
        out = np.where(inside, binv + 1, -1)  # 0 .. len(EDGES): distance bins; -1 the edge band
        # phase of the tile holding the point: (col % 2, row % 2)
        col, row = np.clip(np.floor(a / tile), 0, 3).astype(int), np.clip(np.floor(b / tile), 0, 3).astype(int)
        return out, (row % 2) * 2 + (col % 2)

    eb, ep = lab(x, y)
    gb, gp = lab(gx, gy)
    nb = len(EDGES) + 1
    area = np.array([(gb == b).sum() * 0.0625 for b in range(-1, nb)])
    cnt = np.zeros((nb + 1, len(kinds)))
    np.add.at(cnt, (eb + 1, kind), 1)
    parea = np.array([((gp == p) & (gb >= 0)).sum() * 0.0625 for p in range(4)])
    pcnt = np.zeros((4, len(kinds)))
    ok = eb >= 0
    np.add.at(pcnt, (ep[ok], kind[ok]), 1)
    return dict(kinds=kinds, area=area, cnt=cnt, parea=parea, pcnt=pcnt, n=len(x))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("tiled")
    ap.add_argument("control")
    ap.add_argument("--out", default=None)
    args = ap.parse_args()
    res = {"tiled": args.tiled, "control": args.control, "worlds": {}}
    for p in sorted(RES.glob(f"orn19m_{args.tiled}_T*.npz")):
        T = p.name.rsplit("_T", 1)[1][:-4]
        q = RES / f"orn19m_{args.control}_T{T}.npz"
        if not q.exists():
            continue
        zc = np.load(q)
        side = float(zc["meta"][0])
        s = 1.0 / np.sqrt(len(zc["x"]) / side**2)  # the control's spacing, for both
        a, c = _profile(p, s), _profile(q, s)
        kinds = a["kinds"]
        labels = ["edge band", f"<{EDGES[0]:g}"] + [f"{EDGES[i]:+g}..{EDGES[i + 1]:+g}" for i in range(len(EDGES) - 1)] + [f">{EDGES[-1]:g}"]
        print(f"T {T}: elements tiled {a['n']:,} control {c['n']:,} ({a['n'] / c['n']:.4f}); s {s:.3f}")
        print(f"  {'bin (s)':12s} {'area':>8s} {'tiled/ctl':>9s} " + " ".join(f"{k:>9s}" for k in kinds) + "   missing (ctl - tiled, per kind)")
        rows = {}
        for b, l in enumerate(labels):
            ta, ca = a["cnt"][b], c["cnt"][b]
            ar = a["area"][b]
            if ar <= 0:
                continue
            r = ta.sum() / max(ca.sum(), 1)
            rk = ta / np.maximum(ca, 1)
            rows[l] = dict(area=float(ar), tiled=ta.tolist(), control=ca.tolist(), ratio=float(r))
            print(f"  {l:12s} {ar:8.0f} {r:9.3f} " + " ".join(f"{v:9.3f}" for v in rk) + "   " + " ".join(f"{int(v):+d}" for v in (ca - ta)))
        ph = {}
        for pidx in range(4):
            ta, ca = a["pcnt"][pidx], c["pcnt"][pidx]
            ph[pidx] = dict(tiled=ta.tolist(), control=ca.tolist(), ratio=float(ta.sum() / max(ca.sum(), 1)))
            print(f"  phase (col%2,row%2)={pidx % 2, pidx // 2}: tiled/ctl {ph[pidx]['ratio']:.3f}  " + " ".join(f"{k} {int(u)}/{int(v)}" for k, u, v in zip(kinds, ta, ca)))
        # the elements counted in the +-1 s and +-2 s strips of vas19s_compare.py (its
        # spacing and edge band, per world), by kind: how many the share ratios rest on
        from orn19m_willow import _world

        strips = {}
        for name, path in (("tiled", p), ("control", q)):
            w = _world(path)
            for width in (1.0, 2.0):
                m = w["inside"] & (w["d"] < width)
                strips.setdefault(f"{width:g}s", {})[name] = dict(zip(kinds, np.bincount(w["kind"][m], minlength=len(kinds)).tolist()))
        for k, v in strips.items():
            print(f"  strip +-{k} counts: tiled {v['tiled']} control {v['control']}")
        res["worlds"][T] = dict(kinds=kinds, bins=rows, phases=ph, elements=[a["n"], c["n"]], s=s, strip_counts=strips)
    if args.out:
        Path(args.out).write_text(json.dumps(res, indent=1) + "\n")
        print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
