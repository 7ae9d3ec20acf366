"""Issue 13 point 1, helper svar13i: where synth's hub-tile pair correlation goes wrong on
tightly spaced rings (``rings`` with tiles 14, radius 20, hub 8, spacing 52).

For each (variant, seed): g[tile,hub](r) of exemplar and result (``strew.metrics``'s
``pair_correlation`` at the fidelity's r range), the metric, and ring structure per hub
in the result: tiles within radius +- 4 of the hub (full ring = ``tiles``), hubs with no
ring, tiles with no hub at ring radius (orphans), tiles nearer a second hub's ring radius
(interleaved), hub-hub nn distances against the lattice spacing. ``--render`` writes
PNGs to ``/tmp/svar13i/``.

    python benchmarks/svar13i_rings_diag.py [--variants 7,8] [--seeds 1,2] [--set ...] [--render]
"""

from __future__ import annotations

import argparse
import json
import time

import numpy as np
from _runner import fidelity_suite
from scipy.spatial import cKDTree

from strew import Region
from strew.metrics import fidelity
from strew.synth import synthesize


def ring_stats(out, tiles: int, radius: float, spacing: float) -> dict:
    kinds = list(out.kinds)
    hub = out.xy[out.kind == kinds.index("hub")]
    tile = out.xy[out.kind == kinds.index("tile")]
    x0, y0, x1, y1 = out.region.bounds
    inner = (hub[:, 0] > x0 + spacing) & (hub[:, 0] < x1 - spacing) & (hub[:, 1] > y0 + spacing) & (hub[:, 1] < y1 - spacing)
    th = cKDTree(tile)
    per = np.array([len(th.query_ball_point(h, radius + 4.0)) - len(th.query_ball_point(h, max(radius - 4.0, 0.1))) for h in hub])
    hh = cKDTree(hub)
    d1, _ = hh.query(tile, 2)
    dn, _ = hh.query(hub, 2)
    ti = (tile[:, 0] > x0 + spacing) & (tile[:, 0] < x1 - spacing) & (tile[:, 1] > y0 + spacing) & (tile[:, 1] < y1 - spacing)
    return {
        "hubs": int(inner.sum()),
        "tiles_per_hub": np.bincount(per[inner], minlength=tiles + 3).tolist(),
        "full_rings": float(np.mean(per[inner] == tiles)),
        "tiles_per_hub_mean": float(per[inner].mean()),
        "orphan_tiles": float(np.mean(np.abs(d1[ti, 0] - radius) > 4.0)),
        "tile_hub_d_q": np.round(np.quantile(d1[ti, 0], [0.02, 0.1, 0.5, 0.9, 0.98]), 2).tolist(),
        "hub_hub_nn_q": np.round(np.quantile(dn[inner, 1], [0.02, 0.1, 0.5, 0.9, 0.98]), 2).tolist(),
        "n_tiles_per_hub": float(len(tile) / max(len(hub), 1)),
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--variants", default="7,8")
    ap.add_argument("--seeds", default="1,2")
    ap.add_argument("--set", default='{"tiles": 14, "radius": 20.0, "hub": 8.0, "spacing": 52.0}')
    ap.add_argument("--scale", type=float, default=3.5)
    ap.add_argument("--render", action="store_true")
    ap.add_argument("--json", default=None)
    a = ap.parse_args()
    kw = json.loads(a.set)
    mk = fidelity_suite()
    from strew.metrics import pair_correlation

    rows = []
    for v in [int(x) for x in a.variants.split(",")]:
        ex = mk.make_exemplar("rings", rng=v, **kw)
        tiles, radius, spacing = kw.get("tiles", 10), kw.get("radius", 15.0), kw.get("spacing", 40.0)
        x0, y0, x1, y1 = ex.region.bounds
        for s in [int(x) for x in a.seeds.split(",")]:
            t0 = time.process_time()
            out = synthesize(ex, Region.rectangle(a.scale * (x1 - x0), a.scale * (y1 - y0)), rng=s, measure=False)
            dt = time.process_time() - t0
            rep = fidelity(ex, out, eq5=False, local=False)
            m = rep.metrics["g[tile,hub]"]
            ge, go = pair_correlation(ex), pair_correlation(out)
            row = {"variant": v, "seed": s, "n": len(out), "cpu_s": round(dt, 2), "g_tile_hub": round(m.value, 3), "tol": m.tolerance,
                   "faithful": rep.faithful, "failures": [f"{k}={mm.value:.3g}/{mm.tolerance:.3g}" for k, mm in rep.metrics.items() if mm.applicable and not mm.passed],
                   "r": np.round(ge["r"], 1).tolist(), "g_ex": np.round(ge["g"].get("tile,hub", ge["g"].get("hub,tile")), 2).tolist(),
                   "g_out": np.round(go["g"].get("tile,hub", go["g"].get("hub,tile")), 2).tolist(),
                   "ex_rings": ring_stats(ex, tiles, radius, spacing), "out_rings": ring_stats(out, tiles, radius, spacing)}
            rows.append(row)
            print(json.dumps({k: row[k] for k in ("variant", "seed", "n", "cpu_s", "g_tile_hub", "failures")}))
            print("  r    ", row["r"])
            print("  g_ex ", row["g_ex"])
            print("  g_out", row["g_out"])
            print("  ex  ", row["ex_rings"])
            print("  out ", row["out_rings"])
            if a.render:
                from strew.io import save as render

                path = f"/tmp/svar13i/rings_v{v}_s{s}.png"
                render(out, path)
                render(ex, f"/tmp/svar13i/rings_v{v}_ex.png")
    if a.json:
        with open(a.json, "w") as f:
            json.dump(rows, f, indent=1)


if __name__ == "__main__":
    main()
