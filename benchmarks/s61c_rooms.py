"""Helper s61c: after fill_holes on a far-clusters row (clusters p2s36), the exemplar's largest empty circle (fill_holes'
limit), its far hubs' spacing (closest, median nearest), the far hubs the output holds against _far_hub_room's cap,
and the rooms left among the output's hubs (Delaunay circumcircles of the far-hub kind, centre in the domain) at
least the exemplar's closest hub spacing wide.

    PYTHONPATH=src:benchmarks python benchmarks/s61c_rooms.py LABEL SEEDS
"""
import sys
import numpy as np
from scipy.spatial import cKDTree
sys.path.insert(0, __file__.rsplit("/", 1)[0])
from fresh17_rows import exemplar
from _runner import fidelity_suite
from synth_variants import run
import strew.synth._grow as G

label, seeds = sys.argv[1], [int(s) for s in sys.argv[2].split(",")]
ex = exemplar(fidelity_suite(), "clusters", label)
orig = G.fill_holes
def spy(state, room=None, since=0):
    prep = state.prep
    before = G._far_hub_room(state)
    got = orig(state, room, since)
    after = G._far_hub_room(state)
    far = prep._far_hubs & prep.selected_elements & ~prep.void
    k = int(prep.skind[far][0])
    p = prep.pos[far]
    d = cKDTree(p).query(p, 2)[0][:, 1]
    lec = G.largest_empty_circles(prep)[prep.selected]
    mine = np.flatnonzero((prep.skind[state.src] == k) & ~prep.void[state.src])
    cen, rad, tri = G.circumcircles(state.pos[mine])
    ok = state.in_domain(cen)
    rr = np.sort(rad[ok])[::-1]
    od = cKDTree(state.pos[mine]).query(state.pos[mine], 2)[0][:, 1]
    print(f"  limit {lec.max():.1f}; ex hubs {far.sum()} closest {d.min():.1f} median nn {np.median(d):.1f}; out hubs {len(mine)} nn median {np.median(od):.1f} min {od.min():.1f};"
          f" cap left before {before[k]} after {after[k]}; added {got}; rooms >= closest {np.count_nonzero(rr >= d.min())}, >= median nn {np.count_nonzero(rr >= np.median(d))}; widest {np.round(rr[:8], 1)}", flush=True)
    return got
G.fill_holes = spy
for seed in seeds:
    out, _ = run(ex, 3.5, seed, None)
    print(f"seed {seed} n={len(out)}", flush=True)
