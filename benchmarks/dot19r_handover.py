"""Ornament tiles: how the hand-over of dropped room (issue 19.4) fares per pattern.

``PYTHONPATH=TREE/src python benchmarks/dot19r_handover.py --json F [--patterns dots,hierarchy,willow]
[--side 160 --tile 40]`` grows ``strew.tiles.tiled("ornament", NAME, (side, side),
tile_size=tile, seed=1)`` and counts, over all tiles, the rule tries on an empty circle
that a finished neighbour's handed-over circle raised (strew.ornament._engine._handed_over:
``_try`` called with ``circle=``) against the plain tries: how many succeed, and the mean
radius of the circle against the raised one. Nothing in the library is changed (``_try``
is wrapped for the run only).
"""

from __future__ import annotations

import argparse
import json
import time


def count(name: str, side: float, tile: float) -> dict:
    import strew.ornament._engine as E
    import strew.tiles as T

    c = dict(plain_ok=0, plain_fail=0, scaled_ok=0, scaled_fail=0, r_circle=0.0, r_scaled=0.0)
    orig = E._Grower._try

    def _try(self, goal, candidates, shift=None, circle=None):
        ok = orig(self, goal, candidates, shift, circle)
        if circle is None:
            c["plain_ok" if ok else "plain_fail"] += 1
        else:
            c["scaled_ok" if ok else "scaled_fail"] += 1
            c["r_circle"] += float(circle.radius)
            c["r_scaled"] += float(goal.radius)
        return ok

    E._Grower._try = _try
    try:
        t0 = time.process_time()
        arr = T.tiled("ornament", name, (side, side), tile_size=tile, seed=1)
        cpu = time.process_time() - t0
    finally:
        E._Grower._try = orig
    n = c["scaled_ok"] + c["scaled_fail"]
    c["r_circle"] = c["r_circle"] / n if n else float("nan")
    c["r_scaled"] = c["r_scaled"] / n if n else float("nan")
    c["scaled_fail_share"] = c["scaled_fail"] / n if n else float("nan")
    m = c["plain_ok"] + c["plain_fail"]
    c["plain_fail_share"] = c["plain_fail"] / m if m else float("nan")
    c["elements"] = len(arr)
    c["cpu_s"] = cpu
    return c


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--json", required=True)
    ap.add_argument("--patterns", default="dots,hierarchy,willow")
    ap.add_argument("--side", type=float, default=160.0)
    ap.add_argument("--tile", type=float, default=40.0)
    ap.add_argument("--quick", action="store_true", help="dots only (a check of the script)")
    args = ap.parse_args()
    names = ["dots"] if args.quick else args.patterns.split(",")
    out = {"command": f"python benchmarks/dot19r_handover.py --patterns {','.join(names)} --side {args.side:g} --tile {args.tile:g}", "patterns": {}}
    for name in names:
        c = count(name, args.side, args.tile)
        out["patterns"][name] = c
        print(f"{name}: raised tries {c['scaled_ok']} ok / {c['scaled_fail']} failed ({c['scaled_fail_share']:.2f}); "
              f"plain {c['plain_ok']} ok / {c['plain_fail']} failed ({c['plain_fail_share']:.3f}); "
              f"radius {c['r_circle']:.2f} -> {c['r_scaled']:.2f}; {c['elements']} el, {c['cpu_s']:.1f} CPU s", flush=True)
    with open(args.json, "w") as f:
        json.dump(out, f, indent=1)


if __name__ == "__main__":
    main()
