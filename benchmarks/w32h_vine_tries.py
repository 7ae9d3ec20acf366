"""Where the tiled hierarchy's vines phase grows its vines, by signed distance to the nearest
inner border, against the untiled control (issue 19.4, helper w32h).

``python benchmarks/w32h_vine_tries.py TILED CONTROL --tile 44 [--seed 19]``

Reads ``benchmarks/results/hie15_tries_TAG_sS_TT.npz`` and ``orn19m_TAG_sS_TT.npz``
(benchmarks/hie15_make.py; the control made with ``--untiled``). Per signed bin of d / s
(negative on the earlier, finished tile's side; orn19m_willow._sd): the vines phase's
successes whose circle centre lies in the bin, grown by the run whose tile holds the centre
(own) or by a neighbour's run (across: mostly the finished tile growing past its border,
then cut), their mean circle radius, and the vines kept in the world (element centres).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
RES = HERE / "results"
sys.path.insert(0, str(HERE))
EDGES = np.array([-100, -6, -4, -3, -2, -1, 0, 1, 2, 3, 4, 6, 100.0])
# strew.tiles' run order for 4 x 4 tiles in 2 x 2 phases (as benchmarks/hie15_tries.py)
ORDER = [(c, r) for ph in ((0, 0), (1, 0), (0, 1), (1, 1)) for r in (ph[1], ph[1] + 2) for c in (ph[0], ph[0] + 2)]


def one(tag: str, tile: int, seed: int, W, tiled: bool) -> dict:
    z = np.load(RES / f"hie15_tries_{tag}_s{seed}_T{tile}.npz")
    w = W._world(RES / f"orn19m_{tag}_s{seed}_T{tile}.npz")
    num, cols = z["num"], list(z["cols"])
    g = lambda n: num[:, cols.index(n)]  # noqa: E731
    x, y = g("x"), g("y")
    _, sd = W._sd(x, y, w["side"], w["tile"])
    sd = sd / w["s"]
    m = w["margin"]
    ins = (x >= m) & (x <= w["side"] - m) & (y >= m) & (y <= w["side"] - m)
    T = w["tile"]
    u = (np.clip(np.floor(y / T), 0, 3) * 4 + np.clip(np.floor(x / T), 0, 3)).astype(int)
    rt = np.array([ORDER[int(k)][1] * 4 + ORDER[int(k)][0] if 0 <= k < 16 else -1 for k in g("run")])
    own = (rt == u) if tiled else np.ones(len(x), bool)
    ok = (g("ok") == 1) & (g("phase") == 0) & ins
    b = np.digitize(sd, EDGES) - 1
    nb = len(EDGES) - 1
    k = np.array(w["kinds"])[w["kind"]]
    kv = (k == "vine") & w["inside"]
    return dict(own=np.bincount(b[ok & own], minlength=nb), across=np.bincount(b[ok & ~own], minlength=nb),
                r=np.bincount(b[ok & own], weights=g("r")[ok & own], minlength=nb),
                kept=np.histogram(w["sd"][kv], EDGES)[0])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("tiled")
    ap.add_argument("control")
    ap.add_argument("--tile", type=int, default=44)
    ap.add_argument("--seed", type=int, default=19)
    a = ap.parse_args()
    import orn19m_willow as W

    t = one(a.tiled, a.tile, a.seed, W, True)
    c = one(a.control, a.tile, a.seed, W, False)
    print(f"T{a.tile} s{a.seed}: vines phase successes by circle centre, tiled {a.tiled} / control {a.control}")
    print("bin d/s        own grown t/c   (mean r t/c)    across(t)   kept vines t/c")
    for i in range(len(EDGES) - 1):
        rt = t["r"][i] / max(t["own"][i], 1)
        rc = c["r"][i] / max(c["own"][i], 1)
        print(f"[{EDGES[i]:+5g},{EDGES[i + 1]:+5g})   {t['own'][i]:4d}/{c['own'][i]:4d}     ({rt:5.1f}/{rc:5.1f})     {t['across'][i]:4d}      {t['kept'][i]:4d}/{c['kept'][i]:4d}")


if __name__ == "__main__":
    main()
