"""Issue 13 point 1, helper peb13m: where synth's isolated pebbles come from on two-size
exemplars (--harder two_sizes). Tags every output element by the step that placed it
(growth incl. the seed patch, anchor rings, fill_room, fill_holes), and for interior
pebbles (2 s from the frame) gives the share with no pebble within 1 s ("isolated") by
step; for grown pebbles also whether their exemplar source pebble had a pebble within
1 s in the exemplar (a copy that lost its pebble neighbours).

Also: the copied pebbles whose exemplar pebble partner in the copied neighbourhood was
placed, lost in placing or refused by the static tests; pebbles evicted by larger
elements (``_grow._evict``); the room left for one more pebble. Experiments (monkeypatched,
nothing in strew changes): PEB_NO_HOLES=1 (no fill_holes), PEB_NO_LARGER=1 (no
larger-in-class order), PEB_NO_YIELD=1 (nothing yields to larger elements).

    python benchmarks/peb13m_origin.py INDEX VSEED [--seeds 1,2] [--scale 3.5]
"""

from __future__ import annotations

import argparse
import sys

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from grow_variants import _harder_suite  # noqa: E402
from synth_variants import _harder  # noqa: E402

from strew import Region  # noqa: E402
from strew.metrics import fidelity  # noqa: E402
from strew.synth import _grow as G  # noqa: E402
from strew.synth import synthesize  # noqa: E402

CAP: dict = {}


def _wrap(name):
    f = getattr(G, name)

    def w(state, *a, **k):
        CAP["state"] = state
        CAP.setdefault("marks", []).append((name, state.n))
        out = f(state, *a, **k)
        CAP["marks"].append((name + ":end", state.n))
        return out

    setattr(G, name, w)


import os  # noqa: E402

if os.environ.get("PEB_NO_HOLES"):
    G.FILL_HOLES = False
if os.environ.get("PEB_NO_LARGER"):
    G._larger_in_class = lambda prep: np.zeros(len(prep.kind))

if os.environ.get("PEB_NO_YIELD"):
    G._split_conflicts = lambda state, pts, src, visible_only: state.conflicts(pts, src, visible_only=visible_only)

_EV = {"on": False}
_ev0 = G._evict


def _evict(state, new, *, voids):
    _EV["on"] = True
    try:
        return _ev0(state, new, voids=voids)
    finally:
        _EV["on"] = False


G._evict = _evict
from strew.synth._state import SynthState  # noqa: E402

_rm0 = SynthState.remove


def _remove(self, mask):
    if _EV["on"]:
        m = np.flatnonzero(mask[: self.n])
        CAP.setdefault("evicted", []).append((self.pos[m].copy(), self.kind[m].copy()))
    return _rm0(self, mask)


SynthState.remove = _remove

_gp0 = G.K.generate_proposals
_pp0 = G.K.place_proposals


def _gp(*a):
    r = _gp0(*a)
    CAP["ex"] = r[1]
    return r


def _pp(costs, slack, out_ptr, count, ppos, pr, psk, md, ok, c, f, cell, pslot, pfree, okey, gen):
    placed, sok = _pp0(costs, slack, out_ptr, count, ppos, pr, psk, md, ok, c, f, cell, pslot, pfree, okey, gen)
    st = CAP.get("state")
    ex = CAP["ex"]
    prep = CAP["prep"]
    pk, s = CAP["pk"], CAP["s"]
    tally = CAP.setdefault("tally", np.zeros(5, np.int64))
    for g in range(len(count)):
        w, cn = out_ptr[g], count[g]
        if cn == 0 or not placed[w:w + cn].any():
            continue
        ids = np.arange(w, w + cn)
        e = ex[ids]
        for t in ids[placed[ids] & (e >= 0)]:
            if prep.kind[ex[t]] != pk:
                continue
            # exemplar pebble partners of ex[t] within 1 s among this copy's proposals
            part = ids[(e >= 0) & (ids != t)]
            part = part[(prep.kind[ex[part]] == pk) & (np.hypot(*(prep.pos[ex[part]] - prep.pos[ex[t]]).T) <= s)]
            if len(part) == 0:
                tally[0] += 1  # no pebble partner in the copy
            elif placed[part].any():
                tally[1] += 1
            elif ok[part].any():
                tally[2] += 1  # partner passed static checks, lost in placing
            else:
                tally[3] += 1  # partner refused by the static checks
    return placed, sok


G.K.place_proposals = _pp
G.K.generate_proposals = _gp

