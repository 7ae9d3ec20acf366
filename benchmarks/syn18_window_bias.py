"""Helper syn18 (issue 13 point 1): how far the nn metric's border-filtered deciles of a frame the exemplar's size
sit from those of the output-sized frame, on the generator's own big draws (no synth involved).

Each big draw (3.5x side, svar13i_oracle.big_params, the exemplar's outlines) is cut into the 3 x 3 windows of the
exemplar's side (elements wholly inside, as make.py's _finish keeps them); nn[a>b] deciles as the metric takes them
(Hanisch filter: d <= distance to the frame, no 1/|W - d| weight) in each window against the whole draw's, in units
of the exemplar's s. A positive column: the big frame's neighbours are farther than a small frame reports.

    PYTHONPATH=TREE/src python benchmarks/syn18_window_bias.py CLASS:H:V A>B [--draws 3]
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
import shapely
from grow_variants import _harder_suite
from svar13i_oracle import big_params
from syn13z_rows import nnq
from synth_variants import _harder

from strew import Region
from strew.metrics import fidelity

args = [x for x in sys.argv[1:] if not x.startswith("--")]
draws = int(sys.argv[sys.argv.index("--draws") + 1]) if "--draws" in sys.argv else 3
args = [x for x in args if x != str(draws)]
name, i, v = args[0].split(":")
a, b = args[1].split(">")
kw = _harder()[name][int(i)]
mk = _harder_suite()
ex = mk.make_exemplar(name, rng=int(v), **kw)
s = fidelity(ex, ex, eq5=False, local=False).s
side = ex.region.bounds[2] - ex.region.bounds[0]
bp = big_params(name, kw, 3.5)
orig = mk._stone
print(f"{args[0]} s={s:.3f} side={side}; exemplar nn[{a}>{b}] deciles/s {np.round(nnq(ex, a, b) / s, 3)}")
allw, allb = [], []
for d in range(draws):
    sg = np.random.default_rng(int(v))
    mk._stone = lambda g, *x, **y: orig(sg, *x, **y)
    try:
        big = mk.make_exemplar(name, rng=int(v) + 1000 * (d + 1), **bp)
    finally:
        mk._stone = orig
    qb = nnq(big, a, b) / s
    allb.append(qb)
    geo = big.geometry
    for ix in range(3):
        for iy in range(3):
            box = shapely.box(ix * side, iy * side, (ix + 1) * side, (iy + 1) * side)
            keep = np.asarray(shapely.contains(box, geo))
            w = big.select(keep)
            w = w.replace(region=Region(box))
            try:
                qw = nnq(w, a, b) / s
            except Exception:
                continue
            allw.append(qw)
    print(f"draw {d}: whole {np.round(qb, 3)}; windows mean {np.round(np.mean(allw[-9:], 0), 3)}", flush=True)
W, B = np.mean(allw, 0), np.mean(allb, 0)
print(f"mean over {len(allw)} windows / {draws} draws: whole - window = {np.round(B - W, 3)}  (mean abs {np.mean(np.abs(B - W)):.4f})")
print(f"exemplar - window mean = {np.round(nnq(ex, a, b) / s - W, 3)}; window sd {np.round(np.std(allw, 0), 3)}")
