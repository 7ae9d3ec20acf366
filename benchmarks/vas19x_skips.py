"""How often vas19x's rule changes a vase run: the vine calls where vase._free_grid_point's
choice differs from the one without the MIN_VINE skip (a grid point at the vine's start,
which grow_vine's length test then failed), in the vines' phase of an untiled panel (issue
19.4, vas19x). 0 such calls: the run is the same as at d67a7c3 (the hooks' phase does not
choose grid points). The run stops at the hooks' phase's first try.

``PYTHONPATH=src python benchmarks/vas19x_skips.py --sides 200,240,264,288,312,336 [--seeds 1]``
"""

from __future__ import annotations

import argparse

import numpy as np


def old_free(ctx, near, start=None):
    """d67a7c3's vase._free_grid_point: no MIN_VINE skip."""
    from strew.ornament.patterns import vase

    i0, j0 = round(near[0] / vase.GRID), round(near[1] / vase.GRID)
    best = None
    for i in range(i0 - 1, i0 + 2):
        for j in range(j0 - 1, j0 + 2):
            if (i, j) in ctx.state.flowers:
                continue
            p = np.array([i * vase.GRID, j * vase.GRID])
            if start is not None and float(np.hypot(*(p - start))) > vase.REACH:
                continue
            d = float(np.hypot(*(p - near)))
            if best is None or d < best[0]:
                best = (d, (i, j), p)
    return best


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--sides", default="200,240,264,288,312,336")
    ap.add_argument("--seeds", default="1")
    args = ap.parse_args()
    import strew
    from strew._errors import Cancelled
    from strew.ornament import grow_ornament
    from strew.ornament.patterns import vase

    new_free = vase._free_grid_point

    st = {"calls": 0, "differ": 0, "state": None}

    def counted(ctx, near, start=None):
        a, b = new_free(ctx, near, start), old_free(ctx, near, start)
        st["calls"] += 1
        st["state"] = ctx.state
        st["differ"] += (a is None) != (b is None) or (a is not None and a[1] != b[1])
        return a

    vase._free_grid_point = counted

    def stop() -> bool:  # the hooks' phase has begun: the vines' phase is done
        return st["state"] is not None and getattr(st["state"], "phase", None) == "hooks"
    try:
        for side in [float(v) for v in args.sides.split(",")]:
            for seed in [int(v) for v in args.seeds.split(",")]:
                st.update(calls=0, differ=0, state=None)
                try:
                    grow_ornament("vase", strew.Region.rectangle(side, side), rng=seed, should_cancel=stop)
                except Cancelled:
                    pass
                print(f"{side:g} s{seed}: grid-point calls {st['calls']}, choice differs {st['differ']}; flowers "
                      f"{len(st['state'].flowers) if st['state'] is not None else 0}", flush=True)
    finally:
        vase._free_grid_point = new_free


if __name__ == "__main__":
    main()
