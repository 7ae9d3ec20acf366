"""g70v (issue 14 point 5, speed; byte-identical output): flow mode's passes with
fewer shapely, numpy and qhull calls.

- ``_overlap_kernels.intersect_certain``: the compiled intersection test of the
  outlines' contact bisection (``_flow_net._touching``) answers as
  ``shapely.intersects`` wherever it answers, and ``_touching`` with it gives the
  shapely-only bisection's distances to the bit;
- ``_Collide.overlapping_each``: the pairs of ``overlapping`` one element at a time;
- ``_place._MEAN_EXACT``: a Python sum in order over the count is ``np.mean`` for up to
  that many values;
- ``_flow_net.triangulation``: a flow growth triangulates no set of positions twice
  (on main 7 of the hexflow growth's 38 triangulations were repeats).
"""

from __future__ import annotations

import math

import numpy as np
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st


def _star(rng, n, cx, cy, r):
    """A simple polygon: n vertices at sorted angles and random radii (often not convex)."""
    t = np.sort(rng.uniform(0, 2 * np.pi, n))
    rr = r * rng.uniform(0.3, 1.0, n)
    return shapely.Polygon(np.c_[cx + rr * np.cos(t), cy + rr * np.sin(t)])


def _pairs(seed, m):
    """Pairs (A, B about the origin, offset of B): overlapping, apart, one inside the
    other, touching exactly and nearly touching."""
    rng = np.random.default_rng(seed)
    A, B, off = [], [], []
    for _ in range(m):
        a = _star(rng, int(rng.integers(3, 26)), 0.0, 0.0, 1.0)
        if rng.random() < 0.3:
            a = a.reverse()  # clockwise rings too
        k = rng.random()
        if k < 0.2:
            # touching: a box beside a's bounding box, nudged by a hair or not at all
            _, y0, x1, y1 = a.bounds
            b = shapely.box(0.0, y0, 1.0, y1)
            o = (x1 + float(rng.choice([0.0, 1e-12, -1e-12, 1e-7, -1e-7])), 0.0)
        elif k < 0.3:
            b = _star(rng, int(rng.integers(3, 12)), 0.0, 0.0, 0.1)  # small: may lie inside a
            o = tuple(rng.uniform(-0.3, 0.3, 2))
        else:
            b = _star(rng, int(rng.integers(3, 26)), 0.0, 0.0, float(rng.uniform(0.05, 1.3)))
            o = tuple(rng.uniform(-2.2, 2.2, 2))
        A.append(a)
        B.append(b)
        off.append(o)
    A = np.array(A, dtype=object)
    B = np.array(B, dtype=object)
    off = np.array(off, dtype=float)
    ok = shapely.is_valid(A) & shapely.is_valid(B)
    return A[ok], B[ok], off[ok]


@settings(max_examples=40, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), tol=st.sampled_from([1e-9, 1e-6]))
def test_intersect_certain_answers_as_shapely(seed, tol):
    from strew.grow._overlap_kernels import intersect_certain

    A, B, off = _pairs(seed, 80)
    cb = shapely.get_coordinates(B)
    ib = shapely.get_coordinates(B, return_index=True)[1]
    moved = shapely.set_coordinates(B.copy(), cb + off[ib])
    ref = shapely.intersects(A, moved)
    oa = np.r_[0, np.cumsum(shapely.get_num_coordinates(A))].astype(np.int64)
    ob = np.r_[0, np.cumsum(shapely.get_num_coordinates(B))].astype(np.int64)
    got = np.empty(len(A), dtype=np.int8)
    k = np.arange(len(A), dtype=np.int64)
    intersect_certain(shapely.get_coordinates(A), oa, cb, ob, k, off, tol, got)
    sure = got >= 0
    assert np.array_equal(got[sure] == 1, ref[sure])
    # the exact contacts are left to shapely, most others are decided
    assert sure.mean() > 0.6
    # a subset of the pairs, in another order: the same answers
    kk = k[::-1][::2].copy()
    got2 = np.empty(len(kk), dtype=np.int8)
    intersect_certain(shapely.get_coordinates(A), oa, cb, ob, kk, off[kk], tol, got2)
    assert np.array_equal(got2, got[kk])


def test_intersect_certain_leaves_exact_contact_to_shapely():
    from strew.grow._overlap_kernels import intersect_certain

    sq = shapely.box(0.0, 0.0, 1.0, 1.0)
    A = np.array([sq, sq, sq, sq], dtype=object)
    B = np.array([sq, sq, sq, shapely.box(0.0, 0.0, 0.2, 0.2)], dtype=object)
    off = np.array([[1.0, 0.0], [1.5, 0.0], [0.5, 0.5], [0.4, 0.4]])  # edge contact, apart, overlap, inside
    oa = np.r_[0, np.cumsum(shapely.get_num_coordinates(A))].astype(np.int64)
    ob = np.r_[0, np.cumsum(shapely.get_num_coordinates(B))].astype(np.int64)
    got = np.empty(4, dtype=np.int8)
    intersect_certain(shapely.get_coordinates(A), oa, shapely.get_coordinates(B), ob, np.arange(4, dtype=np.int64), off, 1e-9, got)
    assert got.tolist() == [-1, 0, 1, 1]


