"""Helper seam13g diagnostic (issue 13 point 2): three sizes at 50x the exemplar's area,
how often small stones stand far from every large one.

    python benchmarks/seam13g_gaps.py [--seeds 1,2,3,4,5,6,7,8] [--name three_sizes]
        [--json PATH]

For each seed: the share of the output's small stones (those at least the exemplar's
largest small-to-large distance inside the canvas) whose nearest large stone is farther
than the exemplar's 95th percentile of that distance (over its interior small stones,
0.05 by definition in the exemplar), and the windows failing the local fidelity map.
Run it against another tree with ``PYTHONPATH=<tree>/src``.
"""
import argparse
import json
import os
import sys
import time

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _runner import SKIPPED, fidelity_suite  # noqa: E402

import strew  # noqa: E402
from strew import Region  # noqa: E402
from strew.metrics import fidelity  # noqa: E402
from strew.synth import synthesize  # noqa: E402


def far_share(ex_xy, ex_kind, ex_box, out_xy, out_kind, out_box, small, large, q=0.95):
    """(threshold, reach, share of the output's small stones beyond it)."""
    d = cKDTree(ex_xy[ex_kind == large]).query(ex_xy[ex_kind == small])[0]
    xy = ex_xy[ex_kind == small]
    x0, y0, x1, y1 = ex_box
    edge = np.minimum.reduce([xy[:, 0] - x0, xy[:, 1] - y0, x1 - xy[:, 0], y1 - xy[:, 1]])
    d = d[d <= edge]  # border-corrected: the nearest large stone is the true one
    thr, reach = float(np.quantile(d, q)), float(d.max())
    sm = out_xy[out_kind == small]
    x0, y0, x1, y1 = out_box
    inner = np.minimum.reduce([sm[:, 0] - x0, sm[:, 1] - y0, x1 - sm[:, 0], y1 - sm[:, 1]]) >= reach
    do = cKDTree(out_xy[out_kind == large]).query(sm[inner])[0]
    return thr, reach, float(np.mean(do > thr))


def main() -> None:
    if "--quick" in sys.argv[1:]:
        print("seam13g_gaps: skipped: a diagnostic run at 50x (minutes)")
        sys.exit(SKIPPED)
    ap = argparse.ArgumentParser()
    ap.add_argument("--name", default="three_sizes")
    ap.add_argument("--seeds", default="1,2,3,4,5,6,7,8")
    ap.add_argument("--json", default=None)
    a = ap.parse_args()
    ex = fidelity_suite().make_exemplar(a.name)
    kinds = list(ex.kinds)
    small, large = kinds.index("small"), kinds.index("large")
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(7.07 * (x1 - x0), 7.07 * (y1 - y0))
    print("strew from", os.path.dirname(strew.__file__))
    res = {}
    for seed in [int(s) for s in a.seeds.split(",") if s]:
        t = time.process_time()
        out = synthesize(ex, region, rng=seed, measure=False)
        t = time.process_time() - t
        thr, reach, share = far_share(ex.xy, np.asarray(ex.kind), ex.region.bounds, out.xy, np.asarray(out.kind), region.bounds, small, large)
        score = np.asarray(fidelity(ex, out, region, eq5=False).local["score"], float)
        nf = int((score[np.isfinite(score)] > 1).sum())
        res[seed] = dict(far_share=share, failing=nf, worst=float(np.nanmax(score)), cpu=t)
        print(f"seed {seed}: small stones beyond q95 ({thr:.1f}) of small>large: {share:.4f} (exemplar 0.05); failing windows {nf}, worst {np.nanmax(score):.3f}")
    sh = [r["far_share"] for r in res.values()]
    print(f"far share mean {np.mean(sh):.4f} (min {np.min(sh):.4f}, max {np.max(sh):.4f}); failing windows total {sum(r['failing'] for r in res.values())}")
    if a.json:
        with open(a.json, "w") as f:
            json.dump(res, f, indent=1)


if __name__ == "__main__":
    main()
