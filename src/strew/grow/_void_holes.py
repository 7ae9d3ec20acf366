"""Fixed mode, exemplars with void kinds: holes among the visible elements that voids
took (issue 14 point 1, untuned exemplars; not in the paper).

Void elements (synth's §5.6 convention) stand for the empty space a texture keeps
between visible ones; grow copies them as any kind (§5.2 matches them, §5.4 seeds
them). Where a void's seed is matched before the visible seeds around it and those
die later (crowded, §5.1's priority wait), a visible element's place is left to the
voids, and the 1-ring matching never comes back to it (§5.2 matches seeds only; a
placed void is never re-matched). Sparse apples drawn saturated (no apple-sized gap
anywhere in the exemplar) grew apple-sized holes of voids: the visible elements'
largest empty circles (q95) 13-23 % wider than the exemplar's (the fidelity judge
leaves voids out). After the growth, each empty circle of the placed visible elements
wider than any the exemplar's visible elements leave (its interior circles, wholly
inside its frame, as the judge measures them) has its voids taken out and a seed of
the visible kind around it put at its centre; the seed is matched (§5.2) and placed
(§5.4) as any other, and its ring's void seeds grow back with the rest of the growth.
If the placement is refused, the voids are put back as they were. The holes are
filled widest first and only until the result has the exemplar's visible density
(:func:`void_budget`; §5 asks no density): filling every one overshot where grow's
result keeps more wide holes than the class's own process (fresh draw 23, spacing 24:
100 holes filled, 1.16 x the exemplar's apples), and a gate on the exemplar's count of
whole circles (30) left a 24-apple exemplar with 29 unfilled (0.87 x).

The same pass runs on irregular exemplars without voids (``GrowParams.open_holes``,
``_Grower._irregular``: long thin sticks grew holes wider than any of the exemplar's,
empty_circle 0.104-0.113 against 0.1), and on the hubs of clustered exemplars
(``GrowParams.hub_holes``, :func:`strew.grow._clusters.hub_hole`); there no void is
taken out, and a hub refused at its fitted position is tried at the circle's centre.
With kinds of several sizes (``GrowParams.open_holes``, :func:`small_fill`) the element
put in a hole is of the smallest kind, and only where it would stand as near each kind
as the reference's smallest elements do (two sizes of nearly one size left pebbles'
places empty: empty_circle up to 0.134 against 0.1).
"""

from __future__ import annotations

import math

import numpy as np

from .._kernels.geometry import circumcircles
from ._objects import DEAD, ELEMENT, SEED

__all__ = ["reference_visible_gap", "reference_visible_density", "visible_density", "void_budget", "small_budget", "fill_void_holes", "reseed_voids", "small_fill"]

#: the fewest whole empty circles of the exemplar's visible elements that tell its widest
MIN_CIRCLES = 30
#: kinds of several sizes: the reference's quantile of the smallest kind's nearest
#: distances to each kind that a hole's centre must have an element of that kind within
#: (the fidelity judge's highest decile; see :func:`small_fill`)
SMALL_DECILE = 0.9
#: the hole pass's second round (``toward``, :func:`_toward_kinds`): the farthest a
#: small element's spot moves from a hole's centre, a fraction of the hole's radius
TOWARD_CAP = 0.5
#: the fewest reference elements of the smallest kind that see their nearest one of a
#: kind within the frame, for that kind's reach to be told (else it asks nothing)
MIN_SMALL = 10


def _visible(g, kinds: np.ndarray) -> np.ndarray:
    return ~g.void_kind[kinds]


def _whole_circles(g) -> tuple[np.ndarray, np.ndarray] | None:
    """The empty circles of the exemplar's visible elements (circumcircles of their
    Delaunay triangles, the non-degenerate ones): radii, shape (m,), and whether each
    lies wholly inside the exemplar's frame, bool (m,) (all, without a frame). None with
    fewer than 4 visible elements or a degenerate set. Cached on ``g``."""
    cached = getattr(g, "_ref_whole_circles", False)
    if cached is not False:
        return cached
    from scipy.spatial import Delaunay, QhullError

    ex = g.ref.exemplar
    pts = ex.xy[_visible(g, g.ex_kind)]
    out = None
    if len(pts) >= 4:
        try:
            tri = Delaunay(pts)
        except QhullError:
            tri = None
        if tri is not None:
            a, b, c = (pts[tri.simplices[:, q]] for q in range(3))
            cen, rr, _ = circumcircles(a, b, c)
            if ex.region is not None and len(cen):
                inner = ex.region.contains(cen) & (ex.region.distance_to_boundary(cen) >= rr)
            else:
                inner = np.ones(len(cen), dtype=bool)
            out = (rr, inner)
    g._ref_whole_circles = out
    return out


