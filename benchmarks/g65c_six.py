"""Helper g65c: grow (fixed) on a ``--varied`` row as ``fresh17_rows.py`` runs it, printing g[disc,dot],
density[...] and the hubs' spread across the start's anti-diagonal (``fresh17_rows.py``'s SHOW splits on commas,
so it cannot name g[disc,dot] where that passes).

    PYTHONPATH=src:benchmarks python benchmarks/g65c_six.py clusters:p2s37 1-6
"""
import sys
from types import SimpleNamespace

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from _runner import fidelity_suite
from fresh17_rows import exemplar
from grow_variants import run

import strew
from strew.metrics import fidelity

cls, label = sys.argv[1].split(":")
ex = exemplar(fidelity_suite(), cls, label)
ok = n = 0
for seed in _variants.ints(sys.argv[2]):
    out, sc = run(ex, 3.5, seed, SimpleNamespace(mode="fixed", times=10.0))
    rep = fidelity(ex, out, eq5=False, local=False)
    shown = [f"{k}={m.value:.3g}/{m.tolerance:.3g}{'' if m.passed else '!'}" for k, m in rep.metrics.items() if m.applicable and (k.startswith(("g[", "density")) or not m.passed)]
    disc = out.kinds.index("disc") if "disc" in out.kinds else 0
    s = out.xy[out.kind == disc].sum(1)
    x0, y0, x1, y1 = out.region.bounds
    ok += int(rep.faithful)
    n += 1
    print(f"  grow {cls}:{label} seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} scale {sc:.2f} frame {x1 - x0:.0f} "
          f"discs {len(s)} x+y {s.min():.0f}-{s.max():.0f}  {' '.join(shown)}", flush=True)
print(f"grow {cls}:{label} {ok}/{n}  ({strew.__file__})")
