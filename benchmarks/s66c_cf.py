"""Helper s66c: counterfactual of synth's hole filling for clusters rows (monkeypatch, src untouched).

``_grow.fill_holes`` (with ``fill_far_hub_rooms`` inside it) clears a candidate at a hole's centre by
``max(rc_p + rc_q, prep.min_dist)``, and ``prep.min_dist`` is 0.95 x the exemplar's closest approach
(``_prepare``: slack for growth's copies). For hubs with rings (clusters' discs) that lets a hole take a disc
at 0.95 x the exemplar's closest disc spacing: clusters p4s39 (Poisson spacing 70, exemplar closest 70.2)
got 29 discs at nn 66.8-67.5 and its disc count per area 1.2x the exemplar's n/|W|. ``--hub-gap full`` runs
fill_holes with the hub kinds' own min_dist (hub kind to the same hub kind, kinds with ring children as
``_ring_size_shares`` finds them) divided back by 0.95: the exemplar's closest hub spacing, as
``fill_hub_rooms`` already keeps. Without the flag: the tree as it is (baseline).

``--hub-gap all``: the same for the whole synthesis (``_api.prepare`` wrapped: growth's collision test too).
``--ring-cv X`` sets ``_optimize.RING_CV`` to X (0.005 on the tree): clusters' dots (cv 0.020-0.023 to their
disc) then count as ring children, so the horizon optimisation keeps them at their exemplar distance from
their disc (``_optimize._keep_ring_radius``), and whatever else reads ``ring_children`` switches on too.

``--radial-cv X`` (narrower): only ``_optimize._keep_ring_radius`` (its call in the horizon optimisation,
before the guards) sees children at std / mean <= X as ring children; ``RING_CV`` stays 0.005 for every other
reader (``_grow``'s ring kids, ``sized_scatter``, the call after the guards).

    PYTHONPATH=src:benchmarks python benchmarks/s66c_cf.py clusters:p4s39,clusters:v35 1-6 [--hub-gap full] [--ring-cv 0.05] [--radial-cv 0.05]
"""
import functools
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from _runner import fidelity_suite
from fresh17_rows import exemplar
from synth_variants import run

import strew.synth._grow as G
from strew.metrics import fidelity

GAP = sys.argv[sys.argv.index("--hub-gap") + 1] if "--hub-gap" in sys.argv else None
FULL = GAP == "full"
_fh = G.fill_holes


@functools.wraps(_fh)
def fill_holes(state, *a, **k):
    prep = state.prep
    ring_n = G._ring_size_shares(prep)[0]
    hubs = np.unique(prep.skind[(ring_n > 0) & prep.selected_elements & ~prep.void])
    if not FULL or len(hubs) == 0:
        return _fh(state, *a, **k)
    keep = prep.min_dist.copy()
    for h in hubs:
        prep.min_dist[h, h] = keep[h, h] / 0.95
    try:
        return _fh(state, *a, **k)
    finally:
        prep.min_dist[...] = keep


G.fill_holes = fill_holes
if GAP == "all":
    import strew.synth._api as A
    _prep = A.prepare

    @functools.wraps(_prep)
    def prepare(*a, **k):
        prep = _prep(*a, **k)
        ring_n = G._ring_size_shares(prep)[0]
        for h in np.unique(prep.skind[(ring_n > 0) & prep.selected_elements & ~prep.void]):
            prep.min_dist[h, h] /= 0.95
        return prep

    A.prepare = prepare
CV = float(sys.argv[sys.argv.index("--ring-cv") + 1]) if "--ring-cv" in sys.argv else None
if CV is not None:
    import strew.synth._optimize as O
    O.RING_CV = CV
RCV = float(sys.argv[sys.argv.index("--radial-cv") + 1]) if "--radial-cv" in sys.argv else None
if RCV is not None:
    import strew.synth._optimize as O
    _rc, _krr, _IN = O.ring_children, O._keep_ring_radius, [False]

    def _loose(prep):
        """(n,) bool: ``ring_children`` at std / mean <= RCV (not cached on ``_ring_children``)."""
        got = getattr(prep, "_s66c_loose", None)
        if got is not None and len(got) == len(prep.kind):
            return got
        out = np.zeros(len(prep.kind), bool)
        has = np.flatnonzero((prep.parent >= 0) & ~prep.void)
        has = has[prep.size_class[prep.parent[has]] != prep.size_class[has]]
        if len(has):
            d = np.hypot(*(prep.pos[has] - prep.pos[prep.parent[has]]).T)
            pair = np.c_[prep.skind[has], prep.skind[prep.parent[has]]]
            _, inv = np.unique(pair, axis=0, return_inverse=True)
            inv = inv.ravel()
            for g in np.unique(inv):
                m = inv == g
                if m.sum() >= 3 and d[m].std() <= RCV * d[m].mean():
                    out[has[m]] = True
        prep._s66c_loose = out
        return out

    def _ring_children(prep):
        return _loose(prep) if _IN[0] else _rc(prep)

    @functools.wraps(_krr)
    def _keep(state, *a, **k):
        _IN[0] = True
        try:
            return _krr(state, *a, **k)
        finally:
            _IN[0] = False

    O.ring_children, O._keep_ring_radius = _ring_children, _keep


def main():
    mk = fidelity_suite()
    seeds = _variants.ints(sys.argv[2])
    for spec in sys.argv[1].split(","):
        cls, label = spec.split(":")
        ex = exemplar(mk, cls, label)
        res = []
        for seed in seeds:
            out, _ = run(ex, 3.5, seed, None)
            rep = fidelity(ex, out, eq5=False, local=False)
            show = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items()
                    if m.applicable and (not m.passed or k in ("g[disc,dot]", "density[disc]", "density[dot]"))]
            res.append(int(rep.faithful))
            print(f"  synth {spec} seed {seed} hub-gap={GAP or 'tree'} ring-cv={CV} radial-cv={RCV}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} {' '.join(show)}", flush=True)
        print(f"{spec} {sum(res)}/{len(res)}", flush=True)


if __name__ == "__main__":
    main()
