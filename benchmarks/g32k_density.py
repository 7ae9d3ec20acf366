"""g32k: sticks' density, grown against the exemplar, on several variant seeds (grow, fixed).

For each row (``v`` default, ``p0`` long thin sticks) at each variant seed: the judge's
density[stick] value and tolerance (eq5 and local off, as the audit), and the signed ratio
of elements per area, output over exemplar (whole frames: edges count in both).

    PYTHONPATH=src python benchmarks/g32k_density.py 19,20,21,22,23,24 1
"""
import sys
sys.path.insert(0, "benchmarks")
from fresh17_rows import exemplar
from _runner import fidelity_suite
from strew import Region
from strew.grow import grow
from strew.metrics import fidelity

mk = fidelity_suite()
seed = int(sys.argv[2])
for v in sys.argv[1].split(","):
    for lab in (f"v{v}", f"p0s{v}"):
        ex = exemplar(mk, "sticks", lab)
        x0, y0, x1, y1 = ex.region.bounds
        out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed)
        m = fidelity(ex, out, eq5=False, local=False).metrics["density[stick]"]
        ratio = (len(out) / (3.5 ** 2)) / len(ex)
        print(f"sticks {lab:6s} seed {seed}: n={len(out)} density {m.value:.3f}/{m.tolerance:.3f} {'pass' if m.passed else 'FAIL'} count/area ratio {ratio:.3f}", flush=True)
