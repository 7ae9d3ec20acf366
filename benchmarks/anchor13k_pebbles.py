"""Issue 13 point 1, helper anchor13k: where synth's pebbles stand on two-size exemplars
whose nn[pebble>pebble] fails (``--harder`` two_sizes h11s8, h12s7). For the exemplar and
the output (elements at least 2 s from the frame, s the exemplar's median nearest-neighbour
distance): kind shares and densities, the share of pebbles with no pebble within 1 s
("isolated"), the mean number of pebbles and stones within 1.3 s of a pebble, and the
share of isolated pebbles boxed in by stones (at least 3 stones within 1.3 s).

    python benchmarks/anchor13k_pebbles.py INDEX VSEED [--seeds 1,2] [--scale 3.5]
"""

from __future__ import annotations

import argparse
import sys

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from grow_variants import _harder_suite  # noqa: E402
from synth_variants import _harder  # noqa: E402

from strew import Region  # noqa: E402
from strew.synth import synthesize  # noqa: E402


def describe(arr, s: float) -> str:
    xy, kind = arr.xy, arr.kind
    st, pb = arr.kinds.index("stone"), arr.kinds.index("pebble")
    x0, y0, x1, y1 = arr.region.bounds
    inner = (xy[:, 0] > x0 + 2 * s) & (xy[:, 0] < x1 - 2 * s) & (xy[:, 1] > y0 + 2 * s) & (xy[:, 1] < y1 - 2 * s)
    area = (x1 - x0 - 4 * s) * (y1 - y0 - 4 * s)
    tp, ts = cKDTree(xy[kind == pb]), cKDTree(xy[kind == st])
    mine = inner & (kind == pb)
    n_p = tp.query_ball_point(xy[mine], 1.3 * s, return_length=True) - 1
    n_s = ts.query_ball_point(xy[mine], 1.3 * s, return_length=True)
    d, _ = tp.query(xy[mine], k=2)
    iso = d[:, 1] > 1.0 * s
    boxed = iso & (n_s >= 3)
    dens = [float(np.sum(inner & (kind == k)) / area * 1e4) for k in (st, pb)]
    return (f"pebble share {np.sum(mine) / max(np.sum(inner), 1):.3f} density stone {dens[0]:.2f} pebble {dens[1]:.2f} /1e4; "
            f"isolated {iso.mean():.3f}, pebbles/stones within 1.3s {n_p.mean():.2f}/{n_s.mean():.2f}, isolated boxed in {boxed.sum()}/{iso.sum()}")


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("index", type=int)
    ap.add_argument("vseed", type=int)
    ap.add_argument("--seeds", default="1,2")
    ap.add_argument("--scale", type=float, default=3.5)
    a = ap.parse_args()
    kw = _harder()["two_sizes"][a.index]
    ex = _harder_suite().make_exemplar("two_sizes", rng=a.vseed, **kw)
    d0, _ = cKDTree(ex.xy).query(ex.xy, k=2)
    s = float(np.median(d0[:, 1]))
    print(f"two_sizes {kw} vseed {a.vseed} s={s:.2f}")
    print("exemplar ", describe(ex, s))
    x0, y0, x1, y1 = ex.region.bounds
    for seed in [int(v) for v in a.seeds.split(",")]:
        out = synthesize(ex, Region.rectangle(a.scale * (x1 - x0), a.scale * (y1 - y0)), rng=seed, measure=False)
        print(f"seed {seed}   ", describe(out, s))


if __name__ == "__main__":
    main()
