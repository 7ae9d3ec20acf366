"""Helper s70t: room for one more medium stone inside the frame less 26.8 (s67t_room.py's points and
exemplar minimum distances), clearing every kind ('all') or only the medium and large ones ('no_small': the
room a largest-first dart thrower saw when it threw the medium class), in the exemplar, its generator at
3.5x (two draws) and synth's outputs; and the share of small stones standing in such no_small rooms.

    PYTHONPATH=src:benchmarks python benchmarks/s70t_room.py three_sizes:h11s44 1,2,3
"""
import sys

import numpy as np
import shapely
from scipy.spatial import cKDTree

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from grow_variants import _harder_suite
from s67t_room import dmin
from svar13i_oracle import big_params
from synth_variants import _harder, run


def room(arr, dm, margin=26.8):
    g = arr.region.geometry.buffer(-margin)
    x0, y0, x1, y1 = g.bounds
    rng = np.random.default_rng(0)
    p = rng.uniform((x0, y0), (x1, y1), (40000, 2))
    p = p[shapely.contains_xy(g, p[:, 0], p[:, 1])][:20000]
    xy, kn = np.asarray(arr.xy), np.asarray(arr.kind_names)
    ok = {}
    for b in ("small", "medium", "large"):
        ok[b] = cKDTree(xy[kn == b]).query(p)[0] >= dm["medium", b]
    ns = ok["medium"] & ok["large"]
    # greedy count of disjoint medium rooms (no_small) per 1e4
    cand = p[ns]
    taken = []
    sep = dm["medium", "medium"]
    for c in cand:
        if all(np.hypot(*(c - t)) >= sep for t in taken):
            taken.append(c)
    return dict(all=round(float((ns & ok["small"]).mean()), 4), no_small=round(float(ns.mean()), 4),
                no_small_rooms_per1e4=round(len(taken) / g.area * 1e4, 2))


def main():
    cls, label = sys.argv[1].split(":")
    i, _, v = label[1:].partition("s")
    mk = _harder_suite()
    kw = _harder()[cls][int(i)]
    ex = mk.make_exemplar(cls, rng=int(v), **kw)
    dm = dmin(ex)
    print(f"== {sys.argv[1]} exemplar min distances {({k: round(x, 2) for k, x in dm.items()})}")
    print(f"  exemplar       medium room {room(ex, dm)}", flush=True)
    big = big_params(cls, kw, 3.5)
    for d in range(2):
        print(f"  oracle d{d}      medium room {room(mk.make_exemplar(cls, rng=int(v) + 1000 * d, **big), dm)}", flush=True)
    for s in [int(x) for x in sys.argv[2].split(",")] if len(sys.argv) > 2 else []:
        out, _ = run(ex, 3.5, s, None)
        print(f"  synth seed {s}   medium room {room(out, dm)}", flush=True)


if __name__ == "__main__":
    main()
