"""``benchmarks/orn19m_willow.py`` for hierarchy with the ``chord`` column set on vines to
the chord of the vine's drawn path (first to last point; NaN for the other kinds), instead of
willow's stems' chord: how long the vines near tile borders are against the interior's
(issue 19.4, helper hie19u). ``PYTHONPATH=TREE/src python benchmarks/hie19u_vines.py make
--tag TAG --tiles 130 --pattern hierarchy --overlaps`` then ``... analyze TAG`` (the profile's
``chord`` column is the vines' mean chord per bin; "stems' chord" the vines a later tile
placed on a finished side within 3 s against those beyond 3 s). ``... sides TAG [--out F]``:
per world, the vines within 3 s of a border split by side and by the tile that placed them,
against the interior (|d| >= 3 s): vines per unit area, goal radius (mean, median) and chord
(mean, median). ``... split TAG [TAG ...]``: per world and strip (+-1 s, +-2 s), the vines per
unit area on each side of the borders against the interior's, split by the tile that placed
them (finished side: kept by the finished tile / refilled by the later tile; later side: the
finished tile's vines crossing the border / the later tile's own). Nothing in the library is
changed.
"""

import runpy
import sys
from pathlib import Path

import numpy as np


def _chord(arr) -> np.ndarray:
    out = np.full(len(arr), np.nan)
    if "vine" not in arr.kinds:
        return out
    k = arr.kinds.index("vine")
    parts = arr.element_parts
    for i in np.flatnonzero(np.asarray(arr.kind) == k):
        p = parts[i][0]
        pts = np.asarray(p["paths"][0]["points"] if isinstance(p, dict) else p.paths[0].points, float)
        out[i] = float(np.hypot(*(pts[-1] - pts[0])))
    return out


def sides(tags: list[str], out: str | None) -> dict:
    import json

    here = Path(__file__).resolve().parent
    sys.path.insert(0, str(here))
    import orn19m_willow as W

    res: dict = {}
    for tag in tags:
        for p in sorted((here / "results").glob(f"orn19m_{tag}_T*.npz")):
            w, z = W._world(p), np.load(p)
            gr, ch = z["goal_r"], w["chord"]
            kinds = w["kinds"]
            s = w["s"]
            # areas (in s^2) of the lattice points by region
            ga = w["garea"] / s**2
            gnear = w["gd"] < 3
            area = {"interior": (~gnear).sum() * ga, "finished side": (gnear & (w["gsd"] < 0)).sum() * ga,
                    "later side": (gnear & (w["gsd"] > 0)).sum() * ga}
            ins = w["inside"]
            sd, oth = w["sd"], w["other"]
            near = (np.abs(sd) < 3) & ins
            regions = {"interior": (ins & (w["d"] >= 3), "interior"),
                       "finished side, placed by the later tile (refill)": (near & (sd < 0) & oth, "finished side"),
                       "finished side, placed by the finished tile": (near & (sd < 0) & ~oth, "finished side"),
                       "later side, placed by the finished tile": (near & (sd > 0) & oth, "later side"),
                       "later side, placed by the later tile": (near & (sd > 0) & ~oth, "later side")}
            r = {}
            for name, (m, a) in regions.items():
                row = {"area_s2": float(area[a])}
                for k, kn in enumerate(kinds):
                    row[f"{kn}_per_s2"] = float((m & (w["kind"] == k)).sum() / area[a])
                v = m & (w["kind"] == kinds.index("vine"))
                row.update(n_vines=int(v.sum()), goal_r_mean=float(np.nanmean(gr[v])), goal_r_median=float(np.nanmedian(gr[v])),
                           chord_mean=float(np.nanmean(ch[v])), chord_median=float(np.nanmedian(ch[v])))
                r[name] = row
                print(f"{p.name} {name:50s} vines {row['n_vines']:5d} per s2 {row['vine_per_s2']:.4f} "
                      f"goal r {row['goal_r_mean']:6.2f}/{row['goal_r_median']:6.2f} chord {row['chord_mean']:6.2f}/{row['chord_median']:6.2f} | "
                      + " ".join(f"{kn} {row[kn + '_per_s2']:.4f}" for kn in kinds))
            res[p.name] = r
    if out:
        Path(out).write_text(json.dumps(res, indent=1))
    return res


def split(tags: list[str]) -> None:
    here = Path(__file__).resolve().parent
    sys.path.insert(0, str(here))
    import orn19m_willow as W

    for tag in tags:
        for p in sorted((here / "results").glob(f"orn19m_{tag}_T*.npz")):
            w = W._world(p)
            s = w["s"]
            ga = w["garea"] / s**2
            v = w["inside"] & (w["kind"] == w["kinds"].index("vine"))
            allin = w["inside"]
            for width in (1.0, 2.0):
                gn = w["gd"] < width
                a_f, a_l, a_i = (gn & (w["gsd"] < 0)).sum() * ga, (gn & (w["gsd"] > 0)).sum() * ga, (w["gd"] >= 3).sum() * ga
                near = w["d"] < width
                iv, ia = (v & (w["d"] >= 3)).sum() / a_i, (allin & (w["d"] >= 3)).sum() / a_i
                f_k = (v & near & (w["sd"] < 0) & ~w["other"]).sum() / a_f
                f_r = (v & near & (w["sd"] < 0) & w["other"]).sum() / a_f
                l_k = (v & near & (w["sd"] > 0) & w["other"]).sum() / a_l
                l_o = (v & near & (w["sd"] > 0) & ~w["other"]).sum() / a_l
                fa, la = (allin & near & (w["sd"] < 0)).sum() / a_f, (allin & near & (w["sd"] > 0)).sum() / a_l
                print(f"{p.name} +-{width:g}s vines/s2 interior {iv:.4f} | finished side kept {f_k / iv:.3f} refill {f_r / iv:.3f} "
                      f"sum {(f_k + f_r) / iv:.3f} (all el {fa / ia:.3f}) | later side finished's {l_k / iv:.3f} own {l_o / iv:.3f} "
                      f"sum {(l_k + l_o) / iv:.3f} (all el {la / ia:.3f})")


if __name__ == "__main__":
    here = Path(__file__).resolve().parent
    sys.path.insert(0, str(here))
    if sys.argv[1:2] == ["sides"]:
        args = [a for a in sys.argv[2:] if not a.startswith("--")]
        o = sys.argv[sys.argv.index("--out") + 1] if "--out" in sys.argv else None
        sides([a for a in args if a != o], o)
        sys.exit(0)
    if sys.argv[1:2] == ["split"]:
        split(sys.argv[2:])
        sys.exit(0)
    g = runpy.run_path(str(here / "orn19m_willow.py"), run_name="orn19m_willow_lib")
    g["make"].__globals__["_chord"] = _chord
    g["main"]()