def reference_visible_gap(g) -> float:
    """The widest empty circle (radius) of the exemplar's visible elements whose circle
    lies wholly inside its frame (as ``strew.metrics.fidelity``'s ``empty_circle``),
    and at least their least distance apart; 0 when there is none.

    Without void kinds the widest circle needs :data:`MIN_CIRCLES` whole circles (else
    0: nothing is filled). With void kinds there is no such gate: how many holes are
    filled is told by the exemplar's density instead (:func:`reference_visible_density`),
    and the limit only keeps a filled element as far from the ring around as the
    exemplar's visible elements stand apart."""
    cached = getattr(g, "_ref_visible_gap", None)
    if cached is not None:
        return cached
    pts = g.ref.exemplar.xy[_visible(g, g.ex_kind)]
    out = 0.0
    if len(pts) >= 4:
        circles = _whole_circles(g)
        if circles is not None:
            rr, inner = circles
            # the widest circle is told only by enough whole circles (30, as the
            # fidelity judge's quantiles need): with fewer the exemplar does not say
            # how wide its holes are, and nothing is filled (sparse apples at default
            # parameters, 9-25 whole circles: filled, they grew 22 % more apples and
            # half the voids)
            if int(inner.sum()) < MIN_CIRCLES and not bool(g.void_kind.any()):
                g._ref_visible_gap = 0.0
                return 0.0
            if bool(inner.any()):
                out = float(rr[inner].max())
        # ... and at least the visible elements' least distance apart: a visible element
        # put at the centre of a narrower circle would stand nearer the ring around it
        # than the exemplar ever has two (sparse apples at default parameters, whose
        # widest circle is 0.94 of that distance, grew 12 % too many: density failed)
        from scipy.spatial import cKDTree

        out = max(out, float(cKDTree(pts).query(pts, k=2)[0][:, 1].min()))
    g._ref_visible_gap = out
    return out


def visible_density(xy: np.ndarray, region, box=None) -> float:
    """Elements (the visible ones: ``xy``) per unit area of their Voronoi cells that no
    element beyond the frame could change: a cell counts when each of its vertices lies
    inside the frame at least as far from its boundary as from the cell's element (its
    empty circle is whole). Neither the frame nor a band along it biases the figure (the
    exemplar's dart keeps its visible elements half their spacing off the frame, a band
    of voids only: the visible count over the frame's area is 0.80-1.00 of the
    interior's). ``region`` the frame (a :class:`strew.Region`), or None and ``box``
    (x0, y0, x1, y1); nan when no cell counts."""
    counted = _counted_cells(xy, region, box)
    if counted is None:
        return float("nan")
    ok, area = counted
    return int(ok.sum()) / area if area > 0 else float("nan")


def _counted_cells(xy: np.ndarray, region, box=None) -> tuple[np.ndarray, float] | None:
    """Which elements' Voronoi cells count (:func:`visible_density`), bool (n,), and
    those cells' total area; None with fewer than 4 elements or a degenerate set."""
    import shapely
    from scipy.spatial import QhullError, Voronoi

    xy = np.asarray(xy, dtype=float)
    if len(xy) < 4:
        return None
    try:
        vor = Voronoi(xy)
    except QhullError:
        return None
    geom = region.geometry if region is not None else shapely.box(*box)
    vv = vor.vertices
    vd = np.where(shapely.contains_xy(geom, vv[:, 0], vv[:, 1]), shapely.distance(geom.boundary, shapely.points(vv)), -1.0)
    ok = np.zeros(len(xy), dtype=bool)
    area = 0.0
    for i, ri in enumerate(vor.point_region.tolist()):
        reg = vor.regions[ri]
        if not reg or -1 in reg:
            continue
        idx = np.asarray(reg, dtype=np.int64)
        p = vv[idx]
        if bool(np.any(vd[idx] < np.hypot(p[:, 0] - xy[i, 0], p[:, 1] - xy[i, 1]))):
            continue
        c = p.mean(axis=0)
        p = p[np.argsort(np.arctan2(p[:, 1] - c[1], p[:, 0] - c[0]), kind="stable")]
        area += 0.5 * abs(float(np.dot(p[:, 0], np.roll(p[:, 1], -1)) - np.dot(p[:, 1], np.roll(p[:, 0], -1))))
        ok[i] = True
    return ok, area


