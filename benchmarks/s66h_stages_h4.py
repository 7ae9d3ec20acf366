"""Helper s66h: where --harder clusters h4 (few big clusters) loses discs under s65c's ring cap, stage by
stage (after growth and after each later pass of ``_grow.grow``, passes wrapped here, src untouched): discs,
dots, stray dots (no disc within 1.25 x the exemplar ring radius), rings per size, the q95 and the largest
empty circles inside the final frame (Delaunay circumcircles of all elements, as the judge) and what borders them.

    PYTHONPATH=src:benchmarks python benchmarks/s66h_stages_h4.py VARIANT SEEDS [--cap 0|1] [--png PREFIX]

``--cap 0`` switches ``_grow.RING_CAP`` off (main's growth, same code otherwise).
"""
import functools
import sys

import numpy as np
import shapely
from scipy.spatial import Delaunay, cKDTree

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from grow_variants import _harder_suite
from synth_variants import _harder, run

import strew.synth._displace as DP
import strew.synth._farmix as FM
import strew.synth._grow as G
import strew.synth._pebbles as PB
import strew.synth._shell as SH
import strew.synth._swap as SW
import strew.synth._thin as TH
from strew.metrics import fidelity

CAP = int(sys.argv[sys.argv.index("--cap") + 1]) if "--cap" in sys.argv else 1
G.RING_CAP = bool(CAP)
STAGES = []
FRAME = [None]
RAD = [None]


def circles(xy, frame):
    """(m, 3) x, y, r of the Delaunay circumcircles wholly inside ``frame`` (a shapely polygon)."""
    tri = Delaunay(xy)
    p = xy[tri.simplices]
    a, b, c = p[:, 0], p[:, 1], p[:, 2]
    d = 2 * (a[:, 0] * (b[:, 1] - c[:, 1]) + b[:, 0] * (c[:, 1] - a[:, 1]) + c[:, 0] * (a[:, 1] - b[:, 1]))
    ok = np.abs(d) > 1e-12
    a2, b2, c2 = (a * a).sum(1), (b * b).sum(1), (c * c).sum(1)
    ux = (a2 * (b[:, 1] - c[:, 1]) + b2 * (c[:, 1] - a[:, 1]) + c2 * (a[:, 1] - b[:, 1])) / np.where(ok, d, 1)
    uy = (a2 * (c[:, 0] - b[:, 0]) + b2 * (a[:, 0] - c[:, 0]) + c2 * (b[:, 0] - a[:, 0])) / np.where(ok, d, 1)
    r = np.hypot(ux - a[:, 0], uy - a[:, 1])
    x0, y0, x1, y1 = frame.bounds
    ins = ok & (ux - r >= x0) & (ux + r <= x1) & (uy - r >= y0) & (uy + r <= y1)
    return np.c_[ux, uy, r][ins]


def shape(pos, kind, frame=None):
    frame = frame or FRAME[0]
    ins = shapely.contains_xy(frame, pos[:, 0], pos[:, 1]) if frame is not None else np.ones(len(pos), bool)
    pos, kind = pos[ins], kind[ins]
    disc, dot = pos[kind == 0], pos[kind == 1]
    d, j = cKDTree(disc).query(dot)
    near = d <= 1.25 * RAD[0]
    per = np.bincount(j[near], minlength=len(disc))
    c = circles(pos, frame) if frame is not None else np.zeros((0, 3))
    q = np.quantile(c[:, 2], 0.95) if len(c) else np.nan
    return {"discs": len(disc), "dots": len(dot), "stray": int((~near).sum()), "rings": np.bincount(per).tolist(), "q95": q,
                "top": c[np.argsort(-c[:, 2])[:5]] if len(c) else c}


def fmt(s):
    return (f"discs {s['discs']} dots {s['dots']} stray {s['stray']} rings {s['rings']} q95 {s['q95']:.2f} "
            f"largest {np.round(s['top'][:3, 2], 1).tolist()}")


def snap(state):
    keep = ~state.ghost
    return state.pos[keep].copy(), np.asarray(state.kind)[keep].copy()


def wrap(mod, name):
    f = getattr(mod, name)

    @functools.wraps(f)
    def w(state, *a, **k):
        if name == "_complete_anchor_rings":
            STAGES.append(("growth", *snap(state)))
        r = f(state, *a, **k)
        p1, k1 = snap(state)
        if len(p1) != len(STAGES[-1][1]) or not np.array_equal(p1, STAGES[-1][1]):
            STAGES.append((name, p1, k1))
        return r

    setattr(mod, name, w)


def main():
    np.set_printoptions(precision=1, suppress=True, linewidth=200)
    for mod, names in ((G, ["_complete_anchor_rings", "fill_room", "fill_holes", "fill_hub_rooms", "fill_far_hub_rooms"]),
                       (DP, ["fill_displaced"]), (SH, ["fill_beside_largest", "fill_beside_far_small"]),
                       (FM, ["trade_far_small", "trade_far_top"]), (PB, ["fill_partners"]), (SW, ["fill_swapped"]),
                       (TH, ["thin_small", "thin_orphans", "thin_crowded", "thin_edge_strays"])):
        for n in names:
            wrap(mod, n)
    v = int(sys.argv[1])
    ex = _harder_suite().make_exemplar("clusters", rng=v, **_harder()["clusters"][4])
    exd, exk = np.c_[ex.x, ex.y], np.asarray(ex.kind)
    d, _ = cKDTree(exd[exk == 0]).query(exd[exk == 1])
    RAD[0] = float(np.median(d))
    print(f"== clusters h4s{v} cap={CAP} exemplar: {fmt(shape(exd, exk, ex.region.geometry))} ring radius {RAD[0]:.2f}")
    for seed in _variants.ints(sys.argv[2]):
        STAGES.clear()
        out, _ = run(ex, 3.5, seed, None)
        FRAME[0] = out.region.geometry
        rep = fidelity(ex, out, eq5=False, local=False)
        m = rep.metrics["empty_circle"]
        print(f" seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} empty_circle {m.value:.3f}/{m.tolerance:.3f}")
        for name, p, k in STAGES:
            print(f"  {name:<22}: n {len(p)} {fmt(shape(p, k))}")
        fo = shape(np.c_[out.x, out.y], np.asarray(out.kind))
        print(f"  {'final':<22}: n {len(out)} {fmt(fo)}")
        print(f"  final largest circles (x, y, r): {np.round(fo['top'], 1).tolist()}")
        np.savez(f"/tmp/s66h/h4s{v}_cap{CAP}_s{seed}.npz", **{f"{i}_{n}": np.c_[p, k] for i, (n, p, k) in enumerate(STAGES)},
                 final=np.c_[out.x, out.y, np.asarray(out.kind)])


if __name__ == "__main__":
    main()
