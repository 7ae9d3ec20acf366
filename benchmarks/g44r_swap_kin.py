"""Helper g44r: the lone-larger swap (``strew.grow._lone_larger``) with and without its
own-kind guard (``LONE_KIN``) on chosen ``--varied`` rows: swaps made, swaps the guard
skipped, the smaller kind's nearest-own-kind deciles, the row's nn metrics and verdict.

    PYTHONPATH=src:benchmarks python benchmarks/g44r_swap_kin.py CLASS:LABEL[,...] SEEDS

Needs the guard: ``git apply benchmarks/results/g44r_rejected_swap_kin.patch`` (rejected, not in src).
"""
import os
import sys
from types import SimpleNamespace

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _variants
from _runner import fidelity_suite
from fresh17_rows import exemplar
from grow_variants import run

import strew.grow._lone_larger as L
from strew.metrics import fidelity

mk = fidelity_suite()
count = {"skip": 0, "swap": 0}
_guard, _swap = L._lone_kin, L._swap_one


def guard(g, o, a):
    out = _guard(g, o, a)
    count["skip"] += int(out)
    return out


def swap(g, o, a):
    out = _swap(g, o, a)
    count["swap"] += int(out)
    return out


L._lone_kin, L._swap_one = guard, swap
for spec in sys.argv[1].split(","):
    cls, label = spec.split(":")
    ex = exemplar(mk, cls, label)
    for kin in (None, 1.0):
        L.LONE_KIN = kin
        ok = 0
        seeds = _variants.ints(sys.argv[2])
        for seed in seeds:
            count.update(skip=0, swap=0)
            out, _ = run(ex, 3.5, seed, SimpleNamespace(mode="fixed", times=10.0))
            rep = fidelity(ex, out, eq5=False, local=False)
            nn = " ".join(f"{k}={m.value:.4f}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if k.startswith("nn[") and m.applicable)
            fails = [k for k, m in rep.metrics.items() if m.applicable and not m.passed]
            ok += int(rep.faithful)
            print(f"  {spec} LONE_KIN={kin} seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} swaps={count['swap']} skipped={count['skip']} {nn} fails={fails}", flush=True)
        print(f"{spec} LONE_KIN={kin} {ok}/{len(seeds)}", flush=True)
