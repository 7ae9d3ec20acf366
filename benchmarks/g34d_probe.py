"""Helper g34d: why grow packs a sparse exemplar denser than it is, per placed element.

    PYTHONPATH=src python benchmarks/g34d_probe.py CLASS:LABEL SEED [KEY=VALUE ...]

Grow is run as the audit's first attempt (3.5x the exemplar's frame, fixed mode), with any
``GrowParams`` overrides given as KEY=VALUE (e.g. ``relax=False fit_reach=0``). Hooks
record, per object, who made it (``ring``: a §5.4 ring slot; ``extra``: a Fig. 6e extra
seed; ``fill``: a hole pass after the growth) and, per placed element, how many placed
neighbours its seed had (``nb``), how far ``_fit_position`` and ``_nudge`` moved it and
the copied 1-ring offset it was put out at. Printed: density against the exemplar's,
element counts by origin, and the ratio of each element's nearest-neighbour distance in
the output (before and after the last relaxation) to its reference element's
nearest-neighbour distance in the exemplar, by origin and by ``nb``.
"""
import os
import sys

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _runner import fidelity_suite  # noqa: E402
from fresh17_rows import exemplar  # noqa: E402

import strew.grow._growth as gr  # noqa: E402
from strew import Region  # noqa: E402
from strew.grow import grow  # noqa: E402
from strew.grow._objects import ELEMENT  # noqa: E402

kept = []
ctx = ["start"]
origin, parent, offset, fitmove, nudgemove, nbcount, prerelax = {}, {}, {}, {}, {}, {}, {}
O = {n: getattr(gr._Grower, n) for n in ("run", "place", "_ring_edges", "new_object", "_fit_position", "_nudge", "settle")}
o_fill = gr.fill_void_holes


def run(self, *a, **k):
    kept.append(self)
    return O["run"](self, *a, **k)


unconn = {}


def place(self, s, a, *rest, **k):
    old, cur = ctx[0], ("ring", s)
    ctx[0] = cur
    nbcount[s] = len(self._last_nb)
    try:
        ok = O["place"](self, s, a, *rest, **k)
    finally:
        ctx[0] = old
    if ok:
        # placed elements near the new one that its matching did not see (no edge to it
        # before the placement: not in w(e_tar)), against the chosen reference's
        # nearest ring member
        x, y = self.xy[s]
        seen = set(self._last_nb.tolist())
        r = int(self.ref_ids[a])
        rn = float(np.hypot(*self.rings["rel"][a, :int(self.rings["n"][a])].T).min())
        near = [o for o in self.near(x, y, rn, (ELEMENT,)) if o != s]
        unconn[s] = (len([o for o in near if o not in seen]), len([o for o in near if o in seen]), rn)
    return ok


def ring_edges(self, s, *a, **k):
    old = ctx[0]
    ctx[0] = ("extra", s)
    try:
        return O["_ring_edges"](self, s, *a, **k)
    finally:
        ctx[0] = old


def new_object(self, x, y, kind):
    i = O["new_object"](self, x, y, kind)
    c = ctx[0]
    if isinstance(c, tuple):
        origin[i], parent[i] = c
        px, py = self.xy[c[1]]
        offset[i] = float(np.hypot(x - px, y - py))
    else:
        origin[i] = c
    return i


def fit_position(self, s, *a, **k):
    x0, y0 = self.xy[s]
    O["_fit_position"](self, s, *a, **k)
    x1, y1 = self.xy[s]
    fitmove[s] = float(np.hypot(x1 - x0, y1 - y0))


def nudge(self, s, kind, x, y, *a, **k):
    r = O["_nudge"](self, s, kind, x, y, *a, **k)
    nudgemove[s] = None if r is None else float(np.hypot(r[0] - x, r[1] - y))
    return r


def settle(self):
    n = self.n
    prerelax["pos"] = self.pos[:n].copy()
    return O["settle"](self)


def fill(g):
    old = ctx[0]
    ctx[0] = "fill"
    try:
        return o_fill(g)
    finally:
        ctx[0] = old


