"""Where the tiled hierarchy's vines and flowers phases try and succeed by side of the
border, against the untiled control, pooled over worlds (issue 19.4, helper hie15).

``python benchmarks/hie15_tries.py TAG ... [--seeds 1] [--tiles 48,52,56,60,64,68] [--json F]``
reads ``benchmarks/results/hie15_tries_TAG_sS_TT.npz`` (benchmarks/hie15_make.py) and
the world (orn19m_TAG_sS_TT.npz, for its spacing s and lines). Per strip (+-1 s, +-2 s)
and side (fin: the earlier, finished tile's side; later), per unit area against the
interior (|d| >= 3 s): the vines phase's tries, its successes, its failures and those
whose candidate parents held no vine (no vine rule could apply: the circle touches only
twigs, flowers, leaves or fillers); the flowers phase's successes (twig + flower), those
in a circle of a vine's size (>= 8, the vines phase's threshold) and those in a circle
that was tried in the vines phase and failed (within 1 unit). Tries in a tile's halo
that the tile then cut are counted too: a try records the run's room, not the world's.
For the tiled worlds the runs are split: ``own`` (the run's tile holds the circle's
centre) and ``across`` (a neighbour's run: on the finished side, the later tile's refill;
on the later side, the finished tile growing past its border). Runs map to tiles in
strew.tiles' order for 4 x 4 tiles in 2 x 2 phases (columns and rows 0, 2 first; then
column 1, 3 of rows 0, 2; then rows 1, 3 of columns 0, 2; then the rest), as run.
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
INNER = 3.0


def _seeds(spec: str) -> list[int]:
    out: list[int] = []
    for part in spec.split(","):
        a, _, b = part.partition("-")
        out.extend(range(int(a), int(b or a) + 1))
    return out


def world_counts(tag: str, tile: str) -> dict:
    import orn19m_willow as W

    w = W._world(RES / f"orn19m_{tag}_T{tile}.npz")
    z = np.load(RES / f"hie15_tries_{tag}_T{tile}.npz")
    n = z["num"]
    ph, x, y, r, run, ok, vc = n[:, 0], n[:, 1], n[:, 2], n[:, 3], n[:, 5], n[:, 7], n[:, 8]
    d, sd = W._sd(x, y, w["side"], w["tile"])
    d, sd = d / w["s"], sd / w["s"]
    m = w["margin"]
    ins = (x >= m) & (x <= w["side"] - m) & (y >= m) & (y <= w["side"] - m)
    # a vines-phase failure near (1 unit) the flowers-phase success's centre, in the same run
    vf = (ph == 0) & (ok == 0)
    fs = (ph == 1) & (ok == 1)
    after_fail = np.zeros(len(x), bool)
    for k in np.flatnonzero(fs):
        q = vf & (run == run[k])
        after_fail[k] = bool(((x[q] - x[k]) ** 2 + (y[q] - y[k]) ** 2 < 1.0).any())
    ev = {
        "vines_tries": ph == 0, "vines_ok": (ph == 0) & (ok == 1), "vines_fail": vf, "vines_fail_novine": vf & (vc == 0),
        "flowers_ok": fs, "flowers_ok_r8": fs & (r >= 8.0), "flowers_ok_after_vine_fail": fs & after_fail,
        "flowers_fail": (ph == 1) & (ok == 0),
    }
    # the tile of each run (col, row) in strew.tiles' order, and the tile holding each centre
    order = [(c, r) for ph in ((0, 0), (1, 0), (0, 1), (1, 1)) for r in (ph[1], ph[1] + 2) for c in (ph[0], ph[0] + 2)]
    rt = np.array([order[int(k)][1] * 4 + order[int(k)][0] if 0 <= k < 16 else -1 for k in run])
    unit = (np.clip(np.floor(y / w["tile"]), 0, 3) * 4 + np.clip(np.floor(x / w["tile"]), 0, 3)).astype(np.int64)
    own = (rt == unit) | (rt < 0)
    out: dict = {}
    for who, sel in (("all", np.ones(len(x), bool)), ("own", own), ("across", ~own)):
        for wd in (1.0, 2.0):
            for side, ss, gs in (("fin", sd < 0, w["gsd"] < 0), ("later", sd > 0, w["gsd"] > 0)):
                strip = ins & sel & (d < wd) & ss
                a = ((w["gd"] < wd) & gs).sum() * w["garea"]
                out[(who, wd, side)] = np.array([a] + [(strip & e).sum() for e in ev.values()], float)
        inner = ins & sel & (d >= INNER)
        out[(who, "inner")] = np.array([(w["gd"] >= INNER).sum() * w["garea"]] + [(inner & e).sum() for e in ev.values()], float)
    out["names"] = list(ev)
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("tags", nargs="+")
    ap.add_argument("--seeds", default="1")
    ap.add_argument("--tiles", default="48,52,56,60,64,68")
    ap.add_argument("--boot", type=int, default=2000)
    ap.add_argument("--json", default=None)
    args = ap.parse_args()
    res: dict = {}
    rng = np.random.default_rng(0)
    for tag in args.tags:
        ws = []
        for tile in args.tiles.split(","):
            for s in _seeds(args.seeds):
                if (RES / f"hie15_tries_{tag}_s{s}_T{tile}.npz").exists():
                    ws.append(world_counts(f"{tag}_s{s}", tile))
        if not ws:
            continue
        names = ws[0]["names"]
        print(f"\n== {tag}: {len(ws)} worlds; per unit area against the same runs' interior (all runs' interior for 'all')")
        res[tag] = {"worlds": len(ws)}
        for who in ("all", "own", "across"):
            inner = np.sum([w[("all", "inner")] for w in ws], 0)
            for wd in (1.0, 2.0):
                for side in ("fin", "later"):
                    S = np.array([w[(who, wd, side)] for w in ws])
                    I = np.array([w[("all", "inner")] for w in ws])

                    def rat(S, I):
                        s, i = S.sum(0), I.sum(0)
                        with np.errstate(divide="ignore", invalid="ignore"):
                            return (s[1:] / s[0]) / (i[1:] / i[0])

                    est = rat(S, I)
                    bs = []
                    for _ in range(args.boot):
                        k = rng.integers(0, len(ws), len(ws))
                        bs.append(rat(S[k], I[k]))
                    lo, hi = np.nanpercentile(np.array(bs), [2.5, 97.5], axis=0)
                    key = f"{who} {wd:g}s {side}"
                    res[tag][key] = {nm: [float(est[j]), float(lo[j]), float(hi[j]), int(S.sum(0)[1 + j])] for j, nm in enumerate(names)}
                    print(f"  {key:18s} " + "; ".join(f"{nm} {est[j]:.2f} ({int(S.sum(0)[1 + j])})" for j, nm in enumerate(names)))
            res[tag]["inner_per_area"] = {nm: float(inner[1 + j] / inner[0]) for j, nm in enumerate(names)}
        print("  interior per unit area: " + "; ".join(f"{k} {v:.4f}" for k, v in res[tag]["inner_per_area"].items()))
    if args.json:
        Path(args.json).write_text(json.dumps(res, indent=1) + "\n")
        print(f"wrote {args.json}")


if __name__ == "__main__":
    main()
