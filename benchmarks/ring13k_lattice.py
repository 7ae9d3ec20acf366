"""Issue 13 point 1, helper ring13k: do synthesized rings keep one hub lattice and whole rings?

Rings of five (radius 10, hubs 30 apart: ``synth_variants.py --harder`` rings h4) failed
0/4 with holes the size of a ring where hub lattices met out of step. Per (variant,
seed) this fills the audit's region (3.5x the frame's side) with
``_grow.LATTICE_CV = 0`` (off, the default: the code before
``_snap_anchors_to_lattice``) and at 0.05, and prints per run: the fidelity verdict and failures, the element count, CPU
seconds, the share of whole rings (``svar13i_rings_diag.ring_stats``) and the hubs'
distance from the lattice of the first hub grown (the exemplar's two shortest hub
offsets, nearest site), median and 90th percentile per band of distance from that hub.
Both settings run in the same process. With ``--toggle complete`` the switch is
``_grow.RING_COMPLETE_LARGER`` instead (rings h2, whose hub is larger than its tiles).

    python benchmarks/ring13k_lattice.py [--set h4|h0|h1|h2|h3|h5] [--variants 7,8] [--seeds 1,2]
                                         [--toggle lattice|complete]
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

import numpy as np
from _runner import fidelity_suite
from scipy.spatial import cKDTree
from svar13i_rings_diag import ring_stats

from strew import Region
from strew.metrics import fidelity
from strew.synth import _grow, synthesize

SETS = {
    "h0": dict(tiles=12, radius=18.0, hub=7.0, spacing=46.0),
    "h1": dict(tiles=8, radius=14.0, hub=6.0, spacing=38.0),
    "h2": dict(tiles=16, radius=22.0, hub=10.0, spacing=56.0),
    "h3": dict(tiles=10, radius=15.0, hub=5.0, spacing=60.0),
    "h4": dict(tiles=5, radius=10.0, hub=4.5, spacing=30.0),
    "h5": dict(tiles=12, radius=16.0, hub=9.0, spacing=42.0, noise=0.02),
}


def lattice_offsets(ex, out, first: np.ndarray, spacing: float) -> list[list[float]]:
    """Per band of ``spacing * 1.5`` from the first hub: [band start, hubs, median, p90]
    of the hubs' distances from the nearest site of the first hub's lattice."""
    eh = ex.xy[ex.kind == list(ex.kinds).index("hub")]
    d, j = cKDTree(eh).query(eh, 7)
    vec = np.concatenate([eh[j[:, k]] - eh for k in range(1, 7)])
    vec = vec[np.hypot(*vec.T) < 1.3 * spacing]
    ang = np.arctan2(vec[:, 1], vec[:, 0])
    a1 = vec[np.argmin(np.abs(ang))]
    a2 = vec[np.argmin(np.abs(ang - np.pi / 3.0))]
    b = np.c_[vec[np.hypot(*(vec - a1).T) < 3].mean(0), vec[np.hypot(*(vec - a2).T) < 3].mean(0)]
    hub = out.xy[out.kind == list(out.kinds).index("hub")]
    co = np.linalg.solve(b, (hub - first).T).T
    off = np.hypot(*(hub - first - np.round(co) @ b.T).T)
    dist = np.hypot(*(hub - first).T)
    rows = []
    step = 1.5 * spacing
    for lo in np.arange(0.0, dist.max() + 1e-9, step):
        m = (dist >= lo) & (dist < lo + step)
        if m.any():
            rows.append([round(float(lo), 1), int(m.sum()), round(float(np.median(off[m])), 2), round(float(np.percentile(off[m], 90)), 2)])
    return rows


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--set", default="h4")
    ap.add_argument("--variants", default="7,8")
    ap.add_argument("--seeds", default="1,2")
    ap.add_argument("--scale", type=float, default=3.5)
    ap.add_argument("--toggle", default="lattice", choices=["lattice", "complete"])
    ap.add_argument("--json", default=None, help="default results/ring13k_lattice_SET.json")
    a = ap.parse_args()
    kw = SETS[a.set]
    mk = fidelity_suite()
    switch = "LATTICE_CV" if a.toggle == "lattice" else "RING_COMPLETE_LARGER"
    plain_cv = getattr(_grow, switch)
    on_value = 0.05 if a.toggle == "lattice" else True  # LATTICE_CV is off by default
    rows = []
    for v in [int(x) for x in a.variants.split(",")]:
        ex = mk.make_exemplar("rings", rng=v, **kw)
        x0, y0, x1, y1 = ex.region.bounds
        region = Region.rectangle(a.scale * (x1 - x0), a.scale * (y1 - y0))
        for s in [int(x) for x in a.seeds.split(",")]:
            for label, cv in (("off", type(on_value)(0)), ("on", on_value)):
                setattr(_grow, switch, cv)
                t0 = time.process_time()
                out = synthesize(ex, region, rng=s, measure=False)
                dt = time.process_time() - t0
                rep = fidelity(ex, out, eq5=False, local=False)
                fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
                # the first hub grown: the one nearest the region's centre (growth starts there)
                hub = out.xy[out.kind == list(out.kinds).index("hub")]
                first = hub[np.argmin(np.hypot(*(hub - np.array(region.geometry.centroid.coords[0])).T))]
                rs = ring_stats(out, kw["tiles"], kw["radius"], kw["spacing"])
                row = {"set": a.set, "v": v, "s": s, "snap": label, "n": len(out), "cpu": round(dt, 2), "ok": rep.faithful, "fails": fails,
                       "full_rings": round(rs["full_rings"], 3),
                       "bands_n_median_p90": lattice_offsets(ex, out, first, kw["spacing"])}
                rows.append(row)
                print(json.dumps(row))
    setattr(_grow, switch, plain_cv)
    for label in ("off", "on"):
        rr = [r for r in rows if r["snap"] == label]
        print(f"{switch} {label}: faithful {sum(r['ok'] for r in rr)}/{len(rr)}, median cpu {np.median([r['cpu'] for r in rr]):.2f}s, "
              f"whole rings {np.median([r['full_rings'] for r in rr]):.3f} (median), "
              f"median p90 lattice offset beyond 2 spacings {np.median([b[3] for r in rr for b in r['bands_n_median_p90'] if b[0] >= 2 * kw['spacing']]):.2f}")
    path = Path(__file__).resolve().parent / (a.json or f"results/ring13k_lattice_{a.set}.json")
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps({"benchmark": "ring13k_lattice", "argv": vars(a), "rows": rows}, indent=1) + "\n")
    print(f"figures written to {path}")


if __name__ == "__main__":
    main()
