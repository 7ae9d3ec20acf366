"""Helper s60t: where `_grow._top_ahead` acts (issue 13 point 1).

    PYTHONPATH=src:benchmarks python benchmarks/s60t_ahead_probe.py [--run] SPEC ...

SPEC is ``p4s27`` / ``v29`` (--varied three_sizes) or ``h6s29`` (--harder), optionally
``:SEEDS`` (default 1). Without --run: the prep scan only (does `_own_setup` keep the
exemplar: would the rule be evaluated at all; cover, large-class density). With --run:
synthesizes at scale 3.5 and logs, per growth call where the closed area is measured,
area / exemplar inner frame, the count the density asks (want), the count (have), the
Poisson z of (have - SLACK*want) and whether ownership acted; then the verdict.
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np

import _variants
from _runner import fidelity_suite
from grow_variants import _harder_suite
from synth_variants import _harder, run

import strew.synth._grow as G
from strew.metrics import fidelity

LOG = []


def exemplar(label):
    if label.startswith("h"):
        i, _, v = label[1:].partition("s")
        return _harder_suite().make_exemplar("three_sizes", rng=int(v), **_harder()["three_sizes"][int(i)])
    mk = fidelity_suite()
    if label.startswith("v"):
        return mk.make_exemplar("three_sizes", rng=int(label[1:]))
    i, _, v = label[1:].partition("s")
    sets = _variants.VARIED.get("three_sizes", []) + _variants.EDGE.get("three_sizes", [])
    return mk.make_exemplar("three_sizes", rng=int(v), **sets[int(i)])


_orig = getattr(G, "_top_ahead", None)


def _logged(state):
    top, _a, cover, rate = G._own_setup(state.prep)
    out = _orig(state)
    if top.any() and state.n:
        prep = state.prep
        src = state.src[: state.n]
        vis = prep.selected_elements[src] & ~prep.void[src]
        got = G._closed_counts(state, vis)
        _reach, inner = G._empty_reach(prep)
        if got is not None:
            area, inside = got
            for s_ in np.flatnonzero(cover > 0):
                here = inside & (prep.source[src] == s_)
                share = np.count_nonzero(here) / max(np.count_nonzero(inside), 1)
                want = rate[s_] * area * share
                have = int(np.count_nonzero(top[src[here]]))
                LOG.append((area / inner, want, have, bool(out.any())))
        else:
            LOG.append((None, None, None, bool(out.any())))
    return out




def main():
    import os
    if "S60T_Z" in os.environ:
        G.OWN_AHEAD_Z = float(os.environ["S60T_Z"])
    G._top_ahead = _logged
    do_run = "--run" in sys.argv
    for spec in [a for a in sys.argv[1:] if not a.startswith("--")]:
        label, _, seeds = spec.partition(":")
        ex = exemplar(label)
        seeds = _variants.ints(seeds or "1")
        if not do_run:
            from strew.synth._api import new_state
            prep = new_state(ex).prep
            top, _a, cover, rate = G._own_setup(prep)
            print(f"{label}: kept={bool(top.any())} cover={cover.max():.3f} rate={rate.max():.5f} topcover={G._top_cover(prep).max():.3f}", flush=True)
            continue
        for seed in seeds:
            LOG.clear()
            out, _ = run(ex, 3.5, seed, None)
            rep = fidelity(ex, out, eq5=False, local=False)
            fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
            acts = sum(a for *_x, a in LOG)
            print(f"{label} seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} calls={len(LOG)} acted={acts} {' '.join(fails)}", flush=True)
            for fr, want, have, a in LOG:
                if fr is None:
                    continue
                z = (have - want) / np.sqrt(want) if want > 0 else 0
                print(f"    frames={fr:6.2f} want={want:7.1f} have={have:5d} ratio={have / max(want, 1e-9):.3f} z={z:+.2f} {'OWN' if a else ''}", flush=True)


if __name__ == "__main__":
    main()
