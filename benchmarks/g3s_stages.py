"""Helper g3s: which stage of grow's fixed-mode growth makes a --harder row fail.

    PYTHONPATH=src python benchmarks/g3s_stages.py three_sizes:3:12,three_sizes:10:12 1,2

Each row is grown with the passes after the main growth switched off in turn
(``holes``: fill_void_holes / open holes; ``lone``: swap_lone_larger, move_lone_smaller,
reseed_lone_kin) and judged as the audit (eq5 and local off); printed: failing metrics
and the values of the named ones.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from grow_variants import HARDER, _harder_suite

import strew.grow._growth as G
from strew import Region
from strew.grow import grow
from strew.metrics import fidelity

SAVED = dict(fill_void_holes=G.fill_void_holes, lone_kinds=G.lone_kinds, swap_lone_larger=G.swap_lone_larger, move_lone_smaller=G.move_lone_smaller, reseed_lone_kin=G.reseed_lone_kin)
OFF = {
    "full": {},
    "no-holes": dict(fill_void_holes=lambda g: False),
    "no-lone": dict(lone_kinds=lambda g: False),
    "no-larger": dict(swap_lone_larger=lambda g: False),
    "no-smaller": dict(move_lone_smaller=lambda g: False),
    "no-kin": dict(reseed_lone_kin=lambda g: False),
    "neither": dict(fill_void_holes=lambda g: False, lone_kinds=lambda g: False),
}


def main():
    mk = _harder_suite()
    show = sys.argv[3].split(",") if len(sys.argv) > 3 else []
    for spec in sys.argv[1].split(","):
        cls, i, v = spec.split(":")
        ex = mk.make_exemplar(cls, rng=int(v), **HARDER[cls][int(i)])
        x0, y0, x1, y1 = ex.region.bounds
        for seed in [int(s) for s in sys.argv[2].split(",")]:
            for name, off in OFF.items():
                for k, f in SAVED.items():
                    setattr(G, k, off.get(k, f))
                out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed)
                rep = fidelity(ex, out, eq5=False, local=False)
                fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
                vals = [f"{k}={rep.metrics[k].value:.3g}" for k in show if k in rep.metrics]
                print(f"{spec} s{seed} {name:>10} n={len(out)} {'pass' if not fails else 'FAIL'} {fails} {vals}", flush=True)


if __name__ == "__main__":
    main()
