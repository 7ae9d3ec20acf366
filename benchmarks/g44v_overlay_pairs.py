"""g44v: the overlap tests of a growth of 2,000 stones (relaxation on, seed 1): pairs
tested, pairs the certificate proves (no GEOS overlay), and the CPU of the test on the
very pairs the growth asked, with the overlay alone (main) and with the certificate
(this tree), best of 7 replays; deterministic counts, a microbenchmark for the time.

Run: ``PYTHONPATH=src python benchmarks/g44v_overlay_pairs.py``
"""

from __future__ import annotations

import time

import numpy as np
import shapely

import strew.grow._collide as C
from strew.grow import analyze, grow
from strew.grow._exemplars import stone_exemplar
from strew.grow._overlap_kernels import overlap_certain

calls = []
orig = C._big_overlaps


def spy(A, B):
    calls.append((A, B))
    return orig(A, B)


C._big_overlaps = spy
ref = analyze(stone_exemplar())
grow(ref, count=2000, rng=1, relax=True)
C._big_overlaps = orig
pairs = sum(len(B) for _, B in calls)


def overlay(A, B):
    return C._area(C._intersection(A, B)) > 1e-9 * np.maximum(C._area(A), 1e-300)


proved = 0
for A, B in calls:
    a = A if isinstance(A, np.ndarray) else np.full(len(B), A, dtype=object)
    ok = overlay(a, B)
    got = orig(A, B)
    assert (ok == got).all()
    oa = np.r_[0, np.cumsum(shapely.get_num_coordinates(a))].astype(np.int64)
    ob = np.r_[0, np.cumsum(shapely.get_num_coordinates(B))].astype(np.int64)
    cert = np.zeros(len(B), dtype=bool)
    overlap_certain(shapely.get_coordinates(a), oa, shapely.get_coordinates(B), ob, cert)
    proved += int(cert.sum())
print(f"stones 2000 relax on, seed 1: {len(calls)} calls of the overlap test, {pairs} pairs; {proved} proved by the certificate "
      f"({proved / max(pairs, 1):.1%}), {pairs - proved} to the overlay")
for name, f in (("overlay alone (main)", lambda A, B: overlay(A if isinstance(A, np.ndarray) else np.full(len(B), A, dtype=object), B)),
                ("certificate, then overlay (this)", orig)):
    best = np.inf
    for _ in range(7):
        c = time.process_time()
        for A, B in calls:
            f(A, B)
        best = min(best, time.process_time() - c)
    print(f"{name:34s} {best * 1e3:7.1f} ms CPU for all the growth's pairs")
