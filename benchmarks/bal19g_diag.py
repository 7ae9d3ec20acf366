"""What synth's balance rule (``_grow._prefer_balanced``) sees near a tile's context
against inside a tile (issue 19 point 4, helper bal19g).

A tiled three_sizes world (as ``benchmarks/worlds_strips.py --methods synth
--synth-exemplar three_sizes``: 2640 x 2640, tiles 440) is made with the rule wrapped:
for every seed it acts on, the class counts in its disc (``n_k``), the expected counts
(``N p_k``), ``z_k``, the share of fixed (context) elements in the disc and, after the
rule, the size class of the candidate it put first. Seeds are binned by their distance
to the nearest inner tile border, in spacings ``s``, and by whether the tile had a
context. Run: ``python benchmarks/bal19g_diag.py --seeds 1 [--variant NAME]
--out /tmp/bal19g/diag.json``.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--seeds", default="1")
    ap.add_argument("--exemplar", default="three_sizes")
    ap.add_argument("--side", type=float, default=2640.0)
    ap.add_argument("--tile", type=float, default=440.0)
    ap.add_argument("--out", required=True)
    args = ap.parse_args()
    import strew.synth._grow as G
    from strew.tiles import tiled
    from strew_testing import fidelity_suite

    ex = fidelity_suite().make_exemplar(args.exemplar)
    rec: list[np.ndarray] = []
    orig = G._prefer_balanced

    def wrapped(state, seeds, cands, costs, slack, c):
        prep = state.prep
        ncls = int(prep.size_class.max()) + 1
        sel = prep.selected_elements & ~prep.void
        vis = np.flatnonzero(sel[state.src] & ~state.ghost)
        before = costs.copy()
        orig(state, seeds, cands, costs, slack, c)
        if len(seeds) == 0 or len(vis) < 2:
            return
        side = np.sqrt(np.bincount(prep.source, minlength=len(prep.names)) / np.maximum(prep.density, 1e-12))
        srcs = prep.source[state.src[seeds]]
        out_cnt = np.bincount(prep.size_class[state.src[vis]], minlength=ncls).astype(float)
        p = out_cnt / out_cnt.sum()
        from scipy.spatial import cKDTree

        tree = cKDTree(state.pos[vis])
        lists = tree.query_ball_point(state.pos[seeds], G.BALANCE_RADIUS * side[srcs])
        fixed = state.fixed[vis]
        cls = prep.size_class[state.src[vis]]
        ctx = float(state.fixed.any())
        for i, lst in enumerate(lists):
            lst = np.asarray(lst, np.int64)
            cnt = np.bincount(cls[lst], minlength=ncls).astype(float)
            N = cnt.sum()
            var = N * p * (1 - p)
            z = np.where(var > 0, (cnt - N * p) / np.sqrt(np.maximum(var, 1e-12)), 0.0)
            b = before[i]
            a = costs[i]
            okb = np.isfinite(b) & (cands[i] >= 0)
            if not okb.any():
                continue
            first_b = prep.size_class[cands[i][np.argmin(np.where(okb, b, np.inf))]]
            first_a = prep.size_class[cands[i][np.argmin(np.where(okb, a, np.inf))]]
            changed = float(not np.array_equal(a, b))
            own = prep.size_class[state.src[seeds[i]]]
            nfix = float(fixed[lst].sum())
            rec.append(np.concatenate([state.pos[seeds[i]], [N, nfix, ctx, changed, first_b, first_a, own], cnt, N * p, z]))

    G._prefer_balanced = wrapped
    rows = {}
    for seed in [int(v) for v in args.seeds.split(",")]:
        t0 = time.process_time()
        arr = tiled("synth", ex, (args.side, args.side), tile_size=args.tile, seed=seed, measure=False)
        s = 1.0 / np.sqrt(len(arr) / args.side**2)
        print(f"seed {seed}: {len(arr)} elements, spacing {s:.2f}, {time.process_time() - t0:.0f} CPU s, {len(rec)} records", flush=True)
    R = np.array(rec)
    ncls = (R.shape[1] - 9) // 3
    xy = R[:, :2]
    T = args.tile
    # distance to the nearest inner tile border line
    d = np.full(len(R), np.inf)
    for ax in range(2):
        k = np.clip(np.round(xy[:, ax] / T), 1, round(args.side / T) - 1)
        d = np.minimum(d, np.abs(xy[:, ax] - k * T))
    ds = d / s
    edge = np.minimum(xy.min(axis=1), args.side - xy.max(axis=1)) < 3 * s
    bins = [0, 1, 2, 3, 4, 6, 10, 1e9]
    cnt = R[:, 9 : 9 + ncls]
    exp = R[:, 9 + ncls : 9 + 2 * ncls]
    z = R[:, 9 + 2 * ncls :]
    print(f"{'bin (s)':>9} {'ctx':>3} {'seeds':>6} {'N':>6} {'fixed':>6} {'acted':>6} " + " ".join(f"{'n/Np' + str(k):>7}" for k in range(ncls))
          + " " + " ".join(f"{'z' + str(k):>6}" for k in range(ncls)) + " " + " ".join(f"{'1st' + str(k) + 'b>a':>12}" for k in range(ncls)))
    for ctxv in (0.0, 1.0):
        for lo, hi in zip(bins[:-1], bins[1:]):
            m = (ds >= lo) & (ds < hi) & ~edge & (R[:, 4] == ctxv)
            if m.sum() == 0:
                continue
            ratio = cnt[m].sum(axis=0) / exp[m].sum(axis=0)
            fb = [float((R[m, 6] == k).mean()) for k in range(ncls)]
            fa = [float((R[m, 7] == k).mean()) for k in range(ncls)]
            row = dict(n=int(m.sum()), N=float(R[m, 2].mean()), fixed=float((R[m, 3] / np.maximum(R[m, 2], 1)).mean()),
                       acted=float(R[m, 5].mean()), ratio=ratio.tolist(), z=z[m].mean(axis=0).tolist(), first_before=fb, first_after=fa)
            rows[f"ctx{int(ctxv)} {lo}-{hi}"] = row
            print(f"{lo:>4}-{hi:<4g} {int(ctxv):>3} {m.sum():>6} {row['N']:>6.1f} {row['fixed']:>6.3f} {row['acted']:>6.3f} "
                  + " ".join(f"{v:>7.3f}" for v in ratio) + " " + " ".join(f"{v:>6.2f}" for v in row["z"]) + " "
                  + " ".join(f"{b:>5.3f}>{a:<6.3f}" for b, a in zip(fb, fa)), flush=True)
    Path(args.out).write_text(json.dumps({"command": " ".join(sys.argv), "rows": rows}, indent=1) + "\n")
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
