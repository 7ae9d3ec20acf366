"""Issue 13 point 1, helper tsz13k: where three_sizes outputs miss their exemplar.

For harder three_sizes sets (``grow_variants.HARDER``), prints per kind the exemplar's,
synth's and the oracle's (the generator drawn ``--scale`` larger) density and the
nearest-neighbour deciles (in units of s) the fidelity metric compares, for the pairs
named by ``--pairs``.

    python benchmarks/tsz13k_diag.py [--sets 1,4,7,9,11] [--variants 7,8] [--seeds 1,2]
                                     [--pairs medium>medium,small>medium] [--no-oracle]
"""

from __future__ import annotations

import argparse
import sys
import time

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from grow_variants import HARDER, _harder_suite  # noqa: E402
from svar13i_oracle import big_params  # noqa: E402

import strew._fidelity as F  # noqa: E402
from strew import Region  # noqa: E402
from strew.synth import synthesize  # noqa: E402

_seen: list = []
_orig = F._discrepancies


def _capture(a, b, kinds, s, **kw):
    if not _seen or _seen[-1] is None:
        _seen.append((a, b, list(kinds), s))
    return _orig(a, b, kinds, s, **kw)


F._discrepancies = _capture


def judge(ex, out):
    _seen.clear()
    _seen.append(None)
    rep = F.fidelity(ex, out, eq5=False, local=False)
    return rep, _seen[1]


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--sets", default="1,4,7,9,11")
    ap.add_argument("--variants", default="7,8")
    ap.add_argument("--seeds", default="1,2")
    ap.add_argument("--pairs", default="medium>medium")
    ap.add_argument("--scale", type=float, default=3.5)
    ap.add_argument("--no-oracle", action="store_true")
    a = ap.parse_args()
    mk = _harder_suite()
    pairs = [p.split(">") for p in a.pairs.split(",")]
    for i in map(int, a.sets.split(",")):
        kw = HARDER["three_sizes"][i]
        for v in map(int, a.variants.split(",")):
            ex = mk.make_exemplar("three_sizes", rng=v, **kw)
            x0, y0, x1, y1 = ex.region.bounds
            runs = []
            for seed in map(int, a.seeds.split(",")):
                t0 = time.process_time()
                out = synthesize(ex, Region.rectangle(a.scale * (x1 - x0), a.scale * (y1 - y0)), rng=seed, measure=False)
                runs.append((f"synth{seed}", out, time.process_time() - t0))
            if not a.no_oracle:
                big = big_params("three_sizes", dict(kw), a.scale)
                runs.append(("oracle", mk.make_exemplar("three_sizes", rng=v, **big), 0.0))
            print(f"== h{i}s{v} {kw}  n_ex={len(ex)}")
            first = True
            for lab, out, dt in runs:
                rep, (res, exs, kinds, s) = judge(ex, out)
                if first:
                    print(f"   exemplar   dens " + " ".join(f"{k}={exs.density[j] * s * s:.3f}" for j, k in enumerate(kinds)) + f"  s={s:.2f}")
                    for pa, pb in pairs:
                        ia, ib = kinds.index(pa), kinds.index(pb)
                        print(f"   exemplar   nn[{pa}>{pb}] " + " ".join(f"{x / s:.2f}" for x in exs.nn[ia, ib]))
                    first = False
                fails = " ".join(f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed)
                print(f"   {lab:9s}  dens " + " ".join(f"{k}={res.density[j] * s * s:.3f}" for j, k in enumerate(kinds)) + f"  n={len(out)} {dt:.1f}s  {fails or 'pass'}")
                for pa, pb in pairs:
                    ia, ib = kinds.index(pa), kinds.index(pb)
                    print(f"   {lab:9s}  nn[{pa}>{pb}] " + " ".join(f"{x / s:.2f}" for x in res.nn[ia, ib]) + f"   diff {' '.join(f'{(x - y) / s:+.2f}' for x, y in zip(res.nn[ia, ib], exs.nn[ia, ib]))}")


if __name__ == "__main__":
    main()