def reference_visible_density(g) -> float:
    """The exemplar's visible elements per unit area (:func:`visible_density`)."""
    cached = getattr(g, "_ref_visible_density", None)
    if cached is not None:
        return cached
    ex = g.ref.exemplar
    pts = ex.xy[_visible(g, g.ex_kind)]
    if ex.region is not None:
        out = visible_density(pts, ex.region)
    elif len(pts):
        out = visible_density(pts, None, (*pts.min(axis=0), *pts.max(axis=0)))
    else:
        out = float("nan")
    g._ref_visible_density = out
    return out


def reference_tells_holes(g) -> bool:
    """Has the exemplar enough whole empty circles of its visible elements to tell how
    wide its holes are in each half of its frame (2 x :data:`MIN_CIRCLES`, as the
    fidelity judge's ``empty_circle`` needs for its quantile and its tolerance)? Then
    every hole wider than its widest (:func:`reference_visible_gap`) is filled, as
    without voids; else only the density's deficit (:func:`void_budget`).

    Crowded apples among small voids (``--varied`` sparse apples p2: 103-120 whole
    circles) filled only to the density left holes the exemplar never has
    (empty_circle 0.142 against 0.123, p2s12; 0.148 against 0.1, p2s20), where filling
    them all passes (density 1.06-1.12 x); sparse apples (24-59 circles, the judge
    leaves their empty circles out) filled them all to 1.10-1.16 x (p0s23, p0s24).
    """
    cached = getattr(g, "_ref_tells_holes", None)
    if cached is not None:
        return cached
    circles = _whole_circles(g) if g.ref.exemplar.region is not None else None
    out = circles is not None and int(circles[1].sum()) >= 2 * MIN_CIRCLES
    g._ref_tells_holes = out
    return out


def void_budget(g) -> int:
    """Exemplars with void kinds: how many holes to fill, the visible elements the
    result lacks to have the exemplar's visible density (:func:`visible_density`, the
    result's placed elements in its region); 0 when it has as many or either density
    is not told.

    Not in the paper (§5 grows until the seeds run out, with no density asked; §5.4
    never returns to a place). Filling every hole wider than the limit overshot:
    grow's result keeps more wide holes AND more near pairs than the exemplar (the
    visible elements' whole circles wider than the exemplar's upper decile: 26-37 %
    of the result's against 10-12 % of the exemplar's, sparse apples of draws 21-24,
    pass off), so filling down to the exemplar's share of wide holes put 15-20 % too
    many apples (``--varied`` sparse apples p0s23: 1.16x, 100 holes filled where the
    class's own process leaves 39), while without a fill the apples stay at
    0.85-0.97 of the exemplar's density (v24: 0.87x). The deficit itself is what
    tells how many (helper g34s, ``benchmarks/g34s_probe.py``).
    """
    d_ex = reference_visible_density(g)
    if not math.isfinite(d_ex) or d_ex <= 0:
        return 0
    placed = np.asarray([i for i in g.order if g.state[i] == ELEMENT], dtype=np.int64)
    if len(placed) < 4:
        return 0
    xy = g.pos[placed[_visible(g, g.kind[placed])]]
    if g.region is not None:
        d_out = visible_density(xy, g.region)
    else:
        d_out = visible_density(xy, None, (*g.pos[placed].min(axis=0), *g.pos[placed].max(axis=0)))
    if not math.isfinite(d_out) or d_out <= 0:
        return 0
    return max(0, math.floor((d_ex / d_out - 1.0) * len(xy)))


def _kind_density(xy: np.ndarray, kinds: np.ndarray, k: int, region, box=None) -> float:
    """Elements of kind ``k`` per unit area of all elements' counted Voronoi cells
    (:func:`visible_density`), as the fidelity judge's ``density[k]`` (the kind's share
    of the counted cells times their density); nan when no cell counts."""
    counted = _counted_cells(xy, region, box)
    if counted is None or counted[1] <= 0:
        return float("nan")
    ok, area = counted
    return int(np.count_nonzero(ok & (np.asarray(kinds) == k))) / area


