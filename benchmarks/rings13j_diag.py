"""Issue 13 point 1, helper rings13j: synth on the harder ring exemplars h4 (five tiles,
radius 10, hub 4.5, spacing 30) and h2 (sixteen tiles, radius 22, hub 10, spacing 56).

Per variant: the exemplar's measured figures (average spacing a, r-bar per kind, the
hubs' closest approach); per (variant, seed, r-bar override): the fidelity failures,
the worst empty circle and the ring structure (``svar13i_rings_diag.ring_stats``).

    python benchmarks/rings13j_diag.py [--set h4|h2] [--variants 7,8] [--seeds 1,2]
                                       [--rbar ""|22,25] [--optimize horizon|none]
"""

from __future__ import annotations

import argparse
import json
import time

import numpy as np
from _runner import fidelity_suite
from scipy.spatial import cKDTree
from svar13i_rings_diag import ring_stats

from strew import Region
from strew.metrics import fidelity
from strew.synth import synthesize
from strew.synth._palette import average_spacing, element_parameters

SETS = {"h4": dict(tiles=5, radius=10.0, hub=4.5, spacing=30.0), "h2": dict(tiles=16, radius=22.0, hub=10.0, spacing=56.0)}


def _circles(arr):
    """Delaunay circumcircles of the centres lying wholly inside the frame's bounds."""
    from strew.synth._grow import circumcircles

    c, r, _ = circumcircles(arr.xy)
    x0, y0, x1, y1 = arr.region.bounds
    ok = (c[:, 0] - r > x0) & (c[:, 0] + r < x1) & (c[:, 1] - r > y0) & (c[:, 1] + r < y1)
    return c[ok], r[ok]


def holes(ex, out) -> dict:
    """The exemplar's largest empty circle, the output's circles wider than 1.1 times it,
    and for the 5 widest distinct holes (centres 15 apart) the 3 nearest hubs' distances."""
    _, re_ = _circles(ex)
    c, r = _circles(out)
    hub = out.xy[out.kind == list(out.kinds).index("hub")]
    ht = cKDTree(hub)
    widest, seen = [], []
    for i in np.argsort(-r):
        if len(seen) == 5:
            break
        if any(np.hypot(*(c[i] - p)) < 15.0 for p in seen):
            continue
        seen.append(c[i])
        d, _ = ht.query(c[i], 3)
        widest.append([round(float(r[i]), 1)] + np.round(d, 1).tolist())
    return {"lec_ex": round(float(re_.max()), 2), "wide_circles": int((r > 1.1 * re_.max()).sum()), "widest_r_hubs3": widest}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--set", default="h4")
    ap.add_argument("--variants", default="7,8")
    ap.add_argument("--seeds", default="1,2")
    ap.add_argument("--rbar", default="", help="r-bar overrides (comma list; TILE:HUB for per kind), '' = default")
    ap.add_argument("--optimize", default=None)
    ap.add_argument("--scale", type=float, default=3.5)
    ap.add_argument("--json", default="results/rings13j_diag.json")
    ap.add_argument("--hub-holes", action="store_true", help="diagnosis: fill_holes may take anchors (with their children)")
    ap.add_argument("--approach", type=float, default=1.0, help="diagnosis: closest approach of the hubs to themselves times this")
    a = ap.parse_args()
    if a.approach != 1.0:
        from strew.synth import _prepare

        plain_ca = _prepare.closest_approach

        def closest_approach(pos, cls, source):
            out = plain_ca(pos, cls, source)
            out[1, 1] *= a.approach  # the hub kind (index 1 in rings)
            return out

        _prepare.closest_approach = closest_approach
    if a.hub_holes:
        import sys as _sys

        from strew.synth import _grow

        plain = _grow.anchors

        def anchors(prep):  # zero for fill_holes' caller only
            out = plain(prep)
            return out * 0 if _sys._getframe(1).f_code.co_name == "fill_holes" else out

        _grow.anchors = anchors
    kw = SETS[a.set]
    mk = fidelity_suite()
    rows = []
    overrides = [None] + [x for x in a.rbar.split(",") if x]
    for v in [int(x) for x in a.variants.split(",")]:
        ex = mk.make_exemplar("rings", rng=v, **kw)
        r, rbar = element_parameters(ex)
        kinds = list(ex.kinds)
        hub = ex.xy[ex.kind == kinds.index("hub")]
        d, _ = cKDTree(hub).query(hub, 2)
        print(f"v{v}: n {len(ex)} a {average_spacing(ex.xy):.2f} rbar " + " ".join(f"{k} {np.unique(rbar[ex.kind == i].round(2))}" for i, k in enumerate(kinds))
              + f" hub closest {d[:, 1].min():.2f} median {np.median(d[:, 1]):.2f}")
        x0, y0, x1, y1 = ex.region.bounds
        for ov in overrides:
            if ov is None:
                e2 = ex
            else:
                t, _, h = ov.partition(":")
                e2 = ex.with_columns(neighborhood_radius=np.where(ex.kind == kinds.index("hub"), float(h or t), float(t)))
            for s in [int(x) for x in a.seeds.split(",")]:
                t0 = time.process_time()
                opts = {} if a.optimize is None else {"optimize": a.optimize}
                out = synthesize(e2, Region.rectangle(a.scale * (x1 - x0), a.scale * (y1 - y0)), rng=s, measure=False, **opts)
                dt = time.process_time() - t0
                rep = fidelity(ex, out, eq5=False, local=False)
                fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
                rs = ring_stats(out, kw["tiles"], kw["radius"], kw["spacing"])
                row = {"set": a.set, "v": v, "s": s, "rbar": ov, "approach": a.approach, "hub_holes": a.hub_holes, "optimize": a.optimize, "n": len(out),
                       "cpu": round(dt, 2), "ok": rep.faithful, "fails": fails, "full_rings": round(rs["full_rings"], 3),
                       "orphans": round(rs["orphan_tiles"], 3), "tph": rs["tiles_per_hub"], **holes(ex, out)}
                rows.append(row)
                print(json.dumps(row))
    from pathlib import Path

    path = Path(__file__).resolve().parent / a.json
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps({"benchmark": "rings13j_diag", "argv": vars(a), "rows": rows}, indent=1) + "\n")
    print(f"figures written to {path}")


if __name__ == "__main__":
    main()