def _hexflow(w_sp=14, h_sp=10):
    from strew import Region
    from strew.grow import analyze
    from strew.grow._exemplars import hex_exemplar

    ref = analyze(hex_exemplar())
    sp = ref.mean_edge
    w = w_sp * sp

    def field(p):
        a = np.radians(90.0) * np.clip(np.asarray(p)[:, 0] / w, 0, 1)
        return np.c_[np.cos(a), np.sin(a)]

    return ref, {"region": Region.rectangle(w, h_sp * sp), "mode": "flow", "flow": field}


def _grower_after(ref, kw, monkeypatch, name="relax_network"):
    """The grower of a flow growth, caught at its first call of ``_flow_net.<name>``."""
    import strew.grow._flow_net as fn
    from strew.grow import grow

    caught = {}
    orig = getattr(fn, name)

    def spy(g, *a, **k):
        caught.setdefault("g", g)
        return orig(g, *a, **k)

    monkeypatch.setattr(fn, name, spy)
    import strew.grow._growth as gr

    if hasattr(gr, name):
        monkeypatch.setattr(gr, name, spy)
    grow(ref, rng=1, relax=True, **kw)
    return caught["g"]


def test_touching_equals_the_shapely_bisection(monkeypatch):
    import strew.grow._flow_net as fn

    ref, kw = _hexflow()
    g = _grower_after(ref, kw, monkeypatch, "_contact_lengths")
    els = fn.placed(g)
    pts = g.pos[els]
    e = fn._delaunay_bonds(pts, 1.4 * g.l)
    a, b = els[e[:, 0]], els[e[:, 1]]
    L = g.l
    rng = np.random.default_rng(5)
    for lo_share, steps in ((0.5, 10), (0.6, 12), (0.66, 6)):
        lo = np.full(len(a), lo_share * L) * rng.uniform(0.9, 1.1, len(a))
        hi = np.full(len(a), 1.5 * L)
        fast = fn._touching(g, a, b, pts[e[:, 0]], pts[e[:, 1]], lo, hi, steps)
        with monkeypatch.context() as m:
            m.setattr(fn, "_simple_polygons", lambda gs: False)  # the shapely-only bisection
            slow = fn._touching(g, a, b, pts[e[:, 0]], pts[e[:, 1]], lo, hi, steps)
        assert np.isfinite(slow).any() and (slow > lo).any()  # pairs that touch at lo were bisected
        assert fast.tobytes() == slow.tobytes()


def test_overlapping_each_is_overlapping_one_by_one(monkeypatch):
    import strew.grow._flow_net as fn

    ref, kw = _hexflow()
    g = _grower_after(ref, kw, monkeypatch)
    els = fn.placed(g).tolist()
    # squeeze a patch together so that some outlines overlap
    rng = np.random.default_rng(3)
    cx, cy = g.pos[els].mean(axis=0)
    moved = [o for o in els if math.hypot(g.xy[o][0] - cx, g.xy[o][1] - cy) < 4 * g.l]
    for o in moved:
        x, y = g.xy[o]
        nx, ny = cx + 0.8 * (x - cx) + rng.normal(0, 0.05 * g.l), cy + 0.8 * (y - cy)
        g._move(o, nx, ny)
        g.geom[o] = g.element_geometry(int(g.kind[o]), nx, ny, float(g.rot[o]), float(g.scl[o]))
    one = {o: sorted(h) for o in els if (h := g.overlapping(o))}
    assert len(one) >= 5
    each = {o: sorted(h) for o, h in g.overlapping_each(els).items()}
    assert each == one


@settings(max_examples=200, deadline=None)
@given(vals=st.lists(st.floats(-1e6, 1e6, allow_nan=False, allow_infinity=False), min_size=1, max_size=7))
def test_python_sum_in_order_is_np_mean(vals):
    from strew.grow._place import _MEAN_EXACT

    assert len(vals) <= _MEAN_EXACT
    tot = 0.0
    for v in vals:
        tot += v
    assert tot / len(vals) == float(np.mean(np.array(vals)))


def test_flow_growth_triangulates_no_positions_twice(monkeypatch):
    import hashlib

    import scipy.spatial

    from strew.grow import grow

    ref, kw = _hexflow(30, 20)
    seen: list[str] = []
    orig = scipy.spatial.Delaunay

    class Counted(orig):
        def __init__(self, pts, *a, **k):
            seen.append(hashlib.sha256(np.ascontiguousarray(pts, dtype=float).tobytes()).hexdigest())
            super().__init__(pts, *a, **k)

    monkeypatch.setattr(scipy.spatial, "Delaunay", Counted)
    out = grow(ref, rng=1, relax=True, **kw)
    assert len(out) > 500
    assert len(seen) > 20
    assert len(set(seen)) == len(seen)
