"""Helper seam13n (issue 13 point 2): is synth's large-stone count per 50x window more
variable than a faithful continuation's? Per-window class counts and the small stones'
distance to the nearest large one, synth against the exemplar's own generator.

Three sizes at 50x the exemplar's area: synth (``seam13f_diag.py``'s canvas) and framed
draws of the generator (``seam13m_oracle50.py``'s oracle), each cut into the local
fidelity map's windows (the exemplar's area, stepped by half a side; the geometry of
``fidelity(...).local`` on the first synth output). Printed per output and pooled per
source: the windows' mean and standard deviation of each class's count, the large
count's coefficient of variation in windows and in cells of a half and a quarter side,
the correlations of the small and medium counts with the large count, the windows'
median distance from a small stone to the nearest large one (the statistic behind
``nn[small>large]``, the commonest failing metric at 50x): its spread over windows and
the part of it the three counts do not explain (least-squares residual), and the share
of the area where one more small stone fits (clearance beyond a small radius; in the
middle of the canvas), against the exemplar's own.

Synth's growth also records each stage's window counts (after growth, fill_displaced,
fill_room, fill_holes): the stage that sets the large count per window.

    python benchmarks/seam13n_windows.py [--seeds 1,2,3,4] [--oracle-seeds 2,3]
        [--json benchmarks/results/seam13n_windows.json]

Figures (05:14-05:22 UTC, 8224b5f, ``--seeds 1,...,8 --oracle-seeds 1,2,3``,
``benchmarks/results/seam13n_windows.json``; synth / generator):
- large count per window sd 2.357 / 2.477 (cv 0.077 / 0.079); in cells of half a side
  cv 0.177 / 0.185, of a quarter 0.429 / 0.438: synth's large count is not more
  variable than a faithful continuation's at any of these scales;
- corr(small, large) -0.49 / -0.23, corr(medium, large) -0.69 / -0.77;
- the windows' median small-to-large distance: mean 17.47 / 16.91 (exemplar 17.43),
  sd 0.329 / 0.244, 0.273 / 0.203 once the three counts are regressed out: the spread
  behind nn[small>large] lies in how small stones sit among large ones within a window,
  not in how many large stones a window holds;
- growth sets the counts (after growth, the large count's sd is the final one);
- room for one more small stone: exemplar 0.048 of the area (0.0024 at 1.5 radii),
  synth 0.050-0.057 (0.0038-0.0058), generator 0.023 (0.0002): the generator at 50x
  is denser than the exemplar, so its windows are a tighter reference than the
  exemplar's own process.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _runner import SKIPPED, fidelity_suite

CLASSES = ("small", "medium", "large")


def _classes(arr) -> np.ndarray:
    return np.array([CLASSES.index(arr.kinds[k]) for k in np.asarray(arr.kind)], np.int64)


def window_stats(xy: np.ndarray, cls: np.ndarray, geom: tuple[float, float, float, float, int, int]) -> np.ndarray:
    """(windows, 4): small, medium, large counts and the small stones' median distance
    to the nearest large one, per window of the local map."""
    x0, y0, step, side, nr, nc = geom
    dsl = cKDTree(xy[cls == 2]).query(xy[cls == 0])[0]
    sm = xy[cls == 0]
    rows = []
    for i in range(nr):
        for j in range(nc):
            wx, wy = x0 + j * step, y0 + i * step
            m = (xy[:, 0] >= wx) & (xy[:, 0] < wx + side) & (xy[:, 1] >= wy) & (xy[:, 1] < wy + side)
            ms = (sm[:, 0] >= wx) & (sm[:, 0] < wx + side) & (sm[:, 1] >= wy) & (sm[:, 1] < wy + side)
            rows.append((*np.bincount(cls[m], minlength=3), float(np.median(dsl[ms])) if ms.any() else np.nan))
    return np.asarray(rows, float)


def cell_cv(xy: np.ndarray, cls: np.ndarray, geom, frac: float) -> float:
    """Coefficient of variation of the large count in square cells of ``frac`` x the
    window's side over the map's extent."""
    x0, y0, step, side, nr, nc = geom
    cs = side * frac
    n = int((side + (max(nr, nc) - 1) * step) / cs)
    L = xy[cls == 2]
    ix = np.floor((L - [x0, y0]) / cs).astype(np.int64)
    ok = (ix >= 0).all(axis=1) & (ix < n).all(axis=1)
    cnt = np.bincount(ix[ok, 1] * n + ix[ok, 0], minlength=n * n)
    return float(cnt.std() / max(cnt.mean(), 1e-12))


def room_share(xy: np.ndarray, cls: np.ndarray, radii: np.ndarray, box) -> tuple[float, float]:
    """Shares of ``box`` (a 1-unit grid) whose clearance to every element's disc exceeds
    one and one and a half small radii."""
    x0, y0, x1, y1 = box
    g = np.mgrid[x0:x1:1.0, y0:y1:1.0].reshape(2, -1).T
    d, i = cKDTree(xy).query(g, k=8)
    cl = (d - radii[cls[i]]).min(axis=1)
    return float(np.mean(cl > radii[0])), float(np.mean(cl > 1.5 * radii[0]))


def pooled(rows: list[np.ndarray], cvs: list[tuple[float, float]]) -> dict:
    A = np.concatenate(rows)
    A = A[np.isfinite(A[:, 3])]
    c, y = A[:, :3], A[:, 3]
    X = np.c_[np.ones(len(y)), (c - c.mean(0)) / np.maximum(c.std(0), 1e-12)]
    b = np.linalg.lstsq(X, y, rcond=None)[0]
    return {
        "windows": len(A), "count_mean": c.mean(0).round(2).tolist(), "count_sd": c.std(0).round(3).tolist(),
        "large_cv": round(float(c[:, 2].std() / c[:, 2].mean()), 4),
        "large_cv_cells_half": round(float(np.mean([v[0] for v in cvs])), 4), "large_cv_cells_quarter": round(float(np.mean([v[1] for v in cvs])), 4),
        "corr_small_large": round(float(np.corrcoef(c[:, 0], c[:, 2])[0, 1]), 3), "corr_medium_large": round(float(np.corrcoef(c[:, 1], c[:, 2])[0, 1]), 3),
        "sl_median_mean": round(float(y.mean()), 3), "sl_median_sd": round(float(y.std()), 4), "sl_median_max": round(float(y.max()), 3),
        "sl_median_resid_sd": round(float((y - X @ b).std()), 4), "sl_coef_per_sd": b[1:].round(4).tolist(),
    }


def main() -> None:
    if "--quick" in sys.argv[1:]:
        print("seam13n_windows: skipped: 50x synth and generator draws (minutes)")
        sys.exit(SKIPPED)
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", default="1,2,3,4")
    ap.add_argument("--oracle-seeds", default="2,3")
    ap.add_argument("--json", default="benchmarks/results/seam13n_windows.json")
    a = ap.parse_args()

    import strew.synth._displace as D
    import strew.synth._grow as G
    from strew import Region
    from strew.metrics import fidelity
    from strew.synth import synthesize

    mk = fidelity_suite()
    ex = mk.make_exemplar("three_sizes")
    radii = np.array([ex.shapes[k].radius for k in CLASSES])
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(7.07 * (x1 - x0), 7.07 * (y1 - y0))
    ecls = _classes(ex)
    m = 2.5 * radii[2]
    out: dict = {"benchmark": "seam13n_windows three_sizes 50x", "exemplar": {}, "rows": [], "pooled": {}}
    out["exemplar"]["room_small"] = room_share(ex.xy, ecls, radii, (x0 + m, y0 + m, x1 - m, y1 - m))
    print("exemplar room for one more small stone (share of area; at 1.5 radii):", np.round(out["exemplar"]["room_small"], 4))

    # stage snapshots of synth's growth (positions and size classes of visible elements)
    snaps: list = []

    def snap(tag, state):
        n = state.n
        vis = ~state.prep.void[state.src[:n]]
        snaps.append((tag, state.pos[:n][vis].copy(), state.prep.size_class[state.src[:n][vis]].copy()))

    def wrapped(mod, name, tag, before=None):
        f = getattr(mod, name)

        def g(state, *args, **kw):
            if before:
                snap(before, state)
            r = f(state, *args, **kw)
            snap(tag, state)
            return r

        setattr(mod, name, g)
        return f

    saved = [(G, "_complete_anchor_rings", wrapped(G, "_complete_anchor_rings", "rings", before="growth")),
             (D, "fill_displaced", wrapped(D, "fill_displaced", "displaced")),
             (G, "fill_room", wrapped(G, "fill_room", "room")), (G, "fill_holes", wrapped(G, "fill_holes", "holes"))]
    geom = None
    acc: dict[str, tuple[list, list]] = {"synth": ([], []), "oracle": ([], [])}
    try:
        for seed in [int(s) for s in a.seeds.split(",") if s]:
            snaps.clear()
            t = time.process_time()
            res = synthesize(ex, region, rng=seed, measure=False)
            t = time.process_time() - t
            L = fidelity(ex, res, region, eq5=False).local
            S = np.asarray(L["score"], float)
            if geom is None:
                geom = (L["x0"], L["y0"], L["step"], L["window"], S.shape[0], S.shape[1])
            cls = _classes(res)
            w = window_stats(res.xy, cls, geom)
            cv = (cell_cv(res.xy, cls, geom, 0.5), cell_cv(res.xy, cls, geom, 0.25))
            acc["synth"][0].append(w)
            acc["synth"][1].append(cv)
            c = region.geometry.centroid
            box = (c.x - 200, c.y - 200, c.x + 200, c.y + 200)
            stages = {}
            for tag, p, k in snaps:
                ws = window_stats(p, k, geom)[:, :3]
                stages[tag] = {"mean": ws.mean(0).round(2).tolist(), "sd": ws.std(0).round(3).tolist()}
            fail = S.ravel()[np.isfinite(S.ravel())] > 1
            row = {"source": "synth", "seed": seed, "n": len(res), "cpu_s": round(t, 1), "failing": int(fail.sum()),
                       "worst": float(np.nanmax(S)), "count_mean": w[:, :3].mean(0).round(2).tolist(), "count_sd": w[:, :3].std(0).round(3).tolist(),
                       "large_in_failing": w[fail, 2].tolist(), "sl_median_sd": round(float(np.nanstd(w[:, 3])), 4), "large_cv_cells": cv,
                       "room_small": room_share(res.xy, cls, radii, box), "stages": stages}
            out["rows"].append(row)
            print(f"synth s{seed} n={len(res)} failing {row['failing']} worst {row['worst']:.3f}; counts mean {row['count_mean']} sd {row['count_sd']}; "
                  f"S>L median sd {row['sl_median_sd']}; room {np.round(row['room_small'], 4)}", flush=True)
            for tag, v in stages.items():
                print(f"    after {tag:10s} mean {v['mean']} sd {v['sd']}")
    finally:
        for mod, name, f in saved:
            setattr(mod, name, f)
    if a.oracle_seeds:
        import seam13m_oracle50 as O

        outl = O._outlines("three_sizes")
        for seed in [int(s) for s in a.oracle_seeds.split(",") if s]:
            t = time.process_time()
            arr, oregion, _ = O.oracle("three_sizes", seed, 50.0, "framed", 2.0, outl)
            t = time.process_time() - t
            cls = _classes(arr)
            w = window_stats(arr.xy, cls, geom)
            cv = (cell_cv(arr.xy, cls, geom, 0.5), cell_cv(arr.xy, cls, geom, 0.25))
            acc["oracle"][0].append(w)
            acc["oracle"][1].append(cv)
            c = oregion.geometry.centroid
            box = (c.x - 200, c.y - 200, c.x + 200, c.y + 200)
            row = {"source": "oracle", "seed": seed, "n": len(arr), "cpu_s": round(t, 1), "count_mean": w[:, :3].mean(0).round(2).tolist(),
                       "count_sd": w[:, :3].std(0).round(3).tolist(), "sl_median_sd": round(float(np.nanstd(w[:, 3])), 4), "large_cv_cells": cv,
                       "room_small": room_share(arr.xy, cls, radii, box)}
            out["rows"].append(row)
            print(f"oracle s{seed} n={len(arr)}; counts mean {row['count_mean']} sd {row['count_sd']}; S>L median sd {row['sl_median_sd']}; "
                  f"room {np.round(row['room_small'], 4)}", flush=True)
    for src, (rows, cvs) in acc.items():
        if rows:
            out["pooled"][src] = pooled(rows, cvs)
            print(src, json.dumps(out["pooled"][src]))
    if a.json:
        with open(a.json, "w") as f:
            json.dump(out, f, indent=1)
        print("figures written to", a.json)


if __name__ == "__main__":
    main()
