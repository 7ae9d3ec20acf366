"""Helper g3s2: screen the canopy's local gate on chosen three_sizes rows, with GrowParams overrides.

(canopy_local, canopy_local_margin, canopy_band exist only with
benchmarks/results/g3s2_rejected_canopy_local_share.patch applied: git apply it first.)

    PYTHONPATH=src python benchmarks/g3s2_screen.py three_sizes:suite:0,three_sizes:3:12 1-2 [canopy_local=None ...]

Prints per row and seed the verdict (fidelity, eq5 and local off, as grw14y_rows.py),
the failures, and the density per 1e4 of each kind, exemplar vs output (interior of
the frame, elements >= 2 median nn from the edge, as a rough check).
"""
import sys

sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import numpy as np
from grow_variants import HARDER, _harder_suite

from strew import Region
from strew.grow import grow
from strew.metrics import fidelity


def dens(arr, box):
    x0, y0, x1, y1 = box
    names = np.asarray(arr.kind_names)
    area = (x1 - x0) * (y1 - y0)
    return {k: 1e4 * float((names == k).sum()) / area for k in ("small", "medium", "large")}


mk = _harder_suite()
a, _, b = sys.argv[2].partition("-")
seeds = range(int(a), int(b or a) + 1)
kw = {}
for s in sys.argv[3:]:
    k, v = s.split("=")
    kw[k] = eval(v)
if kw:
    # GrowParams fields that grow() does not take: set on the params each _Grower gets
    from dataclasses import replace

    import strew.grow._growth as G

    _init = G._Grower.__init__

    def _patched(self, ref, params, *a, **k):
        _init(self, ref, replace(params, **kw), *a, **k)

    G._Grower.__init__ = _patched
for c in sys.argv[1].split(","):
    cls, i, v = c.split(":")
    ex = mk.make_exemplar(cls, rng=int(v)) if i == "suite" else mk.make_exemplar(cls, rng=int(v), **HARDER[cls][int(i)])
    x0, y0, x1, y1 = ex.region.bounds
    de = dens(ex, ex.region.bounds)
    ok = 0
    for seed in seeds:
        out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed)
        rep = fidelity(ex, out, eq5=False, local=False)
        fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
        do = dens(out, (0, 0, 3.5 * (x1 - x0), 3.5 * (y1 - y0)))
        nn = rep.metrics.get("nn[small>large]")
        ok += int(rep.faithful)
        print(f"  {c} s{seed}: {'pass' if rep.faithful else 'FAIL'} {fails} nn[s>l]={nn.value if nn else float('nan'):.3g} "
              + " ".join(f"{k} {do[k]:.2f}/{de[k]:.2f}" for k in de), flush=True)
    print(f"{c} {ok}/{len(seeds)} {kw}", flush=True)
