"""Issue 13 point 2 for noisy rows: does synth keep the exemplar's jitter?

Noisy rows of the fidelity suite (``examples/fidelity/make.py``: the default and
variants of other noise levels, spacings and row angles) fill a region ``--scale`` times
the frame's side (default 7.07: 50x the area). Printed per case and seed: the RMS
angular deviation of the interior bonds to the 4 nearest neighbours from the rows' axes
(degrees) and the coefficient of variation of their lengths, of the exemplar and of the
result, the global verdict, the share of failing windows of the local fidelity map and
the worst window's score (above 1 fails) and metric.

    python benchmarks/synth_jitter.py [--scale 7.07] [--seeds 1,2,3]
"""

from __future__ import annotations

import time

import numpy as np
from _runner import Bench, fidelity_suite, parse_args
from scipy.spatial import cKDTree

from strew import Region
from strew.metrics import fidelity
from strew.synth import synthesize

CASES = {
    "default": {},
    "noise0.02": dict(noise=0.02),
    "noise0.08": dict(noise=0.08),
    "s14_noise0.08": dict(spacing=14.0, noise=0.08),
    "angle0.3_noise0.04": dict(row_angle=0.3, noise=0.04),
    "s9_noise0.06_angle-0.5": dict(spacing=9.0, noise=0.06, row_angle=-0.5),
}


def jitter(xy: np.ndarray, angle: float) -> tuple[float, float]:
    """(RMS angular deviation of interior bonds from the rows' axes in degrees, CV of their lengths)."""
    tree = cKDTree(xy)
    d, j = tree.query(xy, k=5)
    s = float(np.median(d[:, 1]))
    lo, hi = xy.min(axis=0) + 2 * s, xy.max(axis=0) - 2 * s
    inner = np.all((xy > lo) & (xy < hi), axis=1)
    v = xy[j[inner, 1:]] - xy[inner, None, :]
    dev = (np.degrees(np.arctan2(v[..., 1], v[..., 0]) - angle) + 45.0) % 90.0 - 45.0
    length = d[inner, 1:]
    return float(np.sqrt(np.mean(dev**2))), float(length.std() / length.mean())


def main() -> None:
    def extra(p) -> None:
        p.add_argument("--scale", type=float, default=7.07, help="region side / exemplar frame side (7.07: 50x the area)")
        p.add_argument("--seeds", default="1,2,3", help="seeds, comma-separated")
        p.add_argument("--only", default=None, help="cases, comma-separated: " + ", ".join(CASES))

    args = parse_args(__doc__.splitlines()[0], extra)
    mk = fidelity_suite()
    seeds = [int(x) for x in args.seeds.split(",")]
    names = args.only.split(",") if args.only else list(CASES)
    bench = Bench("synth_jitter", f"synth: noisy rows' jitter at {args.scale:g}x the frame's side", baseline="the exemplar's own figures", json_path=args.json)
    for name in names:
        var = CASES[name]
        ex = mk.make_exemplar("rows_noisy", **var)
        angle = float(var.get("row_angle", 0.0))
        ang_ex, cv_ex = jitter(np.asarray(ex.xy, float), angle)
        x0, y0, x1, y1 = ex.region.bounds
        region = Region.rectangle(args.scale * (x1 - x0), args.scale * (y1 - y0))
        for seed in seeds:
            t0 = time.perf_counter()
            out = synthesize(ex, region, rng=seed, measure=False)
            dt = time.perf_counter() - t0
            ang, cv = jitter(np.asarray(out.xy, float), angle)
            rep = fidelity(ex, out, region, eq5=False)
            score = np.asarray(rep.local["score"], float)
            ok = np.isfinite(score)
            worst = rep.local["worst"] or {}
            bench.row(name, seed=seed, elements=len(out), angle_ex=round(ang_ex, 2), angle_out=round(ang, 2), angle_ratio=round(ang / ang_ex, 3),
                      cv_ex=round(cv_ex, 4), cv_out=round(cv, 4), faithful=rep.faithful,
                      failing_share=round(float(np.mean(score[ok] > 1.0)), 3) if ok.any() else None,
                      worst=round(float(worst.get("score", 0.0)), 3), worst_metric=worst.get("metric"), synth_s=round(dt, 2))
    bench.finish()


if __name__ == "__main__":
    main()
