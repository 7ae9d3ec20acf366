"""Helper s36m (issue 13 point 1): is a kind's share near the exemplar's frame the generator's or chance?

    PYTHONPATH=src:benchmarks python benchmarks/s36m_frame_share.py CLASS H[,H..] V[,V..] [BAND]

For each --harder exemplar CLASS:H:V prints per kind: count, the share of its elements within BAND
(default 12.3) of the frame, and the share of the domain's area in that band (what a uniform kind
would have), plus the share within r-bar (no interior candidate of the kind there).
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
import shapely
from grow_variants import _harder_suite
from synth_variants import _harder

name = sys.argv[1]
hs = [int(x) for x in sys.argv[2].split(",")]
vs = [int(x) for x in sys.argv[3].split(",")]
band = float(sys.argv[4]) if len(sys.argv) > 4 else 12.3
for h in hs:
    for v in vs:
        ex = _harder_suite().make_exemplar(name, rng=v, **_harder()[name][h])
        kn = np.asarray(ex.kind_names)
        xy = np.asarray(ex.xy)
        g = ex.region.geometry
        depth = shapely.distance(g.boundary, shapely.points(xy))
        rbar = np.asarray(ex["neighborhood_radius"], float) if "neighborhood_radius" in ex else None
        area_band = 1 - g.buffer(-band).area / g.area
        row = [f"h{h}s{v} band-area {area_band:.2f}"]
        for k in sorted(set(kn)):
            m = kn == k
            row.append(f"{k} n={m.sum()} band {np.mean(depth[m] < band):.2f}")
        print("  ".join(row))
