"""s46w: which audit exemplars _prepare.UNCUT_NN changes at all (free space compared
with the switch on and off). An unchanged one synthesizes identically, so its audit
row equals main's.

    python benchmarks/s46w_scan.py VARIANT_SEEDS   (e.g. 29-32)
"""
from __future__ import annotations

import sys

import _variants
import numpy as np
import synth_variants as SV
from _runner import fidelity_suite
from grow_variants import _harder_suite

import strew.synth._prepare as P
from strew.synth._api import as_selection

seeds = _variants.ints(sys.argv[1])
only = sys.argv[2].split(",") if len(sys.argv) > 2 else None


def key(prep):
    return np.r_[prep.free_ptr, prep.free_off.ravel(), prep.free_cover, prep.free_r]


def changed(ex):
    P.UNCUT_NN = True
    a = key(P.prepare(as_selection(ex), k=5))
    P.UNCUT_NN = False
    b = key(P.prepare(as_selection(ex), k=5))
    P.UNCUT_NN = True
    return not (len(a) == len(b) and np.array_equal(a, b))


mk = fidelity_suite()
names = only or [n for n in mk.NAMES if n != "sticks"]
for name in names:
    _variants.VARIED_SEEDS = tuple(seeds)
    for label, tag, v, kw in _variants.cases(name, seeds, True):
        print("varied", name, label, "CHANGED" if changed(mk.make_exemplar(name, rng=v, **kw)) else "same", flush=True)
hmk = _harder_suite()
SV.HARDER_VARIANTS = tuple(seeds)
for name in names:
    for label, tag, v, kw in SV._harder_cases(name, seeds, False):
        print("harder", name, label, "CHANGED" if changed(hmk.make_exemplar(name, rng=v, **kw)) else "same", flush=True)
