"""Helper s32t: nearest centre neighbour's relative turn, exemplar against synth's output.

    PYTHONPATH=src python benchmarks/s32t_nn_angle.py sticks:p1s19,sticks:p1s20 1

Per row and seed (one-kind rows; interior elements, 1.5 s from the frame): the share of
elements whose nearest centre neighbour is turned less than 20 degrees from them (near
parallel), the median nn distance over ``s`` of near-parallel and of other pairs, and
the share with nn below 0.8 s.
"""
import os
import sys

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _variants  # noqa: E402
from _runner import fidelity_suite  # noqa: E402
from fresh17_rows import exemplar  # noqa: E402
from synth_variants import run  # noqa: E402


def stats(arr, s):
    xy, th = np.asarray(arr.xy, float), np.asarray(arr.rotation, float)
    d, j = cKDTree(xy).query(xy, 2)
    d, j = d[:, 1] / s, j[:, 1]
    x0, y0, x1, y1 = arr.region.bounds
    inner = (xy[:, 0] > x0 + 1.5 * s) & (xy[:, 0] < x1 - 1.5 * s) & (xy[:, 1] > y0 + 1.5 * s) & (xy[:, 1] < y1 - 1.5 * s)
    t = np.abs((th - th[j] + np.pi / 2) % np.pi - np.pi / 2)
    par = t < np.radians(20)
    d, par = d[inner], par[inner]
    return f"parallel {par.mean():.3f} nn|par {np.median(d[par]):.3f} nn|other {np.median(d[~par]):.3f} nn<0.8 {np.mean(d < 0.8):.3f}"


mk = fidelity_suite()
for spec in sys.argv[1].split(","):
    cls, label = spec.split(":")
    ex = exemplar(mk, cls, label)
    s = np.sqrt((lambda b: (b[2] - b[0]) * (b[3] - b[1]))(ex.region.bounds) / len(ex))
    print(f"{spec} exemplar          {stats(ex, s)}", flush=True)
    for seed in _variants.ints(sys.argv[2]):
        out, _ = run(ex, 3.5, seed, None)
        print(f"{spec} output seed {seed}    {stats(out, s)}", flush=True)
