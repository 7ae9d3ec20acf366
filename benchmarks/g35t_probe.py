"""Helper g35t: where grow's widest empty circles lie in a ``--harder`` row and why they stay.

    PYTHONPATH=src python benchmarks/g35t_probe.py CLASS:SET:VARIANT SEEDS [KEY=VALUE ...]
    e.g. PYTHONPATH=src python benchmarks/g35t_probe.py three_sizes:9:25 1-3

Grow as ``grw14y_rows.py`` (3.5x the frame, fixed mode, one attempt), with any ``GrowParams``
overrides. Printed per seed: the judge's empty_circle (q95 of the whole empty circles with
centres in the window, result / exemplar), the share of the result's circles wider than the
exemplar's q95 and its widest; for those wide circles the kinds of their three Delaunay
vertices, the centre's distance to the frame (in s = the exemplar's median nn), and the
same table for the exemplar's own top 5 %; then the hole pass (``fill_void_holes``): its
limit, how many circles exceeded it, how many were skipped by the kind-reach gate
(``_kinds_near``), refused or filled.
"""
import os
import sys
from collections import Counter

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from grow_variants import HARDER, _harder_suite  # noqa: E402

import strew._fidelity as F  # noqa: E402
import strew.grow._void_holes as vh  # noqa: E402
from strew import Region  # noqa: E402
from strew.grow import grow  # noqa: E402
from strew.metrics import fidelity  # noqa: E402

cap = []
o_stats = F._stats


def stats(sm, raw, K, s, win, *a, **k):
    cap.append((sm, raw, s, win))
    return o_stats(sm, raw, K, s, win, *a, **k)


F._stats = stats
calls = []
o_fill, o_near, o_one = vh.fill_void_holes, vh._kinds_near, vh._fill_one
cur = {}


def fill(g, lim=None, bare=False):
    cur.clear()
    cur.update(near_fail=0, refused=0, made=0, lim=vh.reference_visible_gap(g) if lim is None else lim, reach=vh.small_fill(g))
    n = o_fill(g, lim, bare)
    calls.append(dict(cur))
    return n


def near(g, cx, cy, reach):
    ok = o_near(g, cx, cy, reach)
    cur["near_fail"] += not ok
    return ok


def one(g, *a, **k):
    ok = o_one(g, *a, **k)
    cur["made" if ok else "refused"] += 1
    return ok


vh.fill_void_holes, vh._kinds_near, vh._fill_one = fill, near, one
import strew.grow._growth as gr  # noqa: E402

gr.fill_void_holes = fill


def wide_table(sm, raw, s, win, thr, names):
    import shapely

    c, r = raw.circ_c, raw.circ_r
    inw = shapely.contains_xy(win, c[:, 0], c[:, 1])
    c, r = c[inw], r[inw]
    sel = r > thr
    tree = cKDTree(sm.xy)
    _, j = tree.query(c[sel], k=3)
    combos = Counter("".join(sorted(names[sm.kind[v]][0] for v in row)) for row in j)
    edge = np.asarray(shapely.distance(sm.region.boundary, shapely.points(c[sel]))) / s
    allk = Counter(names[k][0] for k in sm.kind)
    return len(r), int(sel.sum()), combos, edge, allk, r


def main():
    spec, seeds = sys.argv[1], sys.argv[2]
    over = {}
    for kv in sys.argv[3:]:
        k, v = kv.split("=")
        over[k] = eval(v)
    cls, i, v = spec.split(":")
    ex = _harder_suite().make_exemplar(cls, rng=int(v), **HARDER[cls][int(i)])
    a, _, b = seeds.partition("-")
    x0, y0, x1, y1 = ex.region.bounds
    for seed in range(int(a), int(b or a) + 1):
        cap.clear()
        calls.clear()
        out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed, **over)
        rep = fidelity(ex, out, eq5=False, local=False)
        m = rep.metrics["empty_circle"]
        (es, er, s, ew), (rs, rr, _, rw) = cap[0], cap[1]
        names = [k for k in ex.kinds]
        ne, nwe, ce, ede, ake, re_ = wide_table(es, er, s, ew, -1, names)
        q95e = float(np.quantile(re_, 0.95))
        ne, nwe, ce, ede, ake, re_ = wide_table(es, er, s, ew, q95e, names)
        nr, nwr, cr, edr, akr, rr_ = wide_table(rs, rr, s, rw, q95e, names)
        q95r = float(np.quantile(rr_, 0.95))
        print(f"seed {seed}: n={len(out)} {'pass' if rep.faithful else 'FAIL'} empty_circle {m.value:.3f}/{m.tolerance:.3f}  s={s:.2f}"
              f"  q95 ex {q95e/s:.3f}s res {q95r/s:.3f}s  max ex {re_.max()/s:.3f}s res {rr_.max()/s:.3f}s")
        print(f"  kinds ex {dict(ake)} res {dict(akr)}  (res/ex count ratio per kind: "
              + " ".join(f"{k}:{akr[k]/ake[k]/len(out)*len(ex):.3f}" for k in ake) + " of the mean)")
        print(f"  circles > ex q95: ex {nwe}/{ne} ({nwe/ne:.3f})  res {nwr}/{nr} ({nwr/nr:.3f});"
              f" res share > 1.1 q95e {np.mean(rr_ > 1.1*q95e):.3f} (ex {np.mean(re_ > 1.1*q95e):.3f})")
        print(f"  vertex kinds of wide circles  ex {dict(ce.most_common())}  res {dict(cr.most_common())}")
        print(f"  all-circle vertex kinds ex {dict(wide_table(es, er, s, ew, -1, names)[2].most_common())}")
        print(f"  all-circle vertex kinds res {dict(wide_table(rs, rr, s, rw, -1, names)[2].most_common())}")
        print(f"  wide circle centre to frame (s): ex q10/50/90 {np.quantile(ede,[.1,.5,.9]).round(2)}"
              f"  res {np.quantile(edr,[.1,.5,.9]).round(2)}  (res frame half-width {3.5*(x1-x0)/2/s:.1f}s)")
        for c in calls:
            print(f"  hole pass: lim {c['lim']/s:.3f}s reach/s {None if c['reach'] is None else (c['reach'][1]/s).round(2)}"
                  f" kind-reach skipped {c['near_fail']} refused {c['refused']} filled {c['made']}")
        if not calls:
            print("  hole pass: not run")


if __name__ == "__main__":
    main()


def metrics(spec, seed, **over):
    """All applicable metrics of one row (value/tolerance), for headroom."""
    cls, i, v = spec.split(":")
    ex = _harder_suite().make_exemplar(cls, rng=int(v), **HARDER[cls][int(i)])
    x0, y0, x1, y1 = ex.region.bounds
    out = grow(ex, region=Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed, **over)
    rep = fidelity(ex, out, eq5=False, local=False)
    for k, m in rep.metrics.items():
        if m.applicable:
            print(f"    {k}: {m.value:.3f}/{m.tolerance:.3f}{'' if m.passed else ' FAIL'}")
    return ex, out
