"""Worlds for the pooled tiled-hierarchy measurement (issue 19.4, helper hie15).

``PYTHONPATH=TREE/src python benchmarks/hie15_make.py --tag TAG --tiles 48,52,56,60,64,68 --seeds 1
[--untiled [--centre]] [--pattern hierarchy]`` runs ``benchmarks/orn19m_willow.py make
--overlaps`` once per tile size and seed, the world saved as
``benchmarks/results/orn19m_TAG_sS_TT.npz``. Hierarchy's geometry does not depend on the
seed (largest empty circle first, §4.1; the rng picks only the flowers' colours: tile 60,
seeds 1-3 gave equal x and kind, 3,868 elements): its worlds differ by tile size.

The untiled control is seeded, by default, at the tiled world's own seed points: a 4 x 4
tiled world with 2 x 2 phases seeds only its four first-phase tiles (columns and rows 0
and 2), each at the centre of its region's largest inscribed circle (strew.ornament
.default_seed; the region is the tile widened by the halo h = T / 4 and clipped to the
world): (0.625 T or 2.5 T) in x and in y (0.625 T = (T + h) / 2). None lies on a border
(0.375 T from the nearest). ``--centre`` gives orn19m's control instead: one seed at the
world's centre, which lies on the central border crossing, where its first vines grow
along the two central borders (the control then splits by side: hie19x, T94 +-1 s
0.98 | 1.21). Same seeds in both: one run grows from the same four fronts the tiles do.

Every empty circle a run tries (strew.ornament._engine._Grower._try, wrapped; nothing in
the library changes) is written to ``benchmarks/results/hie15_tries_TAG_sS_TT.npz``:
the phase, the circle's centre and radius, the run (0, 1, ...: tiles in their order; the
control is one run), whether the run had context (a later tile), whether the try
succeeded, whether a vine and a non-vine element were among its candidate parents
(parents that may carry the rule: not sterile), and the kind the success placed first.
"""

from __future__ import annotations

import argparse
import functools
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))


def tiled_seed_points(tile: float) -> np.ndarray:
    """The seed points of a 4 x 4 tiled world's first-phase tiles (halo T / 4)."""
    h = tile / 4
    c = [(tile + h) / 2, 2.5 * tile]
    return np.array([[x, y] for y in c for x in c], float)


def _seeds(spec: str) -> list[int]:
    out: list[int] = []
    for part in spec.split(","):
        a, _, b = part.partition("-")
        out.extend(range(int(a), int(b or a) + 1))
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--tag", required=True)
    ap.add_argument("--tiles", default="60")
    ap.add_argument("--seeds", default="1-8")
    ap.add_argument("--pattern", default="hierarchy")
    ap.add_argument("--untiled", action="store_true")
    ap.add_argument("--centre", action="store_true", help="untiled: one seed at the world's centre (orn19m's control)")
    ap.add_argument("--halo", type=float, default=None, help="tiled: the halo as a fraction of the tile (default the library's, 1/4)")
    ap.add_argument("--set", action="append", default=[], help="NAME=VALUE: a module constant of strew.tiles or strew.ornament._context (orn19m)")
    args = ap.parse_args()
    import orn19m_willow as W

    import strew.ornament as O
    import strew.ornament._engine as E

    grow = O.grow_ornament
    if args.halo is not None:
        import strew.tiles as T

        tiled = T.tiled
        T.tiled = lambda *a, tile_size, **k: tiled(*a, tile_size=tile_size, halo=args.halo * tile_size, **k)
    rows: list = []
    run_no = [-1]
    orig_init, orig_try = E._Grower.__init__, E._Grower._try
    phases = [p.name for p in __import__("strew.ornament._pattern", fromlist=["load_pattern"]).load_pattern(args.pattern).phases]

    def init(self, *a, **k):
        orig_init(self, *a, **k)
        run_no[0] += 1

    def _try(self, goal, candidates, shift=None, circle=None):
        n0 = len(self.elements)
        ok = orig_try(self, goal, candidates, shift, circle)
        c = goal if circle is None else circle
        types = [self.elements[o].type for o in candidates if not self.elements[o].sterile]
        first = self.elements[n0].type if ok and len(self.elements) > n0 else ""
        ph = phases.index(str(self.state.phase)) if str(self.state.phase) in phases else -1
        rows.append((ph, float(c.center[0]), float(c.center[1]), float(c.radius), float(goal.radius), run_no[0], int(self.n_context > 0), int(bool(ok)),
                     int("vine" in types), int(any(t != "vine" for t in types)), first))
        return ok

    E._Grower.__init__, E._Grower._try = init, _try
    for tile in [float(v) for v in args.tiles.split(",")]:
        for s in _seeds(args.seeds):
            if args.untiled and not args.centre:
                O.grow_ornament = functools.partial(grow, seeds=tiled_seed_points(tile))
            else:
                O.grow_ornament = grow
            t0 = time.time()
            W.make(argparse.Namespace(tag=f"{args.tag}_s{s}", tiles=f"{tile:g}", pattern=args.pattern, untiled=args.untiled,
                                      seed=s, set=args.set, overlaps=True))
            a = rows[:]
            rows.clear()
            run_no[0] = -1
            kinds = sorted({r[-1] for r in a if r[-1]})
            np.savez_compressed(HERE / "results" / f"hie15_tries_{args.tag}_s{s}_T{tile:g}.npz", phases=np.array(phases),
                                num=np.array([r[:10] for r in a], float).reshape(-1, 10),
                                cols=np.array(["phase", "x", "y", "r", "goal_r", "run", "context", "ok", "vine_cand", "other_cand"]),
                                first=np.array([kinds.index(r[-1]) if r[-1] else -1 for r in a]), first_kinds=np.array(kinds or [""]))
            print(f"  wall {time.time() - t0:.0f} s, {len(a)} tries", flush=True)


if __name__ == "__main__":
    main()
