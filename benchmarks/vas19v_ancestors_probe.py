"""How often a tiled ornament world keeps ancestors for a success beyond the later tiles'
reach (strew.ornament._context.keep_ancestors, issue 19.4, vas19v), per pattern.

``PYTHONPATH=TREE/src python benchmarks/vas19v_ancestors_probe.py [--patterns willow,flowers,dots,hierarchy,spirals]
[--side 240 --tile 60] [--json F]`` grows ``strew.tiles.tiled("ornament", NAME, (side, side),
tile_size=tile, seed=1)`` and prints, per pattern, the tiles' calls of keep_ancestors, the
rows whose ``placed`` it set (0: every tile keeps what it kept before, the world is the same
as without it, and no pattern but the vase names tile anchors) and the world's digest
(benchmarks/spi19p_identity.py's). On a tree without keep_ancestors it prints the digest alone.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))


def main() -> None:
    import strew.ornament._context as C
    from spi19p_identity import digest
    from strew.tiles import tiled

    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--patterns", default="willow,flowers,dots,hierarchy,spirals")
    ap.add_argument("--side", type=float, default=240.0)
    ap.add_argument("--tile", type=float, default=60.0)
    ap.add_argument("--json", default=None)
    a = ap.parse_args()
    count = {"calls": 0, "rows": 0}
    if hasattr(C, "keep_ancestors"):
        orig = C.keep_ancestors

        def wrapped(element, parent, group, placed, far):
            out = orig(element, parent, group, placed, far)
            count["calls"] += 1
            count["rows"] += int((out != np.asarray(placed, bool)).sum())
            return out

        C.keep_ancestors = wrapped
    res = {}
    for name in [p for p in a.patterns.split(",") if p]:
        count.update(calls=0, rows=0)
        t0 = time.process_time()
        arr = tiled("ornament", name, (a.side, a.side), tile_size=a.tile, seed=1)
        res[name] = dict(elements=len(arr), digest=digest(arr), keep_ancestors_calls=count["calls"], rows_set=count["rows"])
        print(f"{name}: {len(arr)} el {res[name]['digest']} keep_ancestors calls {count['calls']} rows set {count['rows']} "
              f"({time.process_time() - t0:.1f} CPU s)", flush=True)
    if a.json:
        Path(a.json).write_text(json.dumps(res, indent=1) + "\n")


if __name__ == "__main__":
    main()