for _n in ("_complete_anchor_rings", "fill_room", "fill_holes"):
    _wrap(_n)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("index", type=int)
    ap.add_argument("vseed", type=int)
    ap.add_argument("--seeds", default="1,2")
    ap.add_argument("--scale", type=float, default=3.5)
    a = ap.parse_args()
    kw = _harder()["two_sizes"][a.index]
    ex = _harder_suite().make_exemplar("two_sizes", rng=a.vseed, **kw)
    d0, _ = cKDTree(ex.xy).query(ex.xy, k=2)
    s = float(np.median(d0[:, 1]))
    pb_name = "pebble"
    print(f"two_sizes {kw} vseed {a.vseed} s={s:.2f}")
    x0, y0, x1, y1 = ex.region.bounds
    for seed in [int(v) for v in a.seeds.split(",")]:
        CAP.clear()
        from strew.synth._api import new_state
        CAP["prep"] = new_state(ex, None).prep
        CAP["pk"] = list(CAP["prep"].shapes).index("pebble")
        CAP["s"] = s
        out = synthesize(ex, Region.rectangle(a.scale * (x1 - x0), a.scale * (y1 - y0)), rng=seed, measure=False)
        rep = fidelity(ex, out, eq5=False, local=False)
        nnm = " ".join(f"{k}={m.value:.3g}/{m.tolerance:.3g}{'' if m.passed else '!'}" for k, m in rep.metrics.items() if k.startswith(("nn[", "density")))
        print(f"seed {seed}: {'pass' if rep.faithful else 'FAIL'} {nnm}")
        st = CAP["state"]
        prep = st.prep
        n = st.n
        tag = np.full(n, "grow", object)
        for (nm, lo), (_, hi) in zip(CAP["marks"][0::2], CAP["marks"][1::2]):
            tag[lo:hi] = nm
        pos = st.pos[:n]
        vis = ~prep.void[st.src[:n]]
        kn = np.array([prep.names_kind(k) if hasattr(prep, "names_kind") else k for k in st.kind[:n]])
        pk = list(prep.shapes).index(pb_name) if pb_name in prep.shapes else None
        is_pb = (st.kind[:n] == pk) & vis
        bx0, by0, bx1, by1 = st.region.geometry.bounds
        inner = (pos[:, 0] > bx0 + 2 * s) & (pos[:, 0] < bx1 - 2 * s) & (pos[:, 1] > by0 + 2 * s) & (pos[:, 1] < by1 - 2 * s)
        tp = cKDTree(pos[is_pb])
        d, _ = tp.query(pos[inner & is_pb], k=2)
        iso = d[:, 1] > s
        tg = tag[inner & is_pb]
        # exemplar: source pebble's pebble neighbours
        epb = (prep.kind == pk) & ~prep.void
        te = cKDTree(prep.pos[epb])
        de, _ = te.query(prep.pos, k=2)
        src_iso = np.where(epb, de[:, 1], de[:, 0]) > s
        si = src_iso[st.src[:n]][inner & is_pb]
        sk_ = (st.kind[:n] != pk) & vis
        dps = cKDTree(pos[sk_]).query(pos[inner & is_pb])[0] / s
        for t in np.unique(tag):
            mm = tg == t
            if mm.any():
                print(f"   {t}: pebble>stone nn / s deciles {np.round(np.quantile(dps[mm], [0.1, 0.5, 0.9]), 2)}")
        # room left for one more pebble: share of a fine grid of interior points where a
        # copy of a pebble would intersect nothing (state.conflicts)
        pid = np.flatnonzero(prep.kind == pk)[0]
        gx, gy = np.meshgrid(np.arange(bx0 + 2 * s, bx1 - 2 * s, s / 8), np.arange(by0 + 2 * s, by1 - 2 * s, s / 8))
        gp = np.c_[gx.ravel(), gy.ravel()]
        free = ~st.conflicts(gp, np.full(len(gp), pid))
        print(f"   room for a pebble: {free.mean():.4f} of interior grid points")
        print(f"seed {seed}: n {n}, interior pebbles {len(iso)}, isolated {iso.mean():.3f}")
        for t in np.unique(tag):
            m = tg == t
            if m.any():
                print(f"   {t:24s} pebbles {m.sum():4d} isolated {iso[m].sum():4d} ({iso[m].mean():.3f}); source pebble isolated in exemplar {si[m].mean():.3f}, of isolated ones {si[m & iso].mean() if (m & iso).any() else float('nan'):.3f}")
        tl = CAP.get("tally")
        if tl is not None:
            print(f"   placed copied pebbles: no pebble partner in copy {tl[0]}, partner placed {tl[1]}, partner lost in placing {tl[2]}, partner refused by static checks {tl[3]}")
        ev = CAP.get("evicted", [])
        if ev:
            ep = np.concatenate([e[0] for e in ev])
            ek = np.concatenate([e[1] for e in ev])
            print(f"   evicted: {len(ek)} elements, pebbles {np.sum(ek == pk)}")
            if np.any(ek == pk):
                tev = cKDTree(ep[ek == pk])
                ipos = pos[inner & is_pb]
                near_ev = tev.query_ball_point(ipos, s, return_length=True) > 0
                print(f"   interior pebbles with an evicted pebble within 1 s: isolated {near_ev[iso].mean():.3f}, not isolated {near_ev[~iso].mean():.3f}")
        print(f"   exemplar pebbles isolated (all, incl. frame) {src_iso[epb].mean():.3f}")


if __name__ == "__main__":
    main()
