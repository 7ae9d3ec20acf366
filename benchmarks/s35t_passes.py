"""Helper s35t: interior counts per kind (depth >= 2 largest collision radii) after each pass of synth's fill.

    PYTHONPATH=src:benchmarks python benchmarks/s35t_passes.py CLASS:H:V SEEDS

Wraps the passes grow() calls after region growing and prints, per seed, elements added and the
interior count per kind after each, with the exemplar's inner density times the interior area.
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
import shapely
from grow_variants import _harder_suite
from synth_variants import _harder

from strew import Region
from strew.synth import _displace, _farmix, _grow, _pebbles, _shell, _swap, _thin
from strew.synth import new_state, fill

name, i, v = sys.argv[1].split(":")
ex = _harder_suite().make_exemplar(name, rng=int(v), **_harder()[name][int(i)])
kn = np.asarray(ex.kind_names)
ST = {}


def report(tag):
    st = ST["s"]; p = st.prep
    margin = 2.0 * float(p.rc.max())
    inner = st.region.geometry.buffer(-margin)
    pos = st.pos[: st.n]; src = st._src[: st.n]
    ins = shapely.contains_xy(inner, pos[:, 0], pos[:, 1])
    c = {k: int(np.sum(ins & (kn[src] == k))) for k in sorted(set(kn))}
    dens = _displace._inner_density(p, margin)
    tgt = {kn[np.flatnonzero(p.skind == k)[0]]: round(float(dens[k] * inner.area)) for k in range(len(dens))}
    print(f"  {tag:24s} n={st.n} inner {c} target {tgt}", flush=True)


def wrap(mod, fname):
    f = getattr(mod, fname)
    def g(state, *a, **k):
        r = f(state, *a, **k)
        ST["s"] = state
        report(fname)
        return r
    setattr(mod, fname, g)


for mod, fn in [(_grow, "_complete_anchor_rings"), (_displace, "fill_displaced"), (_shell, "fill_beside_largest"),
                (_farmix, "trade_far_small"), (_farmix, "trade_far_top"), (_shell, "fill_beside_far_small"),
                (_grow, "fill_room"), (_pebbles, "fill_partners"), (_swap, "fill_swapped"), (_grow, "fill_holes"),
                (_thin, "thin_small"), (_thin, "thin_orphans"), (_thin, "thin_crowded"), (_thin, "thin_edge_strays")]:
    wrap(mod, fn)
x0, y0, x1, y1 = ex.region.bounds
for seed in [int(x) for x in sys.argv[2].split(",")]:
    st = new_state(ex, Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed)
    print(f"seed {seed}")
    fill(st)