def small_budget(g) -> int:
    """Kinds of several sizes (:func:`small_fill`): how many holes the second round
    (``fill_void_holes(toward=True)``) may fill, the elements of the smallest kind the
    result lacks to have the exemplar's density of that kind (:func:`_kind_density`,
    the result's placed elements in its region); 0 when it has as many or either
    density is not told.

    Not in the paper (§5 grows until the seeds run out, with no density asked), as
    :func:`void_budget` for voids. Filling every hole the second round can reach
    overshot where the growth had already put small stones enough: ``--harder``
    three_sizes h7s23 (counts 20:120:20, seed 1) had 1.15 x the exemplar's small
    stones before the round and 1.23 x after its 18 fills, which pushed their nearest
    medium stone out at the upper deciles (``nn[small>medium]`` 0.049 -> 0.062 against
    0.052), where h9s25 (seed 1, 0.96 x before) lacks them (helper g37t,
    ``benchmarks/g37t_probe.py``).
    """
    sf = small_fill(g)
    if sf is None:
        return 0
    a = sf[0]
    ex = g.ref.exemplar
    d_ex = getattr(g, "_ref_small_density", None)
    if d_ex is None:
        d_ex = g._ref_small_density = _kind_density(ex.xy, g.ex_kind, a, ex.region)
    if not math.isfinite(d_ex) or d_ex <= 0:
        return 0
    placed = np.asarray([i for i in g.order if g.state[i] == ELEMENT], dtype=np.int64)
    if len(placed) < 4:
        return 0
    xy, kinds = g.pos[placed], g.kind[placed]
    if g.region is not None:
        d_out = _kind_density(xy, kinds, a, g.region)
    else:
        d_out = _kind_density(xy, kinds, a, None, (*xy.min(axis=0), *xy.max(axis=0)))
    if not math.isfinite(d_out) or d_out <= 0:
        return 0
    return max(0, math.floor((d_ex / d_out - 1.0) * int(np.count_nonzero(kinds == a))))


def small_fill(g) -> tuple[int, np.ndarray] | None:
    """Kinds of several sizes without void kinds (fixed mode): the smallest kind, which
    the holes are filled with, and per kind the reach within which a hole's centre must
    have an element of that kind (inf: the reference does not tell); None for other
    exemplars.

    Not in the paper (§5.4 never returns to a place; §5.1 has the smaller kinds fill the
    spaces the larger ones leave, which the growth front does only while it passes).
    Two sizes of nearly one size grew pebbles at 0.77-0.83 of the exemplar's density
    (the judge's, crop free) with the stones at 0.95-1.06 of theirs (``--harder``
    two_sizes h3s10 and h11s7, 3.5x, seeds 1-8; 237 of 515 pebble placements refused
    as nearer a stone than the reference has one, h3s10 seed 1), and the holes they
    left made the empty circles 9-13 % wider than the exemplar's at q95
    (empty_circle 0.100-0.134 against 0.1: h3s10 passed 2 of 8 seeds, h11s7 2 of 8).
    Such a hole, wider than any the exemplar leaves (:func:`reference_visible_gap`),
    is a smaller element's place; its centre gets a seed of the smallest kind, matched
    and placed as any other (:func:`fill_void_holes`). Only where the element would
    have each kind as near as the reference's smallest kind has it at its upper decile
    (:data:`SMALL_DECILE`, border-corrected as the judge): the default two sizes pack
    their pebbles 8.5-11 apart, narrower than their holes, and a pebble alone in the
    middle of one lengthened the pebbles' upper nearest-pebble deciles
    (``nn[pebble>pebble]`` failed 8 of 8 seeds, 0.066-0.077 against 0.0646).
    """
    cached = getattr(g, "_small_fill", False)
    if cached is not False:
        return cached
    out = None
    lv = np.asarray(g.size_level, dtype=float)
    ex = g.ref.exemplar
    small = np.flatnonzero(lv == lv.min()) if g.n_kinds > 1 else np.zeros(0, np.int64)
    if (g.n_kinds > 1 and float(lv.max()) > float(lv.min()) and len(small) == 1 and not bool(g.void_kind.any())
            and ex.region is not None):
        from scipy.spatial import cKDTree

        a = int(small[0])
        sa = np.flatnonzero(g.ex_kind == a)
        to_edge = np.asarray(ex.region.distance_to_boundary(ex.xy[sa]), dtype=float)
        reach = np.full(g.n_kinds, np.inf)
        for b in range(g.n_kinds):
            sb = np.flatnonzero(g.ex_kind == b)
            if len(sb) < (3 if b == a else 2):
                continue
            d, _ = cKDTree(ex.xy[sb]).query(ex.xy[sa], k=2 if b == a else 1)
            d = d[:, 1] if b == a else d
            d = d[d <= to_edge]
            if len(d) >= MIN_SMALL:
                reach[b] = float(np.quantile(d, SMALL_DECILE))
        out = (a, reach)
    g._small_fill = out
    return out


