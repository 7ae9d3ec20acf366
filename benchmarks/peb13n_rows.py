"""Issue 13 point 1, helper peb13n: rerun single rows of ``synth_variants.py`` (--harder
rows ``H:class:index:variant seed:synth seed``, --varied rows ``V:class:label:synth seed``
with the label as the audit names it, e.g. ``V:two_sizes:p2s7:1``) and print each row's
verdict as the audit does, the pebbles' grouped share (interior pebbles with a pebble
within the exemplar's median nearest-neighbour distance s) and the deciles of their
nearest-pebble distance, exemplar and output.

    python benchmarks/peb13n_rows.py H:two_sizes:11:8:1 V:two_sizes:p2s7:1 ...
"""

from __future__ import annotations

import os
import sys
import time

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from grow_variants import _harder_suite
from synth_variants import _harder, run

from strew.metrics import fidelity


def grouped(arr, kind: str, d: float) -> tuple[float, np.ndarray]:
    """Share of ``kind``'s elements at least ``d`` inside the frame with another within
    ``d``, and the deciles 10/50/90 % of their nearest same-kind distance."""
    xy = np.asarray(arr.xy)
    p = xy[np.asarray(arr.kind_names) == kind]
    if len(p) < 3:
        return float("nan"), np.full(3, np.nan)
    x0, y0, x1, y1 = arr.region.bounds
    inn = (
        (p[:, 0] > x0 + d)
        & (p[:, 0] < x1 - d)
        & (p[:, 1] > y0 + d)
        & (p[:, 1] < y1 - d)
    )
    t = cKDTree(p)
    dd = t.query(p[inn], k=2)[0][:, 1]
    return float(np.mean(dd <= d)), np.quantile(dd, [0.1, 0.5, 0.9])


def _experiments() -> None:
    """Monkeypatched variants (nothing in strew changes): PEB_NO_YIELD=1 (nothing
    yields), PEB_MARGIN=x (``_grow.SHARE_MARGIN``), PEB_WINDOW=w (the yield window)."""
    import os

    from strew.synth import _grow as G

    if os.environ.get("PEB_NO_YIELD"):
        G._split_conflicts = lambda state, pts, src, visible_only: state.conflicts(
            pts, src, visible_only=visible_only
        )
    if os.environ.get("PEB_WINDOW"):
        w = int(os.environ["PEB_WINDOW"])
        G._yield_from = lambda state: max(state.grow_start, state.iterations - w)
    if os.environ.get("PEB_MARGIN"):
        G.SHARE_MARGIN = float(os.environ["PEB_MARGIN"])


def main() -> None:
    _experiments()
    for spec in sys.argv[1:]:
        parts = spec.split(":")
        if parts[0] == "H":
            _, name, i, v, seed = parts
            label = f"h{i}s{v}"
            ex = _harder_suite().make_exemplar(
                name, rng=int(v), **_harder()[name][int(i)]
            )
        else:
            _, name, label, seed = parts
            mk = _variants.fidelity_suite()
            got = [c for c in _variants.cases(name, [1, 2, 3], True) if c[0] == label]
            ex = mk.make_exemplar(name, rng=got[0][2], **got[0][3])
        t0 = time.process_time()
        out, _ = run(ex, 3.5, int(seed), None)
        dt = time.process_time() - t0
        rep = fidelity(ex, out, eq5=False, local=False)
        fails = [
            f"{k}={m.value:.3g}/{m.tolerance:.3g}"
            for k, m in rep.metrics.items()
            if m.applicable and not m.passed
        ]
        show = [
            k for k in os.environ.get("PEB_SHOW", "").split(",") if k in rep.metrics
        ]
        if show:
            fails += [
                "(" + " ".join(f"{k}={rep.metrics[k].value:.3g}" for k in show) + ")"
            ]
        s = float(
            np.median(cKDTree(np.asarray(ex.xy)).query(np.asarray(ex.xy), k=2)[0][:, 1])
        )
        small = [
            k
            for k in ("pebble", "small", "dot", "tile")
            if k in set(np.asarray(ex.kind_names))
        ]
        extra = ""
        if small:
            ge, de = grouped(ex, small[0], s)
            go, do = grouped(out, small[0], s)
            extra = f" | {small[0]} grouped ex {ge:.3f} out {go:.3f}; nn deciles/s ex {np.round(de / s, 2)} out {np.round(do / s, 2)}"
        print(
            f"{name} {label} seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} cpu {dt:.1f}s {' '.join(fails)}{extra}",
            flush=True,
        )


if __name__ == "__main__":
    main()
