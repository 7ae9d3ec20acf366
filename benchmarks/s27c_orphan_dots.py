"""Helper s27c: share of output dots within 1.3 ring radii of a disc (tests/synth/test_synth_fidelity.py's
test_untuned_cluster_variants_are_faithful: > 0.9) for clusters variants and seeds at 4x the frame's area.

    PYTHONPATH=src python benchmarks/s27c_orphan_dots.py [--variants 1,3] [--seeds 1-4]
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from scipy.spatial import cKDTree

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _runner import fidelity_suite
from _variants import ints

from strew import Region
from strew.synth import synthesize


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--variants", default="1,3")
    ap.add_argument("--seeds", default="1-4")
    a = ap.parse_args()
    mk = fidelity_suite()
    for v in ints(a.variants):
        ex = mk.make_exemplar("clusters", rng=v)
        x0, y0, x1, y1 = ex.region.bounds
        row = []
        for s in ints(a.seeds):
            out = synthesize(ex, Region.rectangle(2 * (x1 - x0), 2 * (y1 - y0)), rng=s, measure=False)
            dots, discs = out.select(out.kind == out.kinds.index("dot")), out.select(out.kind == out.kinds.index("disc"))
            near = cKDTree(discs.xy).query(dots.xy)[0] < 1.3 * 12.5
            row.append(f"s{s} {near.mean():.4f} ({len(discs)} discs, {len(dots)} dots)")
        print(f"variant {v}: " + "; ".join(row), flush=True)


if __name__ == "__main__":
    main()
