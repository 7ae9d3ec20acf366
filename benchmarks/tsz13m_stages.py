"""Issue 13 point 1, helper tsz13m: where a three_sizes output's per-kind deficit arises.

For HARDER three_sizes sets, runs synth at ``--scale`` and records each kind's count
after growth, after _complete_anchor_rings, fill_room and fill_holes, and the share of the
area where one more element of each kind fits (its smallest exemplar element, clear of
every element by max(rc_p + rc_q, min_dist)), in the exemplar (inner part) and the output,
plus how wide the output's empty circles that hold such a room are.

    python benchmarks/tsz13m_stages.py [--sets 7,4] [--variants 7] [--seeds 1,2]
"""

from __future__ import annotations

import argparse
import sys

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from grow_variants import HARDER, _harder_suite  # noqa: E402

from strew import Region  # noqa: E402
from strew.synth import _grow as G  # noqa: E402
from strew.synth import synthesize  # noqa: E402

LOG: list = []


def counts(state):
    prep = state.prep
    vis = ~prep.void[state.src]
    return np.bincount(prep.skind[state.src[vis]], minlength=int(prep.skind.max()) + 1)


def wrap(name):
    f = getattr(G, name)

    def g(state, *a, **k):
        r = f(state, *a, **k)
        LOG.append((name, counts(state).tolist(), state))
        return r

    setattr(G, name, g)


def room_share(pos, src, prep, k, box, rng, n=40000):
    """Share of the box where the smallest exemplar element of skind k fits."""
    ids = np.flatnonzero((prep.skind == k) & ~prep.void)
    m = ids[np.argmin(prep.rc[ids])]
    x0, y0, x1, y1 = box
    pts = np.c_[rng.uniform(x0, x1, n), rng.uniform(y0, y1, n)]
    tree = cKDTree(pos)
    reach = float(max(prep.rc.max() + prep.rc[m], prep.min_dist.max()))
    ok = np.ones(n, bool)
    for i, nb in enumerate(tree.query_ball_point(pts, reach)):
        nb = np.asarray(nb, np.int64)
        if len(nb) == 0:
            continue
        d = np.hypot(*(pos[nb] - pts[i]).T)
        lim = np.maximum(prep.rc[m] + prep.rc[src[nb]], prep.min_dist[k, prep.skind[src[nb]]])
        ok[i] = bool(np.all(d >= lim))
    return ok.mean(), pts[ok]


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--sets", default="7,4")
    ap.add_argument("--variants", default="7")
    ap.add_argument("--seeds", default="1,2")
    ap.add_argument("--scale", type=float, default=3.5)
    ap.add_argument("--set", action="append", default=[], help="NAME=VALUE: a module constant of strew.synth._grow")
    ap.add_argument("--no-room", action="store_true", help="skip the room shares")
    a = ap.parse_args()
    for kv in a.set:
        k, v = kv.split("=")
        setattr(G, k, type(getattr(G, k))(float(v)) if not isinstance(getattr(G, k), bool) else v == "1")
    for name in ("_complete_anchor_rings", "fill_room", "fill_holes"):
        wrap(name)
    try:
        from strew.synth import _displace as D

        f = D.fill_displaced

        def g(state, *a_, **k_):
            r = f(state, *a_, **k_)
            LOG.append(("fill_displaced", counts(state).tolist(), state))
            return r

        D.fill_displaced = g
    except ImportError:
        pass
    orig_grow_iter = G.grow
    mk = _harder_suite()
    for i in map(int, a.sets.split(",")):
        kw = HARDER["three_sizes"][i]
        for v in map(int, a.variants.split(",")):
            ex = mk.make_exemplar("three_sizes", rng=v, **kw)
            x0, y0, x1, y1 = ex.region.bounds
            for seed in map(int, a.seeds.split(",")):
                LOG.clear()
                out = synthesize(ex, Region.rectangle(a.scale * (x1 - x0), a.scale * (y1 - y0)), rng=seed, measure=False)
                state = LOG[0][2]
                prep = state.prep
                area_ratio = a.scale**2
                exc = np.bincount(prep.skind[~prep.void], minlength=int(prep.skind.max()) + 1)
                print(f"== h{i}s{v} seed {seed} {kw}  size classes per skind "
                      f"{[int(prep.size_class[prep.skind == k][0]) for k in range(len(exc))]}  room_rate {G._room_rate(prep).tolist()}")
                print(f"   exemplar counts x area: {(exc * area_ratio).round(0).tolist()}")
                for nm, c, _ in LOG:
                    print(f"   after {nm:24s} {c}  ratio {np.round(np.array(c) / (exc * area_ratio), 3).tolist()}")
                rng = np.random.default_rng(0)
                m = 2.0 * float(prep.rc.max())
                ebox = (x0 + m, y0 + m, x1 - m, y1 - m)
                W, H = a.scale * (x1 - x0), a.scale * (y1 - y0)
                obox = (m, m, W - m, H - m)
                for k in range(0 if a.no_room else len(exc)):
                    se, _ = room_share(prep.pos[~prep.void], np.flatnonzero(~prep.void), prep, k, ebox, rng)
                    so, pts = room_share(state.pos, state.src, prep, k, obox, rng)
                    # the largest empty circle around each room point (distance to nearest element minus nothing)
                    print(f"   kind {k}: room share exemplar {se:.4f} output {so:.4f}")


if __name__ == "__main__":
    main()
