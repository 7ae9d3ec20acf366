"""``benchmarks/orn19m_willow.py`` with the ``chord`` column set on hierarchy's vines to 1 for
a vine placed after the vines phase (the flowers phase: vine_joins_vine, which joins two
free vine tips meeting head on) and 0 for the others, instead of willow's stems' chord:
where the vines' share of the border strips comes from (issue 19.4). ``PYTHONPATH=TREE/src python
benchmarks/dot19s_vines.py make --tag TAG --tiles 126 --pattern hierarchy`` then
``... analyze TAG``: the profile's ``chord`` column is then the share of joining vines
among the bin's vines, and "stems' chord" that share among the vines a later tile placed on
a finished side within 3 s against those beyond 3 s. ``... radii TAG --out F``: the radius of the empty circle each vine grew
into (the ``goal_r`` the make step saves), interior (|d| >= 3 s) against the vines within 3 s
of a border, split by side and by the tile that placed them. Nothing in the library is
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
    ph = np.asarray(arr["phase"], dtype=object)
    v = np.asarray(arr.kind) == k
    out[v] = np.array([0.0 if p == "vines" else 1.0 for p in ph[v]])
    return out


def radii(tag: str, out: str | None) -> dict:
    import json

    here = Path(__file__).resolve().parent
    sys.path.insert(0, str(here))
    import orn19m_willow as W

    res: dict = {}
    for p in sorted((here / "results").glob(f"orn19m_{tag}_T*.npz")):
        w, z = W._world(p), np.load(p)
        gr = z["goal_r"]
        v = (w["kind"] == w["kinds"].index("vine")) & w["inside"]
        sd, oth = w["sd"], w["other"]
        near = (np.abs(sd) < 3) & v
        rows = {"interior": v & (w["d"] >= 3), "finished side, placed by the later tile (refill)": near & (sd < 0) & oth,
                "finished side, placed by the finished tile": near & (sd < 0) & ~oth,
                "later side, placed by the finished tile": near & (sd > 0) & oth, "later side, placed by the later tile": near & (sd > 0) & ~oth}
        res[p.name] = {k: dict(n=int(m.sum()), mean=float(gr[m].mean()), median=float(np.median(gr[m])), under_12=float((gr[m] < 12).mean()))
                       for k, m in rows.items()}
        for k, r in res[p.name].items():
            print(f"{p.name} {k:50s} n {r['n']:5d} goal radius mean {r['mean']:6.2f} median {r['median']:6.2f} under 12: {r['under_12']:.2f}")
    if out:
        Path(out).write_text(json.dumps(res, indent=1))
    return res


if __name__ == "__main__":
    here = Path(__file__).resolve().parent
    sys.path.insert(0, str(here))
    if sys.argv[1:2] == ["radii"]:
        radii(sys.argv[2], sys.argv[sys.argv.index("--out") + 1] if "--out" in sys.argv else None)
        sys.exit(0)
    g = runpy.run_path(str(here / "orn19m_willow.py"), run_name="orn19m_willow_lib")
    g["make"].__globals__["_chord"] = _chord
    g["main"]()
