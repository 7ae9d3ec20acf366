"""Helper gsz14n (issue 14 point 1): grow, fixed mode, on chosen ``--harder`` rows and the
fidelity suite's three sizes; per run the verdict, failing metrics, each kind's share
against the exemplar's and the relaxation's kind-mismatched Eq. 5 terms (edges whose
neighbour is of another kind than the ring slot it was paired with).

    PYTHONPATH=src python benchmarks/gsz14n_diag.py three_sizes:12:7,three_sizes:1:7 --seeds 1,2
    PYTHONPATH=src python benchmarks/gsz14n_diag.py suite --seeds 1-5     # fidelity.py's three sizes (3.5x, eq5 on)
    PYTHONPATH=src python benchmarks/gsz14n_diag.py slots --seeds 1-3     # test_grow_largest_slots' figure
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from grow_variants import HARDER, _harder_suite

from strew import Region
from strew.grow import grow
from strew.metrics import fidelity


def _seeds(t: str) -> list[int]:
    out = []
    for part in t.split(","):
        a, _, b = part.partition("-")
        out.extend(range(int(a), int(b or a) + 1))
    return out


def shares(ex, out) -> dict[str, float]:
    return {k: round(float(np.mean(out.kind == i)) / max(float(np.mean(ex.kind == i)), 1e-12), 2) for i, k in enumerate(ex.kinds)}


def main() -> None:
    p = argparse.ArgumentParser()
    p.add_argument("cases", help="name:index:variant,... | suite | slots")
    p.add_argument("--seeds", default="1,2")
    a = p.parse_args()
    mk = _harder_suite()
    seeds = _seeds(a.seeds)
    if a.cases == "slots":
        ex = mk.make_exemplar("three_sizes")
        x0, _, x1, _ = ex.region.bounds
        w = x1 - x0
        big = ex.kinds.index("large")
        m = 1.1 * ex.shapes["large"].radius
        ref = float((ex.kind == big).sum()) / (w - 2 * m) ** 2
        side = 2.2 * w
        region = Region.rectangle(side, side)
        kept = []
        for seed in seeds:
            out = grow(ex, region=region, rng=seed)
            inner = region.distance_to_boundary(out.xy) > 3 * m
            kept.append(round(float(((out.kind == big) & inner).sum()) / (side - 6 * m) ** 2 / ref, 3))
        print("largest slots kept", kept, "mean", round(float(np.mean(kept)), 3), flush=True)
        return
    if a.cases == "suite":
        items = [("three_sizes", None, None)]
    else:
        items = [(s.split(":")[0], int(s.split(":")[1]), int(s.split(":")[2])) for s in a.cases.split(",")]
    for name, i, v in items:
        if i is None:
            ex = mk.make_exemplar(name)
            sc, eq5 = 3.5, True
        else:
            ex = mk.make_exemplar(name, rng=v, **HARDER[name][i])
            sc, eq5 = 3.5, False
        x0, y0, x1, y1 = ex.region.bounds
        for seed in seeds:
            t = time.process_time()
            out = grow(ex, region=Region.rectangle(sc * (x1 - x0), sc * (y1 - y0)), rng=seed)
            rep = fidelity(ex, out, eq5=eq5, local=eq5)
            nn = {k: f"{m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and k.startswith("nn[") and m.value > 0.7 * m.tolerance}
            fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
            lab = f"{name} h{i}s{v}" if i is not None else name
            print(f"{lab} seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} {shares(ex, out)} fails {fails} near {nn} {time.process_time() - t:.1f}s", flush=True)


if __name__ == "__main__":
    main()