def fill_void_holes(g, lim: float | None = None, bare: bool = False, toward: bool = False) -> int:
    """A visible element put at the centre of each empty circle of the placed visible
    elements wider than ``lim`` (default :func:`reference_visible_gap`), in place of
    the voids there, widest first; how many (see the module docstring). With void
    kinds and the default ``lim``, at most :func:`void_budget` of them. Without void kinds it fills
    the empty circles of all placed elements (the hubs of clustered exemplars,
    :func:`strew.grow._clusters.grow_clusters`), and with ``bare`` an element whose
    placement at its fitted position is refused is tried at the circle's centre. With
    kinds of several sizes the element is of the smallest kind, where each kind is
    near enough (:func:`small_fill`) at the circle's centre, or with ``toward`` (kinds of
    several sizes only) at a spot of the hole moved toward them (:func:`_toward_kinds`),
    and again where the fit to its ring (§5.4) puts it."""
    from scipy.spatial import Delaunay, QhullError

    budget = None
    if toward:
        # the second round fills only the smallest kind's deficit against the
        # exemplar's density (:func:`small_budget`; not in the paper, §5)
        budget = small_budget(g)
        if budget <= 0:
            return 0
    if lim is None:
        lim = reference_visible_gap(g)
        if bool(g.void_kind.any()) and not reference_tells_holes(g):
            # with voids, the holes are filled widest first only until the result has
            # the exemplar's visible density (:func:`void_budget`; not in the paper, §5)
            budget = void_budget(g) if lim > 0 else 0
            if budget <= 0:
                return 0
    if lim <= 0:
        return 0
    els = np.asarray([i for i in g.order if g.state[i] == ELEMENT], dtype=np.int64)
    if len(els) < 4:
        return 0
    els = els[_visible(g, g.kind[els])]
    if len(els) < 4:
        return 0
    pts = g.pos[els]
    try:
        tri = Delaunay(pts)
    except QhullError:
        return 0
    s = tri.simplices
    a, b, c = (pts[s[:, q]] for q in range(3))
    cen, r, ok = circumcircles(a, b, c)
    if len(r) != len(s):  # (the kernel returns only the non-degenerate triangles)
        full_c = np.full((len(s), 2), np.nan)
        full_r = np.zeros(len(s))
        full_c[ok], full_r[ok] = cen, r
        cen, r = full_c, full_r
    sel = np.flatnonzero(r > lim)
    sel = sel[np.argsort(-r[sel], kind="stable")]
    made = 0
    removed_all: set[int] = set()
    filled: list[tuple[float, float, float]] = []
    sf = small_fill(g)
    for q in sel.tolist():
        if budget is not None and made >= budget:
            break
        cx, cy = float(cen[q, 0]), float(cen[q, 1])
        if not g.in_domain(cx, cy):
            continue
        reach = at = None
        if sf is not None:
            kind = sf[0]
            if not toward:
                if not _kinds_near(g, cx, cy, sf[1]):
                    continue
            else:
                # (each kind's reach asked where the element stands, :func:`_toward_kinds`
                # and :func:`_fill_one`, not at the circle's centre)
                reach = sf[1]
                at = _toward_kinds(g, cx, cy, float(r[q]), reach)
                if at is None:
                    continue
        else:
            tri_kinds = [int(g.kind[els[v]]) for v in s[q].tolist()]
            kind = max(sorted(set(tri_kinds)), key=tri_kinds.count)
        if _fill_one(g, cx, cy, float(r[q]), lim, kind, removed_all, bare, reach, at):
            made += 1
            filled.append((cx, cy, float(r[q])))
    if removed_all:
        g.order[:] = [i for i in g.order if i not in removed_all or g.state[i] == ELEMENT]
    if filled:
        reseed_voids(g, filled)
    return made


