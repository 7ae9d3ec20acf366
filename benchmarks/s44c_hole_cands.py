"""Helper s44c: which exemplar hubs fill_holes may copy (interior, complete ring) and their ring sizes.

    PYTHONPATH=src:benchmarks python benchmarks/s44c_hole_cands.py clusters:p2s27,clusters:v1,...
"""
import sys

import numpy as np

sys.path.insert(0, "benchmarks")
from _runner import fidelity_suite
from fresh17_rows import exemplar

from strew.synth._api import as_selection
from strew.synth._grow import anchors
from strew.synth._prepare import prepare

mk = fidelity_suite()
for spec in sys.argv[1].split(","):
    cls, label = spec.split(":")
    ex = exemplar(mk, cls, label)
    prep = prepare(as_selection(ex), k=5)
    sel = prep.selected_elements & ~prep.void
    interior = np.zeros(len(prep.kind), bool)
    interior[np.concatenate(prep.interior)] = True
    an = anchors(prep)
    par = prep.parent
    kids = np.bincount(par[(par >= 0) & sel], minlength=len(par))
    hubs = np.flatnonzero(kids > 0)
    cand = interior & sel & (an == 0) & (par != -3)
    allr = np.bincount(kids[hubs], minlength=12)
    print(f"{spec}: hubs {len(hubs)} (anchor {int(an[hubs].sum())}) ring sizes all {allr[1:12].tolist()}")
    print(f"   interior non-anchor hubs: ring sizes {np.bincount(kids[hubs[cand[hubs]]], minlength=12)[1:12].tolist()}")
    # depth: distance to frame
    dom = prep.domains[0]
    import shapely
    depth = shapely.distance(dom.exterior, shapely.points(prep.pos))
    reach = np.array([np.hypot(*(prep.pos[par == h] - prep.pos[h]).T).max() + prep.r[par == h].max() for h in hubs])
    whole = depth[hubs] > reach
    print(f"   hubs whose ring lies in the frame: ring sizes {np.bincount(kids[hubs[whole]], minlength=12)[1:12].tolist()}  n-cut kids {int((par == -3).sum())}")
    for h, w, rr in zip(hubs, whole, reach):
        print(f"     hub {h} kind {prep.kind[h]} kids {kids[h]} interior {interior[h]} depth {depth[h]:.1f} reach {rr:.1f} whole {w} anchor {an[h]} par {par[h]}")
