"""Helper s45f: at fill_room, per kind of the smallest size class, the exemplar's rooms
per area (plain, reach-bounded), the output's rooms (plain, reach-bounded), the cap and
the budget; and the inner-density ratios (syn15_stages.ratios) before/after fill_room.

    PYTHONPATH=src:benchmarks python benchmarks/s45f_rooms.py three_sizes:p4s31 1 [--harder H:V]
"""
import sys

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
import shapely
from _runner import fidelity_suite

import strew.synth._displace as DP
import strew.synth._grow as G
from strew.metrics import fidelity

ORIG = G.fill_room


def ratios(state):
    """Per kind, elements per area away from the region's edge over the exemplar's inner density (as syn15_stages)."""
    prep = state.prep
    margin = 2.0 * float(prep.rc.max())
    dens = DP._inner_density(prep, margin)
    inner = state.region.geometry.buffer(-margin)
    vis = np.flatnonzero(~prep.void[state.src])
    p = state.pos[vis]
    k = prep.skind[state.src[vis[shapely.contains_xy(inner, p[:, 0], p[:, 1])]]]
    return np.bincount(k, minlength=len(dens))[: len(dens)] / inner.area / dens


def diag(state, room=None, since=0):
    prep = state.prep
    r0 = ratios(state)
    sel = prep.selected_elements & ~prep.void
    cls0 = prep.size_class[sel].min()
    small = np.unique(prep.skind[sel & (prep.size_class == cls0)])
    area = float(state.region.geometry.area)
    share = G.ROOM_SHARE_SMALLEST if not G._larger_short(state) else G.ROOM_SHARE
    vis = np.flatnonzero(~prep.void[state.src])
    far = G._smallest_reach(prep)
    for k in small:
        m = np.flatnonzero(sel & (prep.skind == k))
        m = m[np.argmin(prep.rc[m])]
        need = np.maximum(prep.rc[:, None] + prep.rc[[m]][None, :], prep.min_dist[prep.skind[:, None], prep.skind[[m]][None, :]]).min(axis=1)
        cen, rad, tri = G._room_circles(state, vis, need, since)
        s_tri = state.src[vis[tri]]
        nk = np.maximum(prep.rc[m] + prep.rc[s_tri], prep.min_dist[k, prep.skind[s_tri]]).max(axis=1)
        ok = rad >= nk
        plain = len(G._greedy_rooms(cen[ok], rad[ok], 2 * prep.rc[m]))
        ncls = far.shape[1] - 1
        nd = np.full((len(cen), ncls), np.inf)
        for c in range(1, ncls):
            nxt = vis[prep.size_class[state.src[vis]] == c]
            nd[:, c] = cKDTree(state.pos[nxt]).query(cen)[0]
        mine = vis[prep.skind[state.src[vis]] == k]
        od = cKDTree(state.pos[mine]).query(cen)[0]
        okr = ok & (nd <= far[k, :-1]).all(axis=1) & (od <= far[k, -1])
        reach = len(G._greedy_rooms(cen[okr], rad[okr], 2 * prep.rc[m]))
        print(f"  kind {k}: share {share} larger_short {G._larger_short(state)} far {far[k]}", flush=True)
        print(f"    exemplar rate*area: plain {G._room_rate(prep, smallest=True, share=np.inf)[k]*area:.1f} "
              f"reach {G._room_rate(prep, smallest=True, share=np.inf, reach=True)[k]*area:.1f} "
              f"(at share {share}: {G._room_rate(prep, smallest=True, share=share)[k]*area:.1f})", flush=True)
        print(f"    output rooms: plain {plain} reach {reach}; cap {G._room_cap(state, int(k))}; "
              f"saturated cands {len(G._saturated_candidates(prep, smallest=True, share=share))}", flush=True)
    got = ORIG(state, room, since)
    print(f"  fill_room added {got}; ratios {np.round(r0, 3)} -> {np.round(ratios(state), 3)}", flush=True)
    return got


G.fill_room = diag


def main():
    spec, seeds = sys.argv[1], _variants.ints(sys.argv[2])
    mk = fidelity_suite()
    cls, label = spec.split(":")[:2]
    if label.startswith("h"):
        from synth_variants import _harder

        i, _, v = label[1:].partition("s")
        ex = mk.make_exemplar(cls, rng=int(v), **_harder()[cls][int(i)])
    else:
        from fresh17_rows import exemplar

        ex = exemplar(mk, cls, label)
    from synth_variants import run

    for seed in seeds:
        out, _ = run(ex, 3.5, seed, None)
        rep = fidelity(ex, out, eq5=False, local=False)
        fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
        print(f"{spec} seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} {' '.join(fails)}", flush=True)


if __name__ == "__main__":
    main()
