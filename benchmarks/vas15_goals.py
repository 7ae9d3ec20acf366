"""The vines' phase goals of a tiled vase world's tiles, traced (issue 19.4, vas15).

``PYTHONPATH=src python benchmarks/vas15_goals.py TAG --tiles T [--seed S] [--untiled] [--set NAME=VALUE]``
grows the world (as ``benchmarks/orn19m_willow.py make --pattern vase``) and saves to
``benchmarks/results/vas15_goals_<TAG>_T<T>.npz`` every goal the vines' phase tried: the tile,
the empty circle (x, y, radius), whether a rule grew into it, how many of the elements
touching it (the candidates) can parent a vine (a vine or a flower, not sterile) and how many
of those are context elements (a finished neighbour's), and the parent a success grew from.
Then prints, per signed distance to the nearest inner border (orn19m_willow.py's sign: the
finished side negative), the goals tried and their outcome.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
RES = HERE / "results"
sys.path.insert(0, str(HERE))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("tag")
    ap.add_argument("--tiles", type=float, required=True)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--untiled", action="store_true")
    ap.add_argument("--set", action="append", default=[])
    args = ap.parse_args()
    import strew
    import strew.ornament._context as C
    import strew.tiles as T
    from strew.ornament import _engine as E

    for kv in args.set:
        name, _, val = kv.partition("=")
        mod = T if hasattr(T, name) else C
        setattr(mod, name, type(getattr(mod, name))(val))
    cur = {"tile": -1}
    orig_rng = T.tile_rng

    def tile_rng(seed, index):
        cur["tile"] = int(index)
        return orig_rng(seed, index)

    T.tile_rng = tile_rng
    rows: list = []
    orig_try = E._Grower._try
    vp = {"vine", "lotus", "peony", "seed"}

    def _try(self, goal, candidates, shift=None, circle=None):
        if self.state.phase != "vines":
            return orig_try(self, goal, candidates, shift, circle)
        n0 = len(self.elements)
        ok = orig_try(self, goal, candidates, shift, circle)
        els = [self.elements[o] for o in candidates]
        can = [e for e in els if e.type in vp and not e.sterile]
        nctx = sum(bool(getattr(e, "context", False)) for e in can)
        par = -1
        if ok and len(self.elements) > n0:
            p = self.elements[n0].parent if hasattr(self.elements[n0], "parent") else None
            par = 1 if (p is not None and getattr(p, "context", False)) else 0
        first = els[0].type if els else ""
        rows.append((cur["tile"], float(goal.center[0]), float(goal.center[1]), float(goal.radius), bool(ok), len(els), len(can), nctx, par,
                     ["", "seed", "vine", "lotus", "peony", "hook", "teardrop"].index(first), bool(getattr(els[0], "context", False)) if els else False))
        return ok

    E._Grower._try = _try
    side = 4 * args.tiles
    if args.untiled:
        from strew.ornament import grow_ornament

        grow_ornament("vase", strew.Region.rectangle(side, side), rng=args.seed)
    else:
        T.tiled("ornament", "vase", (side, side), tile_size=args.tiles, seed=args.seed)
    a = np.array(rows, float)
    path = RES / f"vas15_goals_{args.tag}_T{args.tiles:g}.npz"
    np.savez_compressed(path, rows=a, meta=np.array([side, args.tiles, args.seed]))
    print(f"{len(a)} vines-phase goals -> {path.name}")
    report(a, side, args.tiles)


def report(a, side, tile) -> None:
    from orn19m_willow import _sd

    _, sd = _sd(a[:, 1], a[:, 2], side, tile)
    bins = np.array([-30, -15, -10, -5, 0, 5, 10, 15, 30.0])
    b = np.digitize(sd, bins) - 1
    print("signed distance (units) | goals | succeeded | none of the touching elements can parent a vine | succeeded from a context parent")
    for k in range(len(bins) - 1):
        m = b == k
        print(f"  {bins[k]:+4.0f}..{bins[k + 1]:+4.0f}: {int(m.sum()):5d} | {int(a[m, 4].sum()):4d} | {int((m & (a[:, 6] == 0)).sum()):5d} | {int((m & (a[:, 8] == 1)).sum()):4d}")


if __name__ == "__main__":
    main()
