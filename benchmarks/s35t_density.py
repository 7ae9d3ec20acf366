"""Helper s35t: per-kind density (per 1e4) by distance band from the frame: exemplar, generator at 3.5x, synth output.

    PYTHONPATH=src:benchmarks python benchmarks/s35t_density.py CLASS:H:V SEEDS [DRAWS]

Bands: [0,15), [15,30), >=30 (elements by their centre's distance to the frame, band area).
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
import shapely
from grow_variants import _harder_suite
from svar13i_oracle import big_params
from synth_variants import _harder, run

name, i, v = sys.argv[1].split(":")
seeds = [int(x) for x in sys.argv[2].split(",")]
draws = int(sys.argv[3]) if len(sys.argv) > 3 else 1
kw = _harder()[name][int(i)]
mk = _harder_suite()
ex = mk.make_exemplar(name, rng=int(v), **kw)
BANDS = ((0, 15), (15, 30), (30, 1e9))


def bands(arr):
    g = arr.region.geometry
    xy = np.asarray(arr.xy); kn = np.asarray(arr.kind_names)
    dep = shapely.distance(g.boundary, shapely.points(xy))
    out = {}
    for lo, hi in BANDS:
        ring = g.buffer(-lo).difference(g.buffer(-hi)) if hi < 1e8 else g.buffer(-lo)
        m = (dep >= lo) & (dep < hi)
        out[f"{lo}-{hi if hi < 1e8 else 'inf'}"] = {k: round(float(np.sum(m & (kn == k)) / ring.area * 1e4), 2) for k in sorted(set(kn))}
    return out


print("exemplar", bands(ex))
orig = mk._stone
bp = big_params(name, kw, 3.5)
for d in range(draws):
    sg = np.random.default_rng(int(v))
    mk._stone = lambda g, *x, **y: orig(sg, *x, **y)
    try:
        big = mk.make_exemplar(name, rng=int(v) + 1000 * (d + 1), **bp)
    finally:
        mk._stone = orig
    print(f"generator draw {d}", bands(big))
for s in seeds:
    out, _ = run(ex, 3.5, s, None)
    print(f"synth seed {s}", bands(out))
