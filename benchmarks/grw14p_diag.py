"""Helper grw14p (issue 14 point 1): grow, fixed mode, on chosen ``--harder`` rows; per run
the failing and near-failing nn[a>b] metrics with their signed decile errors (output less
exemplar, in units of s: + too far, - too close), the kinds' shares against the
exemplar's, and (``--oracle``) the same figures for the exemplar's own generator drawn at
the output's size (counts x scale^2).

    PYTHONPATH=src python benchmarks/grw14p_diag.py three_sizes:1:7,three_sizes:9:7 --seeds 1,2 [--oracle]
    PYTHONPATH=src python benchmarks/grw14p_diag.py scan   # exemplars with two kinds of one size level among several

``scan`` lists the audits' exemplars (fidelity suite, ``--varied`` at variant seeds 1-3,
``--harder``) where two different kinds share a size level while there are several
levels: the only ones whose fixed-mode growth the outline-gap rule of grw14p changes.
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from grow_variants import HARDER, _harder_suite

import strew._fidelity as F
from strew import Region
from strew.grow import grow
from strew.metrics import fidelity


def _seeds(t: str) -> list[int]:
    out = []
    for part in t.split(","):
        a, _, b = part.partition("-")
        out.extend(range(int(a), int(b or a) + 1))
    return out


_cap: list = []
_orig = F._discrepancies


def _spy(a, b, kinds, s, **kw):
    if not _cap:
        _cap.append((a, b, kinds, s))
    return _orig(a, b, kinds, s, **kw)


F._discrepancies = _spy


def report(lab, ex, out, near=0.6):
    _cap.clear()
    rep = fidelity(ex, out, eq5=False, local=False)
    a, b, kinds, s = _cap[0]
    sh = {k: round(float(np.mean(out.kind == i)) / max(float(np.mean(ex.kind == i)), 1e-12), 2) for i, k in enumerate(ex.kinds)}
    fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
    print(f"{lab}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} shares {sh} fails {fails}", flush=True)
    for k, m in rep.metrics.items():
        if m.applicable and k.startswith("nn[") and m.value > near * m.tolerance:
            i, j = (kinds.index(x) for x in k[3:-1].split(">"))
            d = (a.nn[i, j] - b.nn[i, j]) / s
            print(f"    {k} {m.value:.3g}/{m.tolerance:.3g} ex deciles/s {np.round(b.nn[i, j] / s, 2)} signed {np.round(d, 2)}", flush=True)
    return rep


def scan(mk) -> None:
    import _variants

    from strew.grow._analysis import size_priority

    def affected(ex) -> bool:
        lv = [size_priority(ex).get(k, 0.0) for k in ex.kinds]
        return max(lv) > min(lv) and any(lv[i] == lv[j] for i in range(len(lv)) for j in range(i + 1, len(lv)))

    hit = []
    for name in mk.NAMES:
        if affected(mk.make_exemplar(name)):
            hit.append(f"suite {name}")
        for lab, _, v, kw in _variants.cases(name, [1, 2, 3], True):
            if affected(mk.make_exemplar(name, rng=v, **kw)):
                hit.append(f"varied {name} {lab}")
        for i, kw in enumerate(HARDER.get(name, [])):
            for v in (7, 8):
                if affected(mk.make_exemplar(name, rng=v, **kw)):
                    hit.append(f"harder {name} h{i}s{v}")
    print("exemplars with two kinds of one size level among several:", hit)


def main() -> None:
    p = argparse.ArgumentParser()
    p.add_argument("cases", help="name:index:variant,...")
    p.add_argument("--seeds", default="1,2")
    p.add_argument("--scale", type=float, default=3.5)
    p.add_argument("--oracle", action="store_true")
    a = p.parse_args()
    mk = _harder_suite()
    if a.cases == "scan":
        scan(mk)
        return
    for spec in a.cases.split(","):
        name, i, v = spec.split(":")
        i, v = int(i), int(v)
        kw = dict(HARDER[name][i])
        ex = mk.make_exemplar(name, rng=v, **kw)
        x0, y0, x1, y1 = ex.region.bounds
        for seed in _seeds(a.seeds):
            t = time.process_time()
            out = grow(ex, region=Region.rectangle(a.scale * (x1 - x0), a.scale * (y1 - y0)), rng=seed)
            report(f"{name} h{i}s{v} seed {seed} ({time.process_time() - t:.1f}s)", ex, out)
            if a.oracle and name == "three_sizes":
                okw = dict(kw)
                okw["size"] = a.scale * kw.get("size", 210.0)
                okw["counts"] = tuple(round(c * a.scale**2) for c in kw.get("counts", (170, 65, 26)))
                orc = mk.make_exemplar(name, rng=1000 + seed, **okw)
                report(f"  oracle h{i}s{v} draw {1000 + seed}", ex, orc)


if __name__ == "__main__":
    main()
