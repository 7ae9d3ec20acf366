"""Helper g37r: chosen grow rows with their empty_circle figure (pass or not) and the
hubs' widest interior holes.

    PYTHONPATH=src:benchmarks python benchmarks/g37r_rows.py rings:v27,rings:p1s27 1-3

As ``fresh17_rows.py grow`` (fixed mode, 3.5x, eq5 and local off), one line per seed:
verdict, count, empty_circle value/tolerance, failures, and the radius of the widest
empty circle of the output's hubs lying wholly inside the frame (a hub left out).
"""
import os
import sys
from types import SimpleNamespace

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _variants
from _runner import fidelity_suite
from fresh17_rows import exemplar
from grow_variants import run

from strew.grow._clusters import satellite_structure
from strew.metrics import fidelity


def widest_hub_hole(out, hub):
    """The widest empty circle of the output's hubs wholly inside its frame."""
    from scipy.spatial import Delaunay

    from strew._kernels.geometry import circumcircles

    p = out.xy[out.kind == hub]
    cen, r, _ = circumcircles(*(p[Delaunay(p).simplices[:, q]] for q in range(3)))
    inner = out.region.contains(cen) & (out.region.distance_to_boundary(cen) >= r)
    return float(r[inner].max()) if inner.any() else float("nan")


def main():
    specs, seeds = sys.argv[1], _variants.ints(sys.argv[2])
    mk = fidelity_suite()
    tot = n = 0
    for spec in specs.split(","):
        cls, label = spec.split(":")
        ex = exemplar(mk, cls, label)
        sat = satellite_structure(ex)
        for seed in seeds:
            out, _ = run(ex, 3.5, seed, SimpleNamespace(mode="fixed", times=10.0))
            rep = fidelity(ex, out, eq5=False, local=False)
            ec = rep.metrics["empty_circle"]
            fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
            hh = widest_hub_hole(out, sat.hub) if sat is not None else float("nan")
            print(f"  {spec} seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} empty_circle {ec.value:.3f}/{ec.tolerance:.3f} hub hole {hh:.1f} {' '.join(fails)}", flush=True)
            tot += int(rep.faithful)
            n += 1
    print(f"total {tot}/{n}", flush=True)


if __name__ == "__main__":
    main()
