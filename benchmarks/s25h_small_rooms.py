"""Helper s25h: where a three sizes exemplar's small stones go missing in synth.

For each CLASS:H:V:SEEDS, prints per kind-in-exemplar: the exemplar's room rate for one
more (``_grow._room_rate``, plain and ``smallest``; inf: no rule), the exemplar's rooms
over its count (the ``ROOM_SHARE`` test), and, when :func:`fill_room` runs, the output's
rooms for the kind and the cap (``_room_cap``) against the exemplar's rate.

    PYTHONPATH=TREE/src:benchmarks python benchmarks/s25h_small_rooms.py three_sizes:2:15:1
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
import shapely

from grow_variants import _harder_suite
from synth_variants import _harder
import strew.synth._grow as G
from strew import Region
from strew.synth import synthesize


def exemplar_rooms(prep):
    """Rooms per kind in the exemplar (as _room_rate counts them, without the share test)."""
    sel = prep.selected_elements & ~prep.void
    res = {}
    for s, dom in enumerate(prep.domains):
        ids = np.flatnonzero(sel & (prep.source == s))
        cen, rad, tri = G.circumcircles(prep.pos[ids])
        rc, sk = prep.rc[ids], prep.skind[ids]
        margin = 2.0 * float(rc.max())
        inner = dom.buffer(-margin)
        inside = shapely.contains_xy(inner, cen[:, 0], cen[:, 1])
        inside[inside] = shapely.distance(dom.exterior, shapely.points(cen[inside])) >= rad[inside] + margin
        for k in np.unique(sk):
            mine = np.flatnonzero(sk == k)
            m = mine[np.argmin(rc[mine])]
            need = np.maximum(rc[m] + rc[tri], prep.min_dist[k, sk[tri]]).max(axis=1)
            fit = np.flatnonzero(inside & (rad >= need))
            rooms = len(G._greedy_rooms(cen[fit], rad[fit], 2.0 * rc[m]))
            res[int(k)] = (rooms, len(mine) * inner.area / dom.area, rooms / (len(mine) * inner.area / dom.area))
    return res


orig = G.fill_room


def fill_room(state, room=None, since=0):
    prep = state.prep
    print("   rate", np.round(G._room_rate(prep) * 1e4, 3), "rate smallest", np.round(G._room_rate(prep, smallest=True) * 1e4, 3), "(per 1e4)")
    print("   exemplar rooms (rooms, count inner, share):", {k: (a, round(b, 1), round(c, 3)) for k, (a, b, c) in exemplar_rooms(prep).items()}, "ROOM_SHARE", G.ROOM_SHARE)
    print("   size_class per skind:", [int(prep.size_class[prep.skind == q][0]) for q in range(int(prep.skind.max()) + 1)])
    vis = np.flatnonzero(~prep.void[state.src])
    for k in range(int(prep.skind.max()) + 1):
        m = np.flatnonzero(prep.skind == k)
        m = m[np.argmin(prep.rc[m])]
        cen, rad, tri = G.circumcircles(state.pos[vis])
        s_tri = state.src[vis[tri]]
        nk = np.maximum(prep.rc[m] + prep.rc[s_tri], prep.min_dist[k, prep.skind[s_tri]]).max(axis=1)
        ok = rad >= nk
        ok[ok] = state.in_domain(cen[ok])
        fit = np.flatnonzero(ok)
        rooms = len(G._greedy_rooms(cen[fit], rad[fit], 2.0 * prep.rc[m]))
        print(f"   kind {k}: output rooms {rooms} over area {state.region.geometry.area:.0f}; cap {G._room_cap(state, k)}")
    n = orig(state, room, since)
    print("   fill_room added", n)
    return n


if __name__ == "__main__":
    G.fill_room = fill_room
    mk = _harder_suite()
    for spec in sys.argv[1:]:
        cls, h, v, seeds = spec.split(":")
        kw = _harder()[cls][int(h)]
        ex = mk.make_exemplar(cls, rng=int(v), **kw)
        print("==", spec, kw, "kinds", list(ex.kinds))
        x0, y0, x1, y1 = ex.region.bounds
        for seed in [int(s) for s in seeds.split(",")]:
            out = synthesize(ex, Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed, measure=False)
            print("  seed", seed, {k: int(np.sum(out.kind == i)) for i, k in enumerate(out.kinds)})
