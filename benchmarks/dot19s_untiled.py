"""Ornament dots untiled, byte for byte, and how often dot_to_dot's shrink is needed (issue 19.4).

``PYTHONPATH=TREE/src python benchmarks/dot19s_untiled.py --json F [--sizes 60,120,200] [--seeds 1-4]``
hashes (as benchmarks/spi19p_identity.py) ``grow_ornament("dots", S x S, rng=seed)`` for every
size and seed, and counts the dot_to_dot calls whose Appendix A dot did not fit (on the tree
with the shrink: those that shrank). Run it on two trees and compare the JSON files.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))


def main() -> None:
    import strew
    from spi19p_identity import digest
    from strew.ornament import grow_ornament

    ap = argparse.ArgumentParser()
    ap.add_argument("--json", required=True)
    ap.add_argument("--sizes", default="60,120,200")
    ap.add_argument("--seeds", default="1-4")
    args = ap.parse_args()
    a, _, b = args.seeds.partition("-")
    seeds = range(int(a), int(b or a) + 1)
    import strew.ornament._engine as E

    misfit = [0]
    orig = E.RuleContext.intersects

    def intersects(self, item, **kw):  # count the Appendix A dots that overlap (their first test)
        hit = orig(self, item, **kw)
        if hit and self.goal is not None and getattr(item, "type", None) is not None and item.type.name == "dot":
            misfit[0] += 1
        return hit

    E.RuleContext.intersects = intersects
    out = {"tree": strew.__file__, "runs": {}}
    for s in [float(v) for v in args.sizes.split(",")]:
        for seed in seeds:
            misfit[0] = 0
            arr = grow_ornament("dots", strew.Region.rectangle(s, s), rng=seed)
            out["runs"][f"{s:g}/{seed}"] = [len(arr), digest(arr), misfit[0]]
            print(f"{s:g}/{seed}", out["runs"][f"{s:g}/{seed}"], flush=True)
    with open(args.json, "w") as f:
        json.dump(out, f, indent=1)


if __name__ == "__main__":
    main()