def _toward_kinds(g, cx: float, cy: float, rad: float, reach: np.ndarray) -> tuple[float, float] | None:
    """Where in the hole centred at (cx, cy) the smallest kind's element goes: the
    centre, moved straight toward the nearest element of each kind farther than its
    ``reach`` until it is within it (a kind at a time, at most once each), no farther
    from the centre than §5.4's fit may move a seed (``fit_reach * l_short``); None
    where no such spot has every kind within its reach.

    Not in the paper (§5.4 never returns to a place). No element is nearer an empty
    circle's centre than its radius, so a kind whose reach is under the radius was
    never near the centre: three sizes whose smallest kind sits snug against the
    largest (``--harder`` three_sizes h9s25: the small stones' nearest large one within
    1.21 s at the upper decile, holes 1.24-1.5 s) had every hole refused (124 of 124,
    seeds 1-3) and kept empty circles 3-7 % wider than the exemplar's widest at q95.
    """
    x, y = cx, cy
    cap = TOWARD_CAP * rad
    for _ in range(int(np.isfinite(reach).sum()) + 1):
        miss = None
        for b in np.flatnonzero(np.isfinite(reach)).tolist():
            best = None
            for o in g.near(x, y, float(reach[b]) + 2.0 * rad, (ELEMENT,)):
                if int(g.kind[o]) == b:
                    d = math.hypot(g.xy[o][0] - x, g.xy[o][1] - y)
                    if best is None or d < best[0]:
                        best = (d, o)
            if best is None:
                return None
            if best[0] > reach[b]:
                miss = (b, best)
                break
        if miss is None:
            return x, y
        b, (d, o) = miss
        t = (d - float(reach[b]) * (1.0 - 1e-6)) / d
        x, y = x + t * (g.xy[o][0] - x), y + t * (g.xy[o][1] - y)
        if math.hypot(x - cx, y - cy) > cap:
            return None
    return None


def _kinds_near(g, cx: float, cy: float, reach: np.ndarray) -> bool:
    """Has (cx, cy) a placed element of each kind within its ``reach`` (inf: any)?"""
    for b in np.flatnonzero(np.isfinite(reach)).tolist():
        if not any(int(g.kind[o]) == b for o in g.near(cx, cy, float(reach[b]), (ELEMENT,))):
            return False
    return True


def _fitted_xy(g, s: int, pick: tuple[int, int, float]) -> tuple[float, float]:
    """Where seed ``s`` stands once §5.4's placement fits the chosen ring ``pick``
    (:meth:`_Grower.choose`'s answer) to its placed neighbours, as :meth:`_Grower.place`
    fits it (``_fit_position``); the seed is left where it was."""
    a, k, th = pick
    nb = g._last_nb
    x0, y0 = g.xy[s]
    if len(nb) < 2:
        return x0, y0
    rel = g.rings["rel"][a, : int(g.rings["n"][a])]
    g._fit_position(s, nb, rel, k, math.cos(th), math.sin(th))
    x, y = g.xy[s]
    if (x, y) != (x0, y0):
        g._move(s, x0, y0)
    return x, y


