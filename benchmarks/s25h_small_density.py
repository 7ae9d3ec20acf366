"""Helper s25h: small stones' inner density over their exemplar's (``_displace._inner_density``,
margin two of the largest collision radii) in synth's output at SCALE x the exemplar's side,
for three sizes exemplars COUNTS at variant seeds, synth seeds 1,2.

    PYTHONPATH=TREE/src:benchmarks python benchmarks/s25h_small_density.py 2.0 60,30,40:15 40,20,30:16
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
import shapely

from grow_variants import _harder_suite
from strew import Region
from strew.synth import synthesize
from strew.synth._api import as_selection
from strew.synth._displace import _inner_density
from strew.synth._prepare import prepare


def ratios(ex, out):
    prep = prepare(as_selection(ex, None))
    margin = 2.0 * float(prep.rc.max())
    dens = _inner_density(prep, margin)
    inner = out.region.geometry.buffer(-margin)
    ins = shapely.contains_xy(inner, out.xy[:, 0], out.xy[:, 1])
    return np.bincount(out.kind[ins], minlength=3) / inner.area / dens


scale = float(sys.argv[1])
mk = _harder_suite()
for spec in sys.argv[2:]:
    c, v = spec.split(":")
    counts = tuple(int(x) for x in c.split(","))
    ex = mk.make_exemplar("three_sizes", rng=int(v), counts=counts)
    x0, y0, x1, y1 = ex.region.bounds
    for seed in (1, 2):
        out = synthesize(ex, Region.rectangle(scale * (x1 - x0), scale * (y1 - y0)), rng=seed, measure=False)
        print(spec, "seed", seed, np.round(ratios(ex, out), 3), flush=True)
