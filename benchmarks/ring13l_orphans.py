"""Issue 13 point 1, helper ring13l: orphan ring tiles with the hub-lattice snap.

Default rings at 20x the exemplar's area (4.5x its side, as
``tests/synth/test_synth_seams.py::test_rings_on_a_large_canvas_keep_hub_and_tiles``),
per seed, three settings in the same process: ``off`` (``_grow.LATTICE_CV = 0``),
``stay`` (snap on, the tiles copied with a snapped hub left where they were: helper
ring13k's code) and ``follow`` (snap on, those tiles move with their hub: the default).
Prints per run: interior tiles more than 18 from any hub (the test wants 0), the share
of interior rings with all 10 tiles (the test wants >= 0.85), elements, CPU seconds.

    python benchmarks/ring13l_orphans.py [--seeds 1,2,3]
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

import numpy as np
from _runner import fidelity_suite
from scipy.spatial import cKDTree

from strew import Region
from strew.synth import _grow, synthesize


def run(seed: int, mode: str) -> dict:
    ex = fidelity_suite().make_exemplar("rings")
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(4.5 * (x1 - x0), 4.5 * (y1 - y0))
    snap = _grow._snap_anchors_to_lattice
    _grow.LATTICE_CV = 0.0 if mode == "off" else 0.05
    if mode == "stay":
        _grow._snap_anchors_to_lattice = lambda s, e, p, v, ps=None: snap(s, e, p, v, None)
    try:
        t0 = time.process_time()
        out = synthesize(ex, region, rng=seed, measure=False)
        cpu = time.process_time() - t0
    finally:
        _grow._snap_anchors_to_lattice = snap
    hub = out.kind == out.kinds.index("hub")
    size = np.array(region.bounds[2:])
    inner = np.all((out.xy > 40.0) & (out.xy < size - 40.0), axis=1)
    d, _ = cKDTree(out.xy[hub]).query(out.xy[~hub & inner])
    count = np.array([len(v) for v in cKDTree(out.xy[~hub]).query_ball_point(out.xy[hub & inner], 18.0)])
    return dict(seed=seed, mode=mode, n=len(out), orphans=int(np.sum(d > 18.0)), worst=round(float(d.max()), 1),
                whole=round(float(np.mean(count == 10)), 3), cpu_s=round(cpu, 2))


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--seeds", default="1,2,3")
    a = ap.parse_args()
    cv = _grow.LATTICE_CV
    rows = []
    for seed in map(int, a.seeds.split(",")):
        for mode in ("off", "stay", "follow"):
            r = run(seed, mode)
            rows.append(r)
            print(f"seed {seed} {mode:6s} orphans {r['orphans']:3d} (worst {r['worst']:5.1f})  whole rings {r['whole']:.3f}  n={r['n']}  {r['cpu_s']:.1f}s cpu", flush=True)
    _grow.LATTICE_CV = cv
    for mode in ("off", "stay", "follow"):
        m = [r for r in rows if r["mode"] == mode]
        print(f"{mode:6s} orphans total {sum(r['orphans'] for r in m)}, whole median {np.median([r['whole'] for r in m]):.3f}, cpu median {np.median([r['cpu_s'] for r in m]):.2f}s")
    path = Path(__file__).parent / "results" / "ring13l_orphans.json"
    path.parent.mkdir(exist_ok=True)
    path.write_text(json.dumps({"benchmark": "ring13l_orphans", "rows": rows}, indent=2))
    print(f"figures written to {path}")


if __name__ == "__main__":
    main()
