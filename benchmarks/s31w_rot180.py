"""Helper s31w (issue 13 point 2): is synth's stripes bar-spacing gradient (bars' nearest-bar
distance larger in the canvas's lower half at 50x, every seed) the exemplar's or the
algorithm's? Synthesizes the suite exemplar as it is and turned by 180 degrees about its
frame's centre (the same texture process), and prints each kind's median nearest-same-kind
distance in the lower and upper halves, left and right halves of the output.

    PYTHONPATH=src python benchmarks/s31w_rot180.py [--name stripes] [--seeds 1-4] [--scale 7.07]
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _runner import fidelity_suite

from strew import Region
from strew.synth import synthesize


def halves(out) -> str:
    nm = np.asarray(out.kind_names)
    xy = out.xy
    c = xy.mean(0)
    parts = []
    for k in np.unique(nm):
        p = xy[nm == k]
        d = cKDTree(p).query(p, k=2)[0][:, 1]
        lo, le = p[:, 1] < c[1], p[:, 0] < c[0]
        parts.append(f"{k}: y lo/hi {np.median(d[lo]):.2f}/{np.median(d[~lo]):.2f} x lo/hi {np.median(d[le]):.2f}/{np.median(d[~le]):.2f}")
    return "; ".join(parts)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--name", default="stripes")
    ap.add_argument("--seeds", default="1-4")
    ap.add_argument("--scale", type=float, default=7.07)
    a = ap.parse_args()
    lo, _, hi = a.seeds.partition("-")
    seeds = range(int(lo), int(hi or lo) + 1)
    ex = fidelity_suite().make_exemplar(a.name)
    x0, y0, x1, y1 = ex.region.bounds
    turned = ex.replace(x=x0 + x1 - ex.x, y=y0 + y1 - ex.y, rotation=np.asarray(ex.rotation) + np.pi)
    region = Region.rectangle(a.scale * (x1 - x0), a.scale * (y1 - y0))
    for label, e in (("as is", ex), ("turned", turned)):
        for s in seeds:
            out = synthesize(e, region, rng=s, measure=False)
            print(f"{label:7s} s{s} n={len(out)} {halves(out)}", flush=True)


if __name__ == "__main__":
    main()
