"""Helper ssz (issue 13 point 1): one --harder synth row in detail: every failing metric, per-kind density
(result / exemplar statistic), the nn deciles of chosen pairs (output - exemplar, in s) and the output's
elements per area by kind; writes the output to /tmp/ssz/CLASS_hHsV_seedN.json for later study.

    PYTHONPATH=TREE/src:benchmarks python benchmarks/ssz_row.py CLASS:H:V:SEEDS[+CLASS:H:V:SEEDS...] [A>B ...] [--set _prepare.NAME=VALUE]

H is a --harder index or pN (the VARIED then EDGE sets of benchmarks/_variants.py, as synth_variants --varied labels them).

``--set MOD.NAME=VALUE`` (repeatable) sets a constant of ``strew.synth.MOD`` first, for experiments.
"""
import sys
import time

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
from grow_variants import _harder_suite
from syn13z_rows import counts, nnq
from synth_variants import _harder, run

from strew.io import save
from strew.metrics import fidelity

import importlib

argv = sys.argv[1:]
while "--set" in argv:
    j = argv.index("--set")
    lhs, val = argv[j + 1].split("=")
    mod, nm = lhs.rsplit(".", 1)
    setattr(importlib.import_module(f"strew.synth.{mod}"), nm, type(getattr(importlib.import_module(f"strew.synth.{mod}"), nm))(val))
    print("set", lhs, "=", val)
    del argv[j : j + 2]
from _variants import EDGE, VARIED

specs, pairs = argv[0].split("+"), [p.split(">") for p in argv[1:]]
rows = []
for spec in specs:
    name, i, v, seeds = spec.split(":")
    kw = (VARIED.get(name, []) + EDGE.get(name, []))[int(i[1:])] if i.startswith("p") else _harder()[name][int(i)]
    ex = _harder_suite().make_exemplar(name, rng=int(v), **kw)
    rows += [(name, i, v, ex, int(x)) for x in seeds.split(",")]
for name, i, v, ex, seed in rows:
    t0 = time.process_time()
    out, _ = run(ex, 3.5, seed, None)
    dt = time.process_time() - t0
    try:
        save(out, f"/tmp/ssz/{name}_{i}s{v}_seed{seed}.json")
    except Exception as e:  # noqa: BLE001
        print("save failed", e)
    rep = fidelity(ex, out, eq5=False, local=False)
    fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
    hi = i if i.startswith("p") else f"h{i}"
    print(f"{name} {hi}s{v} seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} cpu {dt:.1f} {' '.join(fails)}")
    print(f"  per 1e4: exemplar {counts(ex, 0)} output (20 from the edge) {counts(out, 20)}")
    for k, m in rep.metrics.items():
        if k.startswith("density"):
            print(f"  {k}: out/ex {m.result / m.exemplar:.3f}  value {m.value:.3f} tol {m.tolerance:.3f}")
    for a, b in pairs:
        m = rep.metrics[f"nn[{a}>{b}]"]
        print(f"  nn[{a}>{b}] {m.value:.4f}/{m.tolerance:.4f} dec(out-ex)/s {np.round((nnq(out, a, b) - nnq(ex, a, b)) / rep.s, 2)}")
