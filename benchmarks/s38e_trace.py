"""Helper s38e: the output's empty-circle q95 (as ``strew.metrics.fidelity`` counts it) after each pass of synth's fill.

    PYTHONPATH=src:benchmarks python benchmarks/s38e_trace.py CLASS:H:V SEEDS

Wraps the passes grow() calls after region growing (as ``s35t_passes.py``) and prints,
per seed, the element count and the q95 / max of the output's empty circles (Delaunay
circumradii of the visible centres, centred in the region, wholly inside it) against
the exemplar's.
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
from strew.synth._grow import circumcircles

name, i, v = sys.argv[1].split(":")
ex = _harder_suite().make_exemplar(name, rng=int(v), **_harder()[name][int(i)])
ST = {}


def q(xy, g):
    cen, rad, _ = circumcircles(xy)
    ins = shapely.contains_xy(g, cen[:, 0], cen[:, 1])
    ins[ins] = shapely.distance(g.boundary, shapely.points(cen[ins])) >= rad[ins]
    return rad[ins]


er = q(np.asarray(ex.xy), ex.region.geometry)
print(f"exemplar q95 {np.quantile(er, 0.95):.2f} max {er.max():.2f}")


def report(tag):
    st = ST["s"]
    vis = ~st.prep.void[st.src[: st.n]]
    r = q(st.pos[: st.n][vis], st.region.geometry)
    print(f"  {tag:24s} n={st.n} q95 {np.quantile(r, 0.95):.2f} q99 {np.quantile(r, 0.99):.2f} max {r.max():.2f}", flush=True)


def wrap(mod, fname):
    f = getattr(mod, fname)

    def g(state, *a, **k):
        ST["s"] = state
        if fname == "_complete_anchor_rings":
            report("after growth")
        out = f(state, *a, **k)
        report(fname)
        return out
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
    ST["s"] = st
    report("end")
