"""Ornament vase, tiled world against its untiled control, per world (issue 19.4, vas19s).

For a periodic pattern (the vase's flowers sit on a grid of spacing vase.GRID, fixed in
world coordinates) the border strips sit at a fixed phase of the grid, so their density
and kind shares differ from the interior's even in one untiled run. The fair measure is
therefore the tiled world's strip / interior ratio against the untiled control's ratio
on the same lines (the same strips, the same world size, seed 1): ``tiled / control``.

Reads the worlds of ``benchmarks/orn19m_willow.py make --pattern vase --tag TILED --tiles
T`` and ``... --tag CONTROL --tiles T --untiled`` and prints per tile size T, for the +-1 s
and +-2 s strips (s the world's mean spacing; the world's edge band left out as
worlds_strips.py does): the density ratio and each kind's share ratio, tiled, control and
tiled / control; the overlaps; the folded profile's chi2/dof (tiled, control).

``python benchmarks/vas19s_compare.py TILED CONTROL [--out F.json]``
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
sys.path.insert(0, str(HERE.parent / "tests" / "worlds"))


def _points(w: dict) -> dict:
    """Strip / interior ratios of one world (orn19m_willow._world's record)."""
    kinds = w["kinds"]
    out = {}
    for width in (1.0, 2.0):
        ins = w["inside"]
        near = w["d"] < width
        gnear = w["gd"] < width
        sa, ia = gnear.sum() * w["garea"], (~gnear).sum() * w["garea"]
        s, i = ins & near, ins & ~near
        row = {"density": float((s.sum() / sa) / (i.sum() / ia))}
        for k, name in enumerate(kinds):
            row[name] = float(((w["kind"][s] == k).sum() / max(s.sum(), 1)) / max((w["kind"][i] == k).sum() / max(i.sum(), 1), 1e-300))
        out[f"{width:g}s"] = row
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("tiled")
    ap.add_argument("control")
    ap.add_argument("--out", default=None)
    args = ap.parse_args()
    from orn19m_willow import _world
    from world_stats import folded_profile
    from worlds_strips import _pooled_profile

    class _XY:
        def __init__(self, w):
            self.x, self.y = w["x"], w["y"]

    res = {"tiled": args.tiled, "control": args.control, "worlds": {}}
    for p in sorted(RES.glob(f"orn19m_{args.tiled}_T*.npz")):
        T = p.name.rsplit("_T", 1)[1][:-4]
        q = RES / f"orn19m_{args.control}_T{T}.npz"
        if not q.exists():
            print(f"T {T}: no control")
            continue
        wt, wc = _world(p), _world(q)
        if wt["kinds"] != wc["kinds"]:
            print(f"T {T}: kinds differ {wt['kinds']} / {wc['kinds']}")
        pt, pc = _points(wt), _points(wc)
        zt, zc = np.load(p), np.load(q)
        fold = {}
        for name, w in (("tiled", wt), ("control", wc)):
            # the control measured on the tiled world's spacing, as worlds_strips.py does
            fold[name] = _pooled_profile([folded_profile(_XY(w), (w["side"], w["side"]), w["tile"], wt["s"])])["chi2_dof"]
        row = {"elements": [int(len(wt["x"])), int(len(wc["x"]))], "overlaps": [int(zt["overlaps"]), int(zc["overlaps"])],
               "counts": {"tiled": dict(zip(wt["kinds"], np.bincount(wt["kind"], minlength=len(wt["kinds"])).tolist())),
                          "control": dict(zip(wc["kinds"], np.bincount(wc["kind"], minlength=len(wc["kinds"])).tolist()))},
               "folded_chi2_dof": fold, "strips": {}}
        print(f"T {T}: elements tiled {row['elements'][0]:,} control {row['elements'][1]:,}; overlaps {row['overlaps']}; "
              f"counts tiled {row['counts']['tiled']} control {row['counts']['control']}; folded chi2/dof tiled {fold['tiled']:.2f} "
              f"control {fold['control']:.2f}")
        for width in pt:
            r = {k: {"tiled": pt[width][k], "control": pc[width].get(k, float("nan")),
                     "tiled_over_control": pt[width][k] / pc[width][k] if pc[width].get(k) else float("nan")} for k in pt[width]}
            row["strips"][width] = r
            print(f"  +-{width}: " + "; ".join(f"{k} {v['tiled']:.3f} / {v['control']:.3f} = {v['tiled_over_control']:.3f}"
                                             for k, v in r.items()))
        res["worlds"][T] = row
    if args.out:
        Path(args.out).write_text(json.dumps(res, indent=1) + "\n")
        print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
