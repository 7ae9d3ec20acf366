"""s27t: what thin_orphans sees on clusters h3s9 (test_synth_syc16_orphans's case).

``PYTHONPATH=src python benchmarks/s27t_diag.py [SEED]``: the dot surplus before and after
``_thin.thin_orphans``, how many children it removes, and per output disc the number of dots
nearest it against the exemplar's distribution of ring sizes.
"""

from __future__ import annotations

import sys

sys.path.insert(0, "tests")
import numpy as np
import shapely
from scipy.spatial import cKDTree

from strew_testing import fidelity_suite, synth_inner_density_ratios
from strew.synth import _thin
from strew.synth._displace import _inner_density

CLUSTERS_H3 = {"large": 5.0, "small": 2.0, "cluster_spacing": 30.0, "ring_min": 4, "ring_max": 5}
seed = int(sys.argv[1]) if len(sys.argv) > 1 else 1
orig = _thin.thin_orphans


def stats(state, tag):
    prep = state.prep
    margin = 2.0 * float(prep.rc.max())
    inner = state.region.geometry.buffer(-margin)
    dens = _inner_density(prep, margin)
    src = state.src[: state.n]
    vis = ~prep.void[src]
    ins = shapely.contains_xy(inner, state.pos[: state.n, 0], state.pos[: state.n, 1])
    for k in range(len(dens)):
        if not np.isfinite(dens[k]):
            continue
        c = np.count_nonzero(vis & ins & (prep.skind[src] == k))
        print(tag, "kind", k, "count", c, "target", dens[k] * inner.area, "ratio", c / (dens[k] * inner.area))


def wrap(state, since=0):
    stats(state, "before")
    r = orig(state, since)
    print("thin_orphans removed", r)
    print("thin_crowded removed", _tc(state, since))
    stats(state, "after")
    prep = state.prep
    src = state.src[: state.n]
    par = prep.parent[src]
    kid = (par >= 0) & ~prep.void[src]
    hub = np.isin(np.arange(len(prep.pos)), prep.parent[prep.parent >= 0])[src] & ~prep.void[src]
    hubs = np.flatnonzero(hub)
    t = cKDTree(state.pos[hubs])
    j = t.query(state.pos[np.flatnonzero(kid)])[1]
    cnt = np.bincount(j, minlength=len(hubs))
    print("output ring sizes", np.bincount(cnt))
    sel = prep.selected_elements & ~prep.void
    ep = prep.parent[sel & (prep.parent >= 0)]
    print("exemplar ring sizes", np.bincount(np.bincount(ep)[np.unique(ep)]))
    return r


_thin.thin_orphans = wrap
_thin.THIN_CROWDED_DEBUG = True
_tc = _thin.thin_crowded
_thin.thin_crowded = lambda state, since=0: 0  # called (and reported) from wrap
ex = fidelity_suite().make_exemplar("clusters", rng=9, **CLUSTERS_H3)
print(synth_inner_density_ratios(ex, rng=seed))