gr._Grower.run, gr._Grower.place, gr._Grower._ring_edges = run, place, ring_edges
gr._Grower.new_object, gr._Grower._fit_position, gr._Grower._nudge, gr._Grower.settle = new_object, fit_position, nudge, settle
gr.fill_void_holes = fill


def val(v):
    try:
        return eval(v, {})
    except Exception:
        return v


def q(a):
    a = np.asarray(a, dtype=float)
    if len(a) == 0:
        return "n=0"
    return f"n={len(a):4d} mean {a.mean():.3f} q10/50/90 {np.quantile(a, 0.1):.3f} {np.median(a):.3f} {np.quantile(a, 0.9):.3f}"


def main():
    spec, seed = sys.argv[1], int(sys.argv[2])
    kw = {k: val(v) for k, v in (s.split("=", 1) for s in sys.argv[3:])}
    cls, label = spec.split(":")
    ex = exemplar(fidelity_suite(), cls, label)
    x0, y0, x1, y1 = ex.region.bounds
    W, H = 3.5 * (x1 - x0), 3.5 * (y1 - y0)
    out = grow(ex, region=Region.rectangle(W, H), mode="fixed", rng=seed, **kw)
    g = kept[-1]
    n = g.n
    exy = np.asarray(ex.xy, dtype=float)
    enn = cKDTree(exy).query(exy, k=2)[0][:, 1]
    s = float(np.sqrt((x1 - x0) * (y1 - y0) / len(ex)))
    els = np.array([i for i in g.order if g.state[i] == ELEMENT])
    pos = g.pos[els]
    dens = len(els) / (W * H) / (len(ex) / ((x1 - x0) * (y1 - y0)))
    print(f"{spec} seed {seed} {kw}: n={len(out)} (elements {len(els)}, objects {n}) count density {dens:.3f}x exemplar; s={s:.2f} l_short={g.l_short:.2f}")
    print(f"  exemplar nn/s: {q(enn / s)}")
    # interior elements only (> 2 s from the frame): no frame effect
    db = np.minimum.reduce([pos[:, 0], W - pos[:, 0], pos[:, 1], H - pos[:, 1]])
    inn = db > 2 * s
    onn = cKDTree(pos).query(pos, k=2)[0][:, 1]
    pre = prerelax["pos"][els]
    pnn = cKDTree(pre).query(pre, k=2)[0][:, 1]
    ref_nn = enn[g.sub[els].astype(int)]
    org = np.array([origin.get(int(i), "?") for i in els])
    nb = np.array([nbcount.get(int(i), -1) for i in els])
    print(f"  output nn/s (interior):      {q(onn[inn] / s)}")
    print(f"  output nn/s before settle:   {q(pnn[inn] / s)}")
    print(f"  ratio out nn / ref nn:       {q((onn / ref_nn)[inn])}")
    for o in sorted(set(org)):
        m = inn & (org == o)
        print(f"   origin {o:6s}: {m.sum():4d} ({m.sum() / inn.sum():.2f})  out/ref nn {q((onn / ref_nn)[m])}")
    for lo, hi in ((0, 1), (1, 2), (2, 3), (3, 99)):
        m = inn & (nb >= lo) & (nb < hi)
        print(f"   placed nb in [{lo},{hi}): {m.sum():4d} ({m.sum() / max(inn.sum(), 1):.2f})  out/ref nn {q((onn / ref_nn)[m])}")
    fm = np.array([fitmove.get(int(i), 0.0) for i in els])
    print(f"  _fit_position moved {int((fm > 1e-9).sum())} elements; moved/s {q(fm[fm > 1e-9] / s)}")
    nm = [v for k, v in nudgemove.items() if g.state[k] == ELEMENT and v is not None]
    print(f"  _nudge moved {len(nm)} elements; /s {q(np.array(nm) / s)}")
    ro = np.array([offset[int(i)] for i in els if int(i) in offset and origin.get(int(i)) == "ring"])
    print(f"  copied ring offsets of ring-born elements /s: {q(ro / s)}")
    # the offset a ring slot put the seed at vs the distance to its parent at the end
    dpar = np.array([np.hypot(*(g.pos[int(i)] - g.pos[parent[int(i)]])) / offset[int(i)] for i in els if int(i) in parent and offset[int(i)] > 0])
    print(f"  final dist to parent / copied offset: {q(dpar)}")
    # neighbours within r of each interior element (output) against its reference
    # element's within r in the exemplar (references > r from the exemplar's frame only)
    et = cKDTree(exy)
    edb = np.minimum.reduce([exy[:, 0] - x0, x1 - exy[:, 0], exy[:, 1] - y0, y1 - exy[:, 1]])
    ot = cKDTree(pos)
    sub = g.sub[els].astype(int)
    for r in (0.8, 1.0, 1.2, 1.6):
        R = r * s
        m = inn & (edb[sub] > R)
        no = np.array([len(v) - 1 for v in ot.query_ball_point(pos[m], R)])
        nr = np.array([len(v) - 1 for v in et.query_ball_point(exy[sub[m]], R)])
        em = edb > R
        ne = np.array([len(v) - 1 for v in et.query_ball_point(exy[em], R)])
        print(f"  within {r:.1f} s: output {no.mean():.3f} per element, its references {nr.mean():.3f} (n={m.sum()}), exemplar interior {ne.mean():.3f} (n={em.sum()})")
    # Delaunay edges of the output (interior): an element's own ring slot (parent-child)
    # against edges between elements from different parents
    from scipy.spatial import Delaunay
    tri = Delaunay(pos)
    ed = set()
    for a, b, c in tri.simplices:
        for u, v in ((a, b), (b, c), (a, c)):
            ed.add((min(u, v), max(u, v)))
    ed = np.array(sorted(ed))
    L = np.hypot(*(pos[ed[:, 0]] - pos[ed[:, 1]]).T) / s
    mi = inn[ed[:, 0]] & inn[ed[:, 1]]
    gid = els
    own = np.array([parent.get(int(gid[u])) == int(gid[v]) or parent.get(int(gid[v])) == int(gid[u]) for u, v in ed])
    sib = np.array([parent.get(int(gid[u]), -1) == parent.get(int(gid[v]), -2) for u, v in ed])
    for name, m in (("parent-child", own), ("siblings", sib & ~own), ("other (fronts met)", ~own & ~sib)):
        mm = mi & m
        print(f"  output Delaunay edges {name:20s}: {mm.sum():5d} ({mm.sum() / mi.sum():.2f}) length/s {q(L[mm])}")
    print(f"  output Delaunay edges all: {q(L[mi])}; > 1.5 s {np.mean(L[mi] > 1.5):.3f}")
    # each interior element's neighbours within its reference ring's own reach: ring
    # members (relaxation targets: paired with a slot of its ring) and intruders, placed
    # before it or after it
    rank = {int(i): j for j, i in enumerate(els)}
    rm = ib = ia = nr_ = 0
    cnt = 0
    for j in np.flatnonzero(inn):
        i = int(els[j])
        if g.sub[i] < 0 or edb[int(g.sub[i])] <= 1.0 * s:
            continue
        R = 1.0 * s
        near = [int(els[v]) for v in ot.query_ball_point(pos[j], R) if v != j]
        tg = g.target[i] or {}
        back = {o for o in near if i in (g.target[o] or {})}
        for o in near:
            if o in tg or o in back:
                rm += 1
            elif rank[o] < rank[i]:
                ib += 1
            else:
                ia += 1
        nr_ += len(et.query_ball_point(exy[int(g.sub[i])], R)) - 1
        cnt += 1
    print(f"  within 1.0 s, per element (n={cnt}): ring members {rm / cnt:.3f}, intruders placed before it {ib / cnt:.3f}, after it {ia / cnt:.3f}; its reference has {nr_ / cnt:.3f}")
    u = np.array([unconn.get(int(i), (0, 0, 0)) for i in els])
    m = inn
    print(f"  at placement, placed elements nearer than the chosen reference's nearest ring member: "
          f"unseen by the matching {np.mean(u[m, 0] > 0):.3f} of placements ({u[m, 0].sum():.0f}), seen {np.mean(u[m, 1] > 0):.3f} ({u[m, 1].sum():.0f})")
    nseeds = {o: sum(1 for i, v in origin.items() if v == o) for o in set(origin.values())}
    print(f"  objects made by origin: {nseeds}")


if __name__ == "__main__":
    main()
