"""Issue 13 point 1, helper anchor13k: where an nn[a>b] row fails. Deciles (10 % ... 90 %)
of the distance from each element of kind a to its nearest element of kind b (Hanisch
border rule, as ``strew.metrics.fidelity``), in the exemplar and in synth's output, in
units of the exemplar's median nearest-neighbour distance s; kind shares; and, for a = b,
how clumped the output's b elements are (share with a b neighbour within the exemplar's
10 % decile).

    python benchmarks/anchor13k_deciles.py NAME INDEX VSEED A B [--seeds 1,2] [--scale 3.5]
"""

from __future__ import annotations

import argparse
import sys

import numpy as np
import shapely
from scipy.spatial import cKDTree

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from grow_variants import _harder_suite  # noqa: E402
from synth_variants import _harder  # noqa: E402

from strew import Region  # noqa: E402
from strew.synth import synthesize  # noqa: E402


def nn_deciles(arr, a: str, b: str) -> np.ndarray:
    xy, kind = arr.xy, arr.kind
    ia, ib = arr.kinds.index(a), arr.kinds.index(b)
    pa, pb = np.flatnonzero(kind == ia), np.flatnonzero(kind == ib)
    d, j = cKDTree(xy[pb]).query(xy[pa], k=2)
    first = np.where(pb[j[:, 0]] == pa, d[:, 1], d[:, 0])
    x0, y0, x1, y1 = arr.region.bounds
    edge = shapely.distance(shapely.box(x0, y0, x1, y1).boundary, shapely.points(xy[pa]))
    return np.percentile(first[first < edge], np.arange(10, 100, 10))


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("name")
    ap.add_argument("index", type=int)
    ap.add_argument("vseed", type=int)
    ap.add_argument("a")
    ap.add_argument("b")
    ap.add_argument("--seeds", default="1,2")
    ap.add_argument("--scale", type=float, default=3.5)
    ar = ap.parse_args()
    kw = _harder()[ar.name][ar.index]
    ex = _harder_suite().make_exemplar(ar.name, rng=ar.vseed, **kw)
    d0, _ = cKDTree(ex.xy).query(ex.xy, k=2)
    s = float(np.median(d0[:, 1]))
    ed = nn_deciles(ex, ar.a, ar.b)
    print(f"{ar.name} {kw} s={s:.2f} shares {np.round(np.bincount(ex.kind) / len(ex), 3)}")
    print("exemplar", np.round(ed / s, 2))
    x0, y0, x1, y1 = ex.region.bounds
    for seed in [int(v) for v in ar.seeds.split(",")]:
        out = synthesize(ex, Region.rectangle(ar.scale * (x1 - x0), ar.scale * (y1 - y0)), rng=seed, measure=False)
        od = nn_deciles(out, ar.a, ar.b)
        print(f"seed {seed} ", np.round(od / s, 2), f"mean|diff| {np.mean(np.abs(od - ed)) / s:.3f} shares {np.round(np.bincount(out.kind) / len(out), 3)}")


if __name__ == "__main__":
    main()
