"""Ornament tiles: is a handed-over circle still empty when a later tile's goal raised by it is tried? (issue 19.4)

``PYTHONPATH=TREE/src python benchmarks/dot19s_holes.py --json F [--patterns dots,willow,hierarchy]
[--side 160 --tile 40]`` grows ``strew.tiles.tiled("ornament", NAME, (side, side), tile_size=tile,
seed=1)`` and, for each rule try that a handed-over circle raised (_engine._handed_over), records
the raised circle (the hole): its clearance in the later tile at the moment of the try
(rho_hole: the distance from the hole's centre to the nearest placed element), whether the
nearest element there is a finished neighbour's (context) or the later tile's own, the
distance from the goal's centre to the hole's, and whether the try succeeded. Nothing in the
library is changed (``_try`` is wrapped for the run only).
"""

from __future__ import annotations

import argparse
import json
import time

import numpy as np


def count(name: str, side: float, tile: float) -> dict:
    import strew.ornament._engine as E
    import strew.tiles as T

    rows = []
    orig = E._Grower._try

    def _try(self, goal, candidates, shift=None, circle=None):
        ok = orig(self, goal, candidates, shift, circle)
        if circle is not None:
            holes = self._holes_of_phase()
            c = circle.center
            d = np.hypot(holes[:, 0] - c[0], holes[:, 1] - c[1])
            inside = d < holes[:, 2]
            k = np.flatnonzero(inside)[np.argmax(holes[inside, 2])]
            hx, hy, R = holes[k]
            idx = self.placed.near(hx, hy, R + 10.0)
            dist = self.placed.distances(idx, hx, hy) if len(idx) else np.empty(0)
            # (after the try: a success's own element is placed; measure without it)
            own_new = set()
            if ok:
                own_new = {len(self.elements) - 1}
            if len(idx):
                owners = self.placed.owner[idx]
                m = np.array([o not in own_new for o in owners.tolist()], bool)
                dist, owners = dist[m], owners[m]
            if len(dist):
                j = int(np.argmin(dist))
                rho_h = float(dist[j])
                near_ctx = bool(getattr(self.elements[int(owners[j])], "context", False))
            else:
                rho_h, near_ctx = float("inf"), False
            rows.append(dict(ok=bool(ok), rho=float(circle.radius), R=float(R), rho_hole=rho_h,
                             e=float(d[k]), near_context=near_ctx, phase=str(self.state.phase)))
        return ok

    E._Grower._try = _try
    try:
        t0 = time.process_time()
        arr = T.tiled("ornament", name, (side, side), tile_size=tile, seed=1)
        cpu = time.process_time() - t0
    finally:
        E._Grower._try = orig
    ok = np.array([r["ok"] for r in rows], bool)
    R = np.array([r["R"] for r in rows])
    rh = np.array([r["rho_hole"] for r in rows])
    ctx = np.array([r["near_context"] for r in rows], bool)
    empty = rh >= 0.95 * R
    s = dict(tries=len(rows), ok=int(ok.sum()), hole_empty=int(empty.sum()),
             ok_when_empty=int((ok & empty).sum()), ok_when_filled=int((ok & ~empty).sum()),
             filled_by_context=int((~empty & ctx).sum()), filled_by_own=int((~empty & ~ctx).sum()),
             mean_R=float(R.mean()) if len(R) else None, mean_rho=float(np.mean([r["rho"] for r in rows])) if rows else None,
             mean_rho_hole_over_R=float(np.mean(np.minimum(rh / R, 2.0))) if len(R) else None,
             elements=len(arr), cpu_s=cpu)
    return dict(summary=s, rows=rows)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--json", required=True)
    ap.add_argument("--patterns", default="dots,willow,hierarchy")
    ap.add_argument("--side", type=float, default=160.0)
    ap.add_argument("--tile", type=float, default=40.0)
    args = ap.parse_args()
    out = {"command": f"python benchmarks/dot19s_holes.py --patterns {args.patterns} --side {args.side:g} --tile {args.tile:g}", "patterns": {}}
    for name in args.patterns.split(","):
        c = count(name, args.side, args.tile)
        out["patterns"][name] = c
        print(name, json.dumps(c["summary"]), flush=True)
    with open(args.json, "w") as f:
        json.dump(out, f, indent=1)


if __name__ == "__main__":
    main()
