"""Helper s47p: per kind, elements per inner area over the exemplar's inner density right
after growth and at the end (as syn15_stages.py), and nn[small>small], for synth on chosen
--varied rows with constants or parameters changed.

    PYTHONPATH=src:benchmarks python benchmarks/s47p_knobs.py CLASS:LABEL[,..] SEEDS 'base' 'G.CONST=VAL;P.param=VAL' ...
    G: strew.synth._grow, PR: strew.synth._prepare, P: a synthesize keyword
"""
import os
import sys

import numpy as np
import shapely

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _variants
from _runner import fidelity_suite
from fresh17_rows import exemplar

import strew.synth._displace as DP
import strew.synth._grow as G
import strew.synth._prepare as PR
import strew.synth._thin as TH
from strew import Region
from strew.metrics import fidelity
from strew.synth import synthesize

LOG = {}


def ratios(state):
    prep = state.prep
    margin = 2.0 * float(prep.rc.max())
    dens = DP._inner_density(prep, margin)
    inner = state.region.geometry.buffer(-margin)
    vis = np.flatnonzero(~prep.void[state.src])
    p = state.pos[vis]
    ins = shapely.contains_xy(inner, p[:, 0], p[:, 1])
    k = prep.skind[state.src[vis[ins]]]
    return np.bincount(k, minlength=len(dens))[: len(dens)] / inner.area / dens


def wrap(mod, name, label):
    f = getattr(mod, name)

    def g(state, *a, **k):
        if label == "growth":
            LOG[label] = ratios(state)
            return f(state, *a, **k)
        r = f(state, *a, **k)
        LOG[label] = ratios(state)
        return r

    setattr(mod, name, g)


wrap(G, "_complete_anchor_rings", "growth")
wrap(TH, "thin_small", "end")
MODS = {"G": G, "PR": PR}


def main():
    specs, seeds, variants = sys.argv[1].split(","), _variants.ints(sys.argv[2]), sys.argv[3:]
    mk = fidelity_suite()
    orig = {}
    for var in variants:
        params = {}
        for kv in [x for x in var.split(";") if x and x != "base"]:
            name, val = kv.split("=")
            mod, attr = name.split(".")
            if mod == "P":
                params[attr] = eval(val)
            else:
                orig.setdefault((mod, attr), getattr(MODS[mod], attr))
                setattr(MODS[mod], attr, eval(val))
        tot = []
        for spec in specs:
            cls, label = spec.split(":")
            ex = exemplar(mk, cls, label)
            x0, y0, x1, y1 = ex.region.bounds
            for seed in seeds:
                LOG.clear()
                out = synthesize(ex, Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed, measure=False, **params)
                rep = fidelity(ex, out, eq5=False, local=False)
                m = rep.metrics["nn[small>small]"]
                fails = [f"{k}={v.value:.3g}/{v.tolerance:.3g}" for k, v in rep.metrics.items() if v.applicable and not v.passed]
                tot.append(rep.faithful)
                print(f"[{var}] {spec} s{seed} growth {np.round(LOG.get('growth', []), 3)} end {np.round(LOG.get('end', []), 3)} nn[s>s] {m.value:.3f}/{m.tolerance:.3f} {'pass' if rep.faithful else 'FAIL'} {' '.join(fails)}", flush=True)
        print(f"[{var}] {sum(tot)}/{len(tot)}", flush=True)
        for (mod, attr), v in orig.items():
            setattr(MODS[mod], attr, v)


if __name__ == "__main__":
    main()
