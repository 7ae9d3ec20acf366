"""Helper fr: the suite's rings row at 2.2x its side (tests/grow/test_grow_fidelity.py, seed 1) with
the growth started at offsets from the region's centre: the hub lattice's phase against the judge's
window moves density[hub]. Printed per start: elements, density[hub], failing metrics (judged as the
test: eq5 and local off).

    PYTHONPATH=TREE/src python benchmarks/fr_rings_phase.py [SCALE]
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _runner import fidelity_suite

from strew import Region
from strew.grow import grow
from strew.metrics import fidelity


def main():
    sc = float(sys.argv[1]) if len(sys.argv) > 1 else 2.2
    ex = fidelity_suite().make_exemplar("rings")
    x0, y0, x1, y1 = ex.region.bounds
    W, H = sc * (x1 - x0), sc * (y1 - y0)
    ok = n = 0
    for dx in (0, 10, 20, 30):
        for dy in (0, 17):
            out = grow(ex, region=Region.rectangle(W, H), rng=1, start=(W / 2 + dx, H / 2 + dy))
            r = fidelity(ex, out, eq5=False, local=False)
            ok += r.faithful
            n += 1
            print(f"start +{dx},+{dy}: n={len(out)} density[hub] {r.metrics['density[hub]'].value:.3f}/{r.metrics['density[hub]'].tolerance:.3f} {' '.join(r.failures) or 'pass'}", flush=True)
    print(f"{ok}/{n} starts faithful  ({sys.modules['strew'].__file__})")


if __name__ == "__main__":
    main()
