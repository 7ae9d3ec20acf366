"""Helper s60w (issue 13's ring tiles): synth's rings at 600 x 500, no band of broken,
hubless rings where growth fronts meet?

For the suite's rings (``fidelity_suite().make_exemplar('rings')``, 10 tiles at radius
15) and the demo's (``strew.synth._exemplars.rings()``, 12 tiles at radius 16): tiles of
the interior (40 from the canvas's edge) further than radius + 3.5 from every hub
(hubless), the share of interior hubs with a whole ring (tiles within radius + 3.5:
exactly the exemplar's count), where the broken rings lie (a 4 x 4 grid of counts), and
the fidelity's global verdict and worst window (suite rings only).

    python benchmarks/s60w_rings600.py [--seeds 1,2,3] [--json F]
"""
import argparse
import json
import sys
from pathlib import Path

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _runner import SKIPPED, fidelity_suite

from strew import Region
from strew.metrics import fidelity
from strew.synth import synthesize
from strew.synth._exemplars import rings as demo_rings

if "--quick" in sys.argv[1:]:
    print("s60w_rings600: skipped: six 600 x 500 canvases (minutes)")
    sys.exit(SKIPPED)
ap = argparse.ArgumentParser()
ap.add_argument("--seeds", default="1,2,3")
ap.add_argument("--json", default=str(Path(__file__).resolve().parent / "results" / "s60w_rings600.json"))
a = ap.parse_args()
W, H = 600.0, 500.0
cases = {"suite": (fidelity_suite().make_exemplar("rings"), 15.0, 10), "demo": (demo_rings(), 16.0, 12)}
rows = []
for name, (ex, rad, ntile) in cases.items():
    for seed in [int(s) for s in a.seeds.split(",")]:
        region = Region.rectangle(W, H)
        out = synthesize(ex, region, rng=seed, measure=False)
        hub = out.kind == out.kinds.index("hub")
        xy = np.asarray(out.xy)
        inner = np.all((xy > 40.0) & (xy < np.array([W, H]) - 40.0), axis=1)
        reach = rad + 3.5
        d, _ = cKDTree(xy[hub]).query(xy[~hub & inner])
        hubless = xy[~hub & inner][d > reach]
        hi = hub & inner
        cnt = np.array([len(v) for v in cKDTree(xy[~hub]).query_ball_point(xy[hi], reach)])
        broken = xy[hi][cnt != ntile]
        grid = np.zeros((4, 4), int)
        for p in np.r_[broken, hubless]:
            grid[min(3, int(p[1] / H * 4)), min(3, int(p[0] / W * 4))] += 1
        r = {"exemplar": name, "seed": seed, "n": len(out), "hubs": int(hub.sum()), "interior_hubs": int(hi.sum()), "whole": round(float(np.mean(cnt == ntile)), 3),
                 "over": int(np.sum(cnt > ntile)), "hubless_tiles": len(hubless), "counts": np.bincount(cnt).tolist(), "where_rows_bottom_up": grid.tolist(),
                 "broken_xy": np.round(broken, 1).tolist(), "hubless_xy": np.round(hubless, 1).tolist()}
        if name == "suite":
            rep = fidelity(ex, out, region, eq5=False)
            S = np.asarray(rep.local["score"], float)
            r.update(faithful=bool(rep.faithful), failures=list(rep.failures), windows=int(np.isfinite(S).sum()), failing=int(np.nansum(S > 1.0)),
                     worst=round(float(rep.local["worst"]["score"]), 3), worst_metric=rep.local["worst"]["metric"])
        rows.append(r)
        print({k: v for k, v in r.items() if k not in ("broken_xy", "hubless_xy")}, flush=True)
        Path(a.json).write_text(json.dumps(rows, indent=1))