def _fill_one(g, cx: float, cy: float, rad: float, lim: float, kind: int, removed_all: set[int], bare: bool = False,
              reach: np.ndarray | None = None, at: tuple[float, float] | None = None) -> bool:
    # still a hole (an earlier fill may have closed it)?
    near = g.near(cx, cy, rad, (ELEMENT, SEED))
    if any(int(g.kind[o]) >= 0 and not g.void_kind[int(g.kind[o])] and math.hypot(g.xy[o][0] - cx, g.xy[o][1] - cy) < lim for o in near):
        return False
    voids = sorted(o for o in near if g.state[o] == ELEMENT and g.orig_of[o] == o and int(g.kind[o]) >= 0 and g.void_kind[int(g.kind[o])]
                   and math.hypot(g.xy[o][0] - cx, g.xy[o][1] - cy) < rad)
    if any(g.fixed[o] for o in voids):
        return False
    saved = []
    for o in voids:
        nbs = sorted(g.adj[o])
        tg = {j: g.target[j].pop(o) for j in nbs if g.target[j] is not None and o in g.target[j]}
        saved.append((o, int(g.state[o]), nbs, tg))
        for j in nbs:
            g.remove_edge(o, j)
        g.state[o] = DEAD
        g.index.remove(o)
    ring = sorted(o for o in g.near(cx, cy, rad + 0.5 * g.l, (ELEMENT,)) if g.orig_of[o] == o)
    sx, sy = (cx, cy) if at is None else at
    s = g.new_object(sx, sy, kind)
    for o in ring:
        if not g.crosses_edges(s, (sx, sy), o, g.xy[o]):
            g.add_edge(s, o)
    g._out_of_domain = False
    pick = g.choose(s)
    if pick is not None and reach is not None and not _kinds_near(g, *_fitted_xy(g, s, pick), reach):
        # kinds of several sizes (:func:`small_fill`): each kind's reach is asked where
        # the element stands after the fit to its ring (§5.4), not at the circle's
        # centre, which no element is nearer than the circle's radius
        pick = None
    if pick is not None and g.place(s, *pick):
        # the voids the new element leaves room for come back (the growth does not
        # return to the hole: without this the result's void share fell from 0.76 to 0.58)
        back = []
        for o, st, nbs, tg in saved:
            x, y = g.xy[o]
            k, sc = int(g.kind[o]), float(g.scl[o])
            if (g.too_close_in_kind(x, y, k, o, (ELEMENT,), placing=True) or g.overlaps_any(g.geom[o], k, x, y, sc)
                    or (g.pair_gap_max[k] > 0 and g.crowds_gap(g.geom[o], k, x, y, sc, o))):
                removed_all.add(o)
                continue
            g.state[o] = st
            g.index.insert(o, x, y)
            back.append((o, nbs, tg))
        _rejoin(g, back, check=True)
        return True
    g.kill(s)
    if bare and not saved:
        # the fit to the ring around (§5.4's placement at the matched ring) moved the
        # element towards one side of the hole, too near a neighbour: it goes at the
        # centre, matched with no neighbour (§5.2's Eq. 3 over an empty ring), and is
        # joined to the ring around after
        s = g.new_object(cx, cy, kind)
        g._out_of_domain = False
        pick = g.choose(s)
        if pick is not None and g.place(s, *pick):
            for o in ring:
                if g.state[o] == ELEMENT and not g.has_edge(s, o) and not g.crosses_edges(s, g.xy[s], o, g.xy[o]):
                    g.add_edge(s, o)
            return True
        g.kill(s)
    for o, st, _, _ in saved:
        g.state[o] = st
        g.index.insert(o, g.xy[o][0], g.xy[o][1])
    _rejoin(g, [(o, nbs, tg) for o, _, nbs, tg in saved], check=False)
    return False


def _rejoin(g, back, check: bool) -> None:
    """The edges (and ring targets, §5.5) of objects put back; with ``check``, only
    to living ends and where no edge made since is crossed."""
    for o, nbs, tg in back:
        for j in nbs:
            if g.state[j] not in (ELEMENT, SEED) or g.has_edge(o, j):
                continue
            if check and g.crosses_edges(o, g.xy[o], j, g.xy[j]):
                continue
            g.add_edge(o, j)
            if j in tg:
                g.target[j][o] = tg[j]


def reseed_voids(g, around: list[tuple[float, float, float]]) -> int:
    """Seeds again at the empty void slots of the rings of the elements near the filled
    holes (centre, radius); how many.

    The growth does not return to a place (§5.4 seeds only from the front): the voids
    taken out of a hole and not put back, and the void slots of the ring of the
    element put there, which merged with them before they went, were left empty (the
    result's void share fell from 0.76 to 0.58; a void slot is proposed again only
    where no object lies within half its distance, as :meth:`_Grower.refill` does).
    """
    from ._objects import ELEMENT as _EL

    made = 0
    seen: set[int] = set()
    for cx, cy, rad in around:
        for s in sorted(g.near(cx, cy, rad + 2.0 * g.l, (_EL,))):
            if s in seen or g.state[s] != _EL or g.orig_of[s] != s:
                continue
            seen.add(s)
            made += g.seed_empty_slots(s, only_void=True)
    return made
