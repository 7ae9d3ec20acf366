"""Helper fr: is the suite's rings row at 2.2x (tests/grow/test_grow_fidelity.py) limited by the
region's edge? The class's generator drawn over the same region (4 draws), judged as the test
judges grow, once cropped by centres (as the exemplar's frame) and once keeping only elements
wholly inside (as grow must): density[hub] of each.

    PYTHONPATH=src python benchmarks/fr_rings_edge_oracle.py [SCALE]
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import numpy as np
from _runner import fidelity_suite

from strew import Region
from strew.metrics import fidelity


def main():
    sc = float(sys.argv[1]) if len(sys.argv) > 1 else 2.2
    mk = fidelity_suite()
    ex = mk.make_exemplar("rings")
    x0, y0, x1, y1 = ex.region.bounds
    W, H = sc * (x1 - x0), sc * (y1 - y0)
    region = Region.rectangle(W, H)
    for d in range(4):
        n = int(np.ceil(sc * 4)) + 2
        big = mk.make_exemplar("rings", rng=1000 + d, nx=n, ny=n + n % 2)
        bx0, by0, _, _ = big.region.bounds
        xy = np.c_[big.x, big.y] - [bx0, by0]
        inside = (xy[:, 0] > 0) & (xy[:, 0] < W) & (xy[:, 1] > 0) & (xy[:, 1] < H)
        moved = big.select(np.flatnonzero(inside))
        crop = type(moved)(moved.shapes, moved.kind, moved.x - bx0, moved.y - by0, moved.rotation, moved.scale, region=region)
        whole = crop.select(np.flatnonzero(region.contains_geometry(crop.geometry, tolerance=1e-9)))
        for name, arr in (("crop by centres", crop), ("wholly inside", whole)):
            rep = fidelity(ex, arr, eq5=False, local=False)
            m = rep.metrics["density[hub]"]
            print(f"draw {d} {name:16s} n={len(arr)} density[hub] {m.value:.3f}/{m.tolerance:.3f} {'pass' if rep.faithful else 'FAIL ' + ' '.join(rep.failures)}", flush=True)


if __name__ == "__main__":
    main()
