"""Helper s28h (issue 13 point 1): fate of each size class during synth's growth on one --harder row:
elements added by kind (growth's copies, later passes) and removed (yielding, ``_evict``; later thinning),
and the final count; counts over the whole output.

    PYTHONPATH=TREE/src:benchmarks python benchmarks/s28h_fate.py CLASS:H:V:SEEDS [--set _grow.NAME=VALUE]
"""
import importlib
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
from grow_variants import _harder_suite
from synth_variants import _harder, run

import strew.synth._grow as G
from strew.metrics import fidelity
from strew.synth._state import SynthState

argv = sys.argv[1:]
while "--set" in argv:
    j = argv.index("--set")
    lhs, val = argv[j + 1].split("=")
    mod, nm = lhs.rsplit(".", 1)
    m = importlib.import_module(f"strew.synth.{mod}")
    setattr(m, nm, type(getattr(m, nm))(val))
    print("set", lhs, "=", val)
    del argv[j : j + 2]
name, i, v, seeds = argv[0].split(":")
ex = _harder_suite().make_exemplar(name, rng=int(v), **_harder()[name][int(i)])
LOG = {"added": [], "removed": [], "evicted": []}
PHASE = ["grow"]
_add, _remove, _evict = SynthState.add, SynthState.remove, G._evict


def add(self, src, pos, **kw):
    idx = _add(self, src, pos, **kw)
    LOG["added"].append((PHASE[0], self.prep.skind[np.asarray(src)].copy()))
    return idx


def remove(self, mask):
    LOG["removed"].append((PHASE[0], self.prep.skind[self.src[np.asarray(mask, bool)[: self.n]]].copy()))
    return _remove(self, mask)


_car = G._complete_anchor_rings


def car(state, *a, **k):
    PHASE[0] = "after"
    return _car(state, *a, **k)


SynthState.add, SynthState.remove, G._complete_anchor_rings = add, remove, car
kinds = list(ex.kinds)
for seed in [int(x) for x in seeds.split(",")]:
    for k in LOG:
        LOG[k].clear()
    PHASE[0] = "grow"
    out, _ = run(ex, 3.5, seed, None)
    rep = fidelity(ex, out, eq5=False, local=False)
    S = len(kinds)
    row = {}
    for key in ("added", "removed"):
        for ph in ("grow", "after"):
            ks = [a for p, a in LOG[key] if p == ph]
            row[f"{key}/{ph}"] = np.bincount(np.concatenate(ks), minlength=S)[:S] if ks else np.zeros(S, int)
    fin = np.bincount(np.asarray(out.kind), minlength=S)
    exn = np.bincount(np.asarray(ex.kind), minlength=S)
    print(f"{name} h{i}s{v} seed {seed} {'pass' if rep.faithful else 'FAIL'} kinds {kinds} exemplar {exn} final {fin} final/exemplar/{len(out)/len(ex):.2f} {np.round(fin / exn / (len(out) / len(ex)), 3)}")
    for k, a in row.items():
        print(f"   {k:14s} {a}")
