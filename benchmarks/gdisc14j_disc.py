"""Issue 14 point 1 (helper gdisc14j): how often grow puts a smaller kind inside a larger
kind's bounding disc, against the exemplar. For each three-sizes HARDER set given
(``--sets``, default the rows gvar14i found failing: h0, h1, h7, h9, h10, h12; variant
seeds 7, 8) and grow seeds ``--seeds``: per ordered pair (smaller kind, larger kind) the
share of the smaller kind's elements whose bounding disc (largest outline-vertex distance
from the centre) overlaps a larger element's, and the least gap between the discs, for the
exemplar and the output. Run it on two trees (``PYTHONPATH=<tree>/src``) to compare.

    python benchmarks/gdisc14j_disc.py [--sets 0,1,7] [--seeds 1-2]

JSON: ``benchmarks/results/gdisc14j_disc.json`` (or ``--json PATH``).
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

import numpy as np
import shapely
from grow_variants import HARDER, _harder_suite
from scipy.spatial import cKDTree

from strew import Region
from strew.grow import grow


def disc_radii(arr):
    out = np.empty(len(arr))
    for i, g in enumerate(arr.geometry):
        c = shapely.get_coordinates(g)
        out[i] = float(np.sqrt(((c - arr.xy[i]) ** 2).sum(axis=1)).max())
    return out


def inside_share(arr, small, large):
    """Share of ``small``-kind elements whose disc overlaps a ``large``-kind one's; least gap."""
    r = disc_radii(arr)
    s, l = np.flatnonzero(arr.kind == arr.kinds.index(small)), np.flatnonzero(arr.kind == arr.kinds.index(large))
    if len(s) == 0 or len(l) == 0:
        return float("nan"), float("nan")
    tree = cKDTree(arr.xy[l])
    d, j = tree.query(arr.xy[s], k=min(8, len(l)))
    d, j = np.atleast_2d(d.T).T, np.atleast_2d(j.T).T
    gap = d - r[s][:, None] - r[l][j]
    least = gap.min(axis=1)
    return float(np.mean(least < 0)), float(least.min())


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--sets", default="0,1,7,9,10,12")
    ap.add_argument("--seeds", default="1-2")
    ap.add_argument("--json", default=str(Path(__file__).parent / "results" / "gdisc14j_disc.json"))
    a = ap.parse_args()
    lo, _, hi = a.seeds.partition("-")
    seeds = range(int(lo), int(hi or lo) + 1)
    mk = _harder_suite()
    rows = []
    pairs = [("medium", "large"), ("small", "medium"), ("small", "large")]
    for i in (int(x) for x in a.sets.split(",")):
        kw = HARDER["three_sizes"][i]
        for v in (7, 8):
            ex = mk.make_exemplar("three_sizes", rng=v, **kw)
            exs = {f"{p}>{q}": inside_share(ex, p, q) for p, q in pairs}
            x0, y0, x1, y1 = ex.region.bounds
            for seed in seeds:
                t = time.process_time()
                out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed)
                dt = time.process_time() - t
                ous = {f"{p}>{q}": inside_share(out, p, q) for p, q in pairs}
                rows.append({"set": f"h{i}s{v}", "seed": seed, "exemplar": exs, "output": ous, "cpu_s": round(dt, 2)})
                print(f"h{i}s{v} seed {seed}: " + "  ".join(f"{k} inside {ous[k][0]:.3f} (ex {exs[k][0]:.3f}) least {ous[k][1]:.2f} (ex {exs[k][1]:.2f})" for k in ous) + f"  cpu {dt:.1f}s", flush=True)
    Path(a.json).write_text(json.dumps({"benchmark": "gdisc14j_disc", "rows": rows}, indent=1) + "\n")


if __name__ == "__main__":
    main()
