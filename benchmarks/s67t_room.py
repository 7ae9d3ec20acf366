"""Helper s67t: free room for one more small / medium stone inside the frame less ``margin`` (26.8), in
the exemplar, its generator drawn 3.5x larger (svar13i's oracle) and synth's outputs: the share of
20,000 uniform points (rng 0) at which a stone of that kind fits, a point fitting where its distance to
the nearest element of each kind k is at least the exemplar's smallest distance between that kind and k.

    PYTHONPATH=src:benchmarks python benchmarks/s67t_room.py three_sizes:h8s41 1,2,3
"""
import sys

import numpy as np
import shapely
from scipy.spatial import cKDTree

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from grow_variants import _harder_suite
from svar13i_oracle import big_params
from synth_variants import _harder, run

KINDS = ("small", "medium", "large")


def dmin(ex):
    xy, kn = np.asarray(ex.xy), np.asarray(ex.kind_names)
    out = {}
    for a in KINDS[:2]:
        for b in KINDS:
            pa, pb = xy[kn == a], xy[kn == b]
            d = cKDTree(pb).query(pa, k=2 if a == b else 1)[0]
            d = d[:, 1] if a == b else d
            out[a, b] = float(d.min())
    return out


def room(arr, dm, margin=26.8):
    g = arr.region.geometry.buffer(-margin)
    x0, y0, x1, y1 = g.bounds
    rng = np.random.default_rng(0)
    p = rng.uniform((x0, y0), (x1, y1), (40000, 2))
    p = p[shapely.contains_xy(g, p[:, 0], p[:, 1])][:20000]
    xy, kn = np.asarray(arr.xy), np.asarray(arr.kind_names)
    res = {}
    for a in KINDS[:2]:
        ok = np.ones(len(p), bool)
        for b in KINDS:
            pb = xy[kn == b]
            if len(pb):
                ok &= cKDTree(pb).query(p)[0] >= dm[a, b]
        res[a] = round(float(ok.mean()), 4)
    return res


def main():
    cls, label = sys.argv[1].split(":")
    i, _, v = label[1:].partition("s")
    mk = _harder_suite()
    kw = _harder()[cls][int(i)]
    ex = mk.make_exemplar(cls, rng=int(v), **kw)
    dm = dmin(ex)
    print(f"== {sys.argv[1]} exemplar min distances {{(a, b): d}} {({k: round(x, 2) for k, x in dm.items()})}")
    print(f"  exemplar       room {room(ex, dm)}", flush=True)
    big = big_params(cls, kw, 3.5)
    for d in range(2):
        print(f"  oracle d{d}      room {room(mk.make_exemplar(cls, rng=int(v) + 1000 * d, **big), dm)}", flush=True)
    for s in [int(x) for x in sys.argv[2].split(",")] if len(sys.argv) > 2 else []:
        out, _ = run(ex, 3.5, s, None)
        print(f"  synth seed {s}   room {room(out, dm)}", flush=True)


if __name__ == "__main__":
    main()
