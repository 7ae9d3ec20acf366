"""Helper s66c: ring radius of synth's ring dots right after growth (clusters rows), split by where each dot
came from: a copy of a dot of the ring of the exemplar disc that the output disc copies ("own"), of another
exemplar disc's ring ("other"), and, for those, by how far their source dot's parent lies from the dot's
output disc (as a copy, the parent sits at its exemplar offset from the dot). src untouched.

    PYTHONPATH=src:benchmarks python benchmarks/s66c_radius.py clusters:p4s39 1 [--hub-gap full]
"""
import functools
import sys

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from _runner import fidelity_suite
from fresh17_rows import exemplar
from synth_variants import run

import strew.synth._grow as G

if "--hub-gap" in sys.argv:
    import s66c_cf  # noqa: F401
EDGE = 1.4 * 10.77
_car = G._complete_anchor_rings


@functools.wraps(_car)
def car(state, *a, **k):
    prep = state.prep
    keep = np.flatnonzero(~state.ghost)
    pos, src = state.pos[keep], state.src[keep]
    kind = prep.kind[src]
    di, do = np.flatnonzero(kind == 0), np.flatnonzero(kind == 1)
    d, j = cKDTree(pos[di]).query(pos[do])
    m = d < 25.0
    d, j, do = d[m], j[m], do[m]
    par = prep.parent[src[do]]
    own = par == src[di][j]
    exr = np.where(par >= 0, np.hypot(*(prep.pos[src[do]] - prep.pos[np.maximum(par, 0)]).T), np.nan)  # the source dot's own ring radius
    for tag, s in (("own", own), ("other", ~own & (par >= 0)), ("no parent", par < 0)):
        if s.sum():
            print(f"   after growth, {tag}: {int(s.sum())} dots, radius p5/50/95 {np.percentile(d[s], [5, 50, 95]).round(2)} >=1.4s {np.mean(d[s] >= EDGE):.3f};"
                  f" |radius - source ring radius| p50/p95 {np.nanpercentile(np.abs(d[s] - exr[s]), [50, 95]).round(2)}", flush=True)
    return _car(state, *a, **k)


G._complete_anchor_rings = car


def main():
    mk = fidelity_suite()
    cls, label = sys.argv[1].split(":")
    ex = exemplar(mk, cls, label)
    for seed in _variants.ints(sys.argv[2]):
        print(f" {sys.argv[1]} seed {seed}", flush=True)
        run(ex, 3.5, seed, None)


if __name__ == "__main__":
    main()
