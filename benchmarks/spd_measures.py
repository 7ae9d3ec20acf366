"""The flow measures' share of a flow growth, cKDTree against ``_near_kernels``
(issue 14 point 5): the ``hexflow`` case of ``benchmarks/grow.py --against``, relaxation
on. One growth records the arguments of every call to ``ball_counts`` and ``far_from``;
then, in the same process, each call is timed (CPU, best of ``reps``) both ways -- the
cKDTree queries the kernels replaced, and the kernels -- and the answers compared. A
machine shared with other jobs skews whole-growth ratios; this times the same inputs
side by side.

Run: ``PYTHONPATH=src python benchmarks/spd_measures.py [reps]``.
"""

from __future__ import annotations

import json
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))

from spd15_sample import case_kwargs
from scipy.spatial import cKDTree

import strew.grow._near_kernels as nk
from strew.grow import _flow_densify, _flow_net, _flow_retry, _flow_shear, analyze, grow
from strew.grow._exemplars import hex_exemplar


def _old_counts(p, q, a, b):
    t = cKDTree(p)
    return (np.asarray(t.query_ball_point(q, a, return_length=True), dtype=int),
            np.asarray(t.query_ball_point(q, b, return_length=True), dtype=int))


def _old_far(p, q, r):
    return cKDTree(p).query(q, distance_upper_bound=r)[0] > r


def main() -> None:
    reps = int(sys.argv[1]) if len(sys.argv) > 1 else 5
    ref = analyze(hex_exemplar())
    kw = case_kwargs("hexflow", ref)
    grow(ref, rng=1, relax=True, **kw)  # kernels compiled or loaded
    calls: list[tuple] = []
    real_b, real_f = nk.ball_counts, nk.far_from

    def rec_b(p, q, a, b):
        calls.append(("ball", np.array(p), np.array(q), a, b))
        return real_b(p, q, a, b)

    def rec_f(p, q, r):
        calls.append(("far", np.array(p), np.array(q), r))
        return real_f(p, q, r)

    mods = (_flow_net, _flow_shear, _flow_retry, _flow_densify)
    saved = [(m, m.__dict__.get("ball_counts"), m.__dict__.get("far_from")) for m in mods]
    for m in mods:
        if "ball_counts" in m.__dict__:
            m.ball_counts = rec_b
        if "far_from" in m.__dict__:
            m.far_from = rec_f
    t0 = time.process_time()
    grow(ref, rng=1, relax=True, **kw)
    growth = time.process_time() - t0
    for m, b, f in saved:
        if b is not None:
            m.ball_counts = b
        if f is not None:
            m.far_from = f
    cpu = {"old": 0.0, "new": 0.0}
    same = True
    for c in calls:
        best = {}
        for k in ("old", "new"):
            ts = []
            for _ in range(reps):
                t = time.process_time()
                if c[0] == "ball":
                    got = _old_counts(*c[1:]) if k == "old" else real_b(*c[1:])
                else:
                    got = _old_far(*c[1:]) if k == "old" else real_f(*c[1:])
                ts.append(time.process_time() - t)
                if k == "old":
                    ref_ans = got
                else:
                    same &= all(np.array_equal(np.asarray(x), np.asarray(y)) for x, y in zip(ref_ans if c[0] == "ball" else (ref_ans,), got if c[0] == "ball" else (got,)))
            best[k] = min(ts)
        cpu["old"] += best["old"]
        cpu["new"] += best["new"]
    base = growth - cpu["new"] + cpu["old"]  # (the growth as it was with cKDTree)
    res = {"calls": len(calls), "growth_cpu_s": growth, "measures_cpu_s_ckdtree": cpu["old"], "measures_cpu_s_kernels": cpu["new"],
           "share_of_growth_ckdtree": cpu["old"] / base, "saved_share": (cpu["old"] - cpu["new"]) / base, "answers_equal": bool(same)}
    print(json.dumps(res, indent=1))


if __name__ == "__main__":
    main()
