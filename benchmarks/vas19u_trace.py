"""Trace of a tiled vase world's rule tries (issue 19.4, vas19u): per try on an empty circle, the
tile, the phase, the circle (x, y, r), the goal radius a hand-over raised it to, and whether it
succeeded; per tile, the grower's final stats. Nothing in the library changes (wrappers for the
run only).

``PYTHONPATH=TREE/src python benchmarks/vas19u_trace.py --tile 84 --out F.npz [--pattern vase]``, then
``python benchmarks/vas19u_trace.py --read F.npz [--json J]``: the hooks phase's tries by signed
distance to the nearest inner border (negative on the finished, earlier side), the later tiles'
(phase > 0) against the first tiles': how many, the share that succeed, the share a hand-over
raised, the mean circle radius r and goal radius g.
"""

from __future__ import annotations

import argparse
import time

import numpy as np


BINS = [-30, -21, -15, -10.5, -7, -4.5, -2.3, 0, 2.3, 4.5, 7, 10.5, 15, 21, 30]


def summary(path: str, out: str | None) -> dict:
    z = np.load(path)
    a = z["tries"]
    T = float(z["meta"][1])
    tile, ph, x, y, r, g, ok, _ = a.T
    lines = np.arange(1, 4) * T
    dxl = np.min(np.abs(x[:, None] - lines), 1)
    dyl = np.min(np.abs(y[:, None] - lines), 1)
    col, row = np.floor(x / T).astype(int), np.floor(y / T).astype(int)
    sgn = np.where(dxl <= dyl, np.where(col % 2 == 0, -1.0, 1.0), np.where(row % 2 == 0, -1.0, 1.0))
    sd = sgn * np.minimum(dxl, dyl)
    tph = np.array([((int(t) // 4) % 2) * 2 + int(t) % 2 for t in tile])  # 4 x 4 tiles, index j * 4 + i
    raised = g > r + 1e-9
    res: dict = {"file": path, "bins": {}}
    print("hooks phase tries by signed distance (units): later tiles (phase > 0) | first tiles (phase 0)")
    for lo, hi in zip(BINS[:-1], BINS[1:]):
        row_: dict = {}
        for P in ("later", "first"):
            m = (ph == 1) & (sd >= lo) & (sd < hi) & ((tph > 0) if P == "later" else (tph == 0))
            if not m.any():
                continue
            mr = m & raised
            row_[P] = dict(tries=int(m.sum()), ok=float(ok[m].mean()), raised=float(raised[m].mean()), r=float(r[m].mean()),
                           g=float(g[m].mean()), g_over_r_raised=float(np.mean(g[mr] / r[mr])) if mr.any() else float("nan"))
        res["bins"][f"{lo:+g}..{hi:+g}"] = row_
        print(f"  {lo:+6.1f}..{hi:+6.1f} " + " | ".join(
            f"{P}: {v['tries']:5d} tries ok {v['ok']:.3f} raised {v['raised']:.3f} r {v['r']:.2f} g {v['g']:.2f} g/r(raised) {v['g_over_r_raised']:.2f}"
            for P, v in row_.items()))
    if out:
        import json

        with open(out, "w") as f:
            json.dump(res, f, indent=1)
    return res


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--tile", type=float, default=84.0)
    ap.add_argument("--pattern", default="vase")
    ap.add_argument("--untiled", action="store_true")
    ap.add_argument("--out", default=None)
    ap.add_argument("--read", default=None, help="summarize a trace written by --out")
    ap.add_argument("--json", default=None)
    args = ap.parse_args()
    if args.read:
        summary(args.read, args.json)
        return
    import strew
    import strew.ornament._engine as E
    import strew.tiles as T

    cur = {"tile": -1}
    rows: list = []
    stats: list = []
    orig_try, orig_run, orig_tile = E._Grower._try, E._Grower.run, T.run_tile

    def _try(self, goal, candidates, shift=None, circle=None):
        ok = orig_try(self, goal, candidates, shift, circle)
        c = goal if circle is None else circle
        ph = {"vines": 0, "hooks": 1}.get(str(self.state.phase), -1)
        rows.append((cur["tile"], ph, float(c.center[0]), float(c.center[1]), float(c.radius), float(goal.radius), bool(ok), len(candidates)))
        return ok

    def run(self):
        orig_run(self)
        stats.append((cur["tile"], dict(self.stats)))

    def run_tile(job, t, *nb):
        cur["tile"] = t.index
        return orig_tile(job, t, *nb)

    E._Grower._try, E._Grower.run, T.run_tile = _try, run, run_tile
    side = 4 * args.tile
    t0 = time.process_time()
    if args.untiled:
        from strew.ornament import grow_ornament

        arr = grow_ornament(args.pattern, strew.Region.rectangle(side, side), rng=1)
    else:
        arr = T.tiled("ornament", args.pattern, (side, side), tile_size=args.tile, seed=1)
    cpu = time.process_time() - t0
    a = np.array(rows, float).reshape(-1, 8)
    np.savez_compressed(args.out, tries=a, x=np.asarray(arr.x, float), y=np.asarray(arr.y, float), kind=np.asarray(arr.kind),
                        kinds=np.array(list(arr.kinds)), meta=np.array([side, args.tile, cpu]),
                        stats=np.array([repr(s) for s in stats]))
    print(f"{len(arr):,} el, {len(a):,} tries ({int(a[:, 6].sum()):,} ok), {cpu:.1f} CPU s -> {args.out}")


if __name__ == "__main__":
    main()
