"""Why the finished tile's border flowers are lost (issue 19.4, helper w31h): one tiled
hierarchy world (4 x 4 tiles of T, seed S) in which every tile's keep-rule
(strew.tiles._keep_groups) is also re-run on the same grown rows with one hand-over rule
off at a time; per bin of signed distance to the nearest later tile (negative: inside the
tile; in units of the world's spacing s), the flower successes (twig rows) the tile grew,
kept, and would keep with each rule off.

``PYTHONPATH=src python benchmarks/w31h_trace.py --tile 40 --seed 19 [--set NAME=VALUE ...]``
-> benchmarks/results/w31h_trace_T{T}.txt (and prints it)
"""
import argparse
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
EDGES = np.arange(-3, 1.01, 0.5)
VARIANTS = {"LB0": {"_LATE_BAND": 0.0}, "CUT0": {"_CUT_ROUNDS": 0}, "BEY0": {"_FIRST_BEYOND": 0},
            "LB0+CUT0": {"_LATE_BAND": 0.0, "_CUT_ROUNDS": 0}}


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--tile", type=float, default=40)
    ap.add_argument("--seed", type=int, default=19)
    ap.add_argument("--set", action="append", default=[])
    ap.add_argument("--kinds", default="twig,flower,leaf,vine")
    a = ap.parse_args()
    import strew.tiles as T

    for kv in a.set:
        k, _, v = kv.partition("=")
        setattr(T, k, type(getattr(T, k))(v))
    orig = T._keep_groups
    rows = []

    def wrapped(arr, keep, t, job, links):
        k = orig(arr, keep, t, job, links)
        later = T._later_rects(t, job)
        if not later or not len(arr):
            return k
        x, y = np.asarray(arr.x, float), np.asarray(arr.y, float)
        d = np.full(len(arr), np.inf)
        for x0, y0, x1, y1 in later:
            d = np.minimum(d, np.hypot(np.maximum(np.maximum(x0 - x, x - x1), 0.0), np.maximum(np.maximum(y0 - y, y - y1), 0.0)))
        tx0, ty0, tx1, ty1 = t.rect
        inside = (x >= tx0) & (x < tx1) & (y >= ty0) & (y < ty1)
        # signed: negative inside the tile (distance to the nearest later tile), positive in a later tile
        sd = np.where(inside, -d, 0.0)
        inl = d <= 0
        if inl.any():  # depth into the later tile: distance past t's rectangle
            sd[inl] = np.hypot(np.maximum(np.maximum(tx0 - x, x - tx1), 0.0), np.maximum(np.maximum(ty0 - y, y - ty1), 0.0))[inl]
        out = {"main": k}
        for name, sets in VARIANTS.items():
            old = {n: getattr(T, n) for n in sets}
            for n, v in sets.items():
                setattr(T, n, v)
            try:
                out[name] = orig(arr, keep, t, job, links)
            finally:
                for n, v in old.items():
                    setattr(T, n, v)
        kinds = np.asarray([arr.kinds[i] for i in arr.kind])
        rows.append((t.index, sd, kinds, out, inside | inl))
        return k

    T._keep_groups = wrapped
    side = 4 * a.tile
    t0 = time.time()
    w = T.tiled("ornament", "hierarchy", (side, side), tile_size=a.tile, seed=a.seed)
    s = side / np.sqrt(len(w))
    lines = [f"w31h trace T{a.tile:g} seed {a.seed} {' '.join(a.set)}: {len(w)} elements, s {s:.2f}, halo {float(w.meta['world']['halo']):g}, {time.time() - t0:.0f} s",
             "per kind, bin of signed distance / s to the nearest later tile (neg: inside the finished tile): grown, kept (main), kept with " + ", ".join(VARIANTS)]
    for kind in a.kinds.split(","):
        lines.append(f"-- {kind}")
        nb = len(EDGES) - 1
        tab = np.zeros((2 + len(VARIANTS), nb), int)
        for _, sd, kinds, out, ok in rows:
            m = ok & (kinds == kind) & (sd / s >= EDGES[0]) & (sd / s < EDGES[-1])
            b = np.clip(np.digitize(sd[m] / s, EDGES) - 1, 0, nb - 1)
            tab[0] += np.bincount(b, minlength=nb)
            for r, name in enumerate(["main", *VARIANTS]):
                tab[1 + r] += np.bincount(b[out[name][m]], minlength=nb)
        lines.append("bin        grown  main " + " ".join(f"{n:>8s}" for n in VARIANTS))
        for i in range(nb):
            lines.append(f"{EDGES[i]:+.1f}..{EDGES[i + 1]:+.1f} {tab[0, i]:5d} {tab[1, i]:5d} " + " ".join(f"{v:8d}" for v in tab[2:, i]))
    txt = "\n".join(lines)
    print(txt)
    (HERE / "results" / f"w31h_trace_T{a.tile:g}{'_' + '_'.join(a.set) if a.set else ''}.txt").write_text(txt + "\n")


if __name__ == "__main__":
    main()
