"""Unsaturated exemplars: each element keeps its reference's nearest distance (not in the paper).

§5.4 (b) merges a new seed only with an object within ``l_short``, half the shortest
reference edge, and §5.2 matches a seed against its *connected* neighbours w(e_tar)
alone. A sparse exemplar drawn with a fixed count (a dart throw stopped well before it
is full: ``_variants.EDGE`` stones p2, 60 stones of radius 4 and gap 4 in 200 x 200)
keeps wide empty places between its elements, and nothing in §5 keeps them: a ring slot
of one element lands in the empty part of a neighbour's ring, farther than ``l_short``
from everything, and is placed there (helper g34d, ``benchmarks/g34d_probe.py``: within
one mean spacing each element had 0.86 elements its ring did not pair, 0.42 placed
before it and 0.44 after; its reference element had 2.98 neighbours there and the
output element 3.54; the copied ring offsets themselves were kept, 0.99 of their length
at the end, ``_fit_position`` moved elements 0.04 spacings, ``_nudge`` none, the hole
passes 1). The result was 22 % denser than the exemplar (empty_circle 0.158 against
0.149; the class's own generator at that size passes).

In the exemplar every pair of elements lies at least the larger of their two
nearest-neighbour distances apart (by definition of the nearest neighbour). Where the
exemplar leaves room (:func:`free_share`), growth keeps most of that: an element is not
placed nearer a placed one than :data:`KEEP_SHARE` of the larger of their reference
elements' nearest distances.
Saturated and lattice exemplars have no room, and there the rule would only turn growth
noise into holes (forced on the default stones, ``--varied`` stones v23: density
0.002 -> 0.111 against a tolerance of 0.1), so it applies only where
:func:`free_share` is at least :data:`FREE_MIN`, to exemplars of one kind (two kinds of
one size in bands of dots and bars, stripes p2, have as much room between the bands,
and the rule failed them: nn[bar>bar] 0.068 against 0.062).

Keeping the distances does not keep the holes: the growth still reaches every place the
rule allows, and the result is more even than the dart throw (its whole empty circles'
q95 0.82-0.88 of the exemplar's, draws 23-30). :func:`thin_to_holes` takes elements out
after the growth until the exemplar's share of wide circles is back (helper g42s).
"""

from __future__ import annotations

import math

import numpy as np
from scipy.spatial import cKDTree

from ..arrangement import Arrangement

#: the least :func:`free_share` at which elements keep their reference's nearest
#: distance. Of the audit's one-kind exemplars (variant seeds 1-26, ``--varied``
#: labels; ``benchmarks/g34d_room.py``), the sparse stones (EDGE stones p2) have
#: 0.26-0.46; saturated stones (p1) 0.03-0.14, the default stones 0.00-0.01, sticks,
#: lattices, bricks and scales 0.
FREE_MIN = 0.2

#: the share of the larger reference nearest distance kept between two elements. The
#: whole distance pushes the output's nearest distances above the exemplar's (each
#: element's is at least its reference's): at 1.0 stones p2s7 seed 1 failed
#: nn[stone>stone] 0.153/0.12, at 0.9 p2s17 seed 1 0.163/0.15 (main passes both); at
#: 0.85 stones p2s7-p2s26 seed 1 and p2s23 seeds 2-3 all pass (p2s23: 868 stones, the
#: generator's 735, main's 1011; benchmarks/results/g34d_p2_rows.txt)
KEEP_SHARE = 0.85


def free_share(ex: Arrangement, step: float = 0.25) -> float:
    """Share of the exemplar's interior where one more element would fit.

    The element is the exemplar's smallest (bounding disc), kept the least gap between
    bounding discs that any two elements of the exemplar keep; the interior lies
    ``2 r_max + gap`` inside the frame; sampled on a grid of ``step`` times the disc's
    needed clearance. 0 for a lattice or a dart throw run until nothing fits.
    """
    xy = np.asarray(ex.xy, dtype=float)
    if len(xy) < 4 or ex.region is None:
        return 0.0
    rad = np.array([float(ex.shapes[k].radius) for k in ex.kinds])[np.asarray(ex.kind)] * np.asarray(ex.scale, dtype=float)
    tree = cKDTree(xy)
    k = min(8, len(xy))
    d, q = tree.query(xy, k=k)
    gap = max(float((d[:, 1:] - rad[:, None] - rad[q[:, 1:]]).min()), 0.0)
    need = float(rad.min()) + gap
    if need <= 0:
        return 0.0
    x0, y0, x1, y1 = ex.region.bounds
    m = float(2 * rad.max() + gap)
    h = step * need
    gx, gy = np.meshgrid(np.arange(x0 + m, x1 - m, h), np.arange(y0 + m, y1 - m, h))
    if gx.size == 0:
        return 0.0
    dd, qq = tree.query(np.c_[gx.ravel(), gy.ravel()], k=k)
    return float(np.mean(np.min(dd - rad[qq], axis=1) >= need))


def reference_nn(ex: Arrangement, mode: str, keep: bool | None) -> np.ndarray | None:
    """Each exemplar element's nearest-neighbour distance where elements keep it, or None.

    ``keep`` True or False forces the rule on or off (``GrowParams.keep_nn``); None
    decides by the exemplar: one kind, no voids, :func:`free_share` at least
    :data:`FREE_MIN`, fixed mode (the audits measured it there).
    """
    if keep is False or len(ex) < 2:
        return None
    if keep is None and (mode != "fixed" or len(ex.kinds) != 1 or "void" in ex.columns
                         or free_share(ex) < FREE_MIN):
        return None
    xy = np.asarray(ex.xy, dtype=float)
    return cKDTree(xy).query(xy, k=2)[0][:, 1]


#: the exemplar's quantile of its whole empty circles above which a circle counts as a
#: hole (:func:`thin_to_holes`): the result is thinned until that share of its own whole
#: circles is as wide
HOLE_QUANTILE = 0.9


def _circles(pts: np.ndarray, region) -> tuple[np.ndarray, np.ndarray]:
    """The empty circles of ``pts`` (n, 2) wholly inside ``region``: centres (m, 2) and
    radii (m,), as the fidelity judge's ``empty_circle`` measures them (Delaunay
    circumcircles, the non-degenerate ones)."""
    from scipy.spatial import Delaunay, QhullError

    from .._kernels.geometry import circumcircles

    if len(pts) < 4:
        return np.zeros((0, 2)), np.zeros(0)
    try:
        tri = Delaunay(pts)
    except QhullError:
        return np.zeros((0, 2)), np.zeros(0)
    a, b, c = (pts[tri.simplices[:, q]] for q in range(3))
    cen, rr, _ = circumcircles(a, b, c)
    if not len(cen):
        return cen, rr
    inner = region.contains(cen) & (region.distance_to_boundary(cen) >= rr)
    return cen[inner], rr[inner]


def _opened(pts: np.ndarray, tree: cKDTree, alive: np.ndarray, e: int, reach: float) -> float:
    """The widest empty circle that taking element ``e`` out of ``pts`` (n, 2) opens: the
    widest circumcircle of the Delaunay triangles of the live elements within ``reach``
    of it (``alive`` bool (n,), ``e`` left out) that holds ``e``'s position; 0 if none."""
    from scipy.spatial import Delaunay, QhullError

    from .._kernels.geometry import circumcircles

    idx = np.asarray(tree.query_ball_point(pts[e], reach), dtype=np.int64)
    idx = idx[alive[idx] & (idx != e)]
    if len(idx) < 3:
        return 0.0
    sub = pts[idx]
    try:
        tri = Delaunay(sub)
    except QhullError:
        return 0.0
    a, b, c = (sub[tri.simplices[:, q]] for q in range(3))
    cen, rr, _ = circumcircles(a, b, c)
    hit = np.hypot(cen[:, 0] - pts[e, 0], cen[:, 1] - pts[e, 1]) < rr
    return float(rr[hit].max()) if bool(hit.any()) else 0.0


def thin_to_holes(g, tries: int = 32) -> int:
    """Unsaturated exemplars: take elements out of the result until as large a share of
    its whole empty circles is as wide as the exemplar's upper :data:`HOLE_QUANTILE`
    as the exemplar has; how many were taken out.

    Not in the paper (§5 grows until the seeds run out and never takes an element
    back). A dart throw stopped at a count (``_variants.EDGE`` stones p2, 60 stones of
    radius 4 and gap 4 in 200 x 200) leaves holes where nothing happened to land; the
    growth reaches every place (each element's ring slots lie all around it, and a slot
    in the empty part of one ring is another's to fill), so even with
    :data:`KEEP_SHARE` the result is the more even: its whole empty circles' q95 was
    0.82-0.88 of the exemplar's on each of draws 23-30 at seed 1 (the class's own
    generator at the result's size: 0.95-1.05; empty_circle 0.149-0.181 against
    0.121-0.13 at p2s29 and p2s30, seeds 1-6: helper g42s, ``benchmarks/g42s_probe.py``).
    Each element taken out, drawn at random from ``g.rng``, opens one hole: only an
    element at least the exemplar's widest circle from the region's edge, and only
    where the widest circle it opens lies between the exemplar's upper quantile and its
    widest (above which :func:`strew.grow._void_holes.fill_void_holes` fills), up to
    ``tries`` refused draws per element taken out. The circles are counted anew after
    each batch of a quarter of the wide circles missing (a hole opens about four).
    Needs the exemplar's :data:`strew.grow._void_holes.MIN_CIRCLES` whole circles, as
    that pass.
    """
    from ._objects import ELEMENT
    from ._void_holes import MIN_CIRCLES, _whole_circles

    if g.region is None:
        return 0
    circles = _whole_circles(g)
    if circles is None or int(circles[1].sum()) < MIN_CIRCLES:
        return 0
    rex = circles[0][circles[1]]
    lo, hi = float(np.quantile(rex, HOLE_QUANTILE)), float(rex.max())
    share = float(np.mean(rex > lo))
    els = np.asarray([i for i in g.order if g.state[i] == ELEMENT], dtype=np.int64)
    if len(els) < 4:
        return 0
    pts = g.pos[els].astype(float)
    far = np.asarray(g.region.distance_to_boundary(pts), dtype=float) >= hi
    alive = np.ones(len(els), dtype=bool)
    tree = cKDTree(pts)
    reach = 4.0 * hi
    taken = 0
    while True:
        _, rr = _circles(pts[alive], g.region)
        missing = math.ceil(share * len(rr)) - int(np.count_nonzero(rr > lo))
        if not len(rr) or missing <= 0:
            break
        batch, made, refused = max(1, missing // 4), 0, 0
        for e in g.rng.permutation(np.flatnonzero(alive & far)).tolist():
            if lo < _opened(pts, tree, alive, e, reach) <= hi:
                alive[e] = False
                made += 1
                if made >= batch:
                    break
            else:
                refused += 1
                if refused >= tries * (made + 1):
                    break
        taken += made
        if made < batch:
            break
    if taken:
        gone = set(els[~alive].tolist())
        for i in sorted(gone):
            g.kill(i)
        g.order[:] = [i for i in g.order if i not in gone]
    return taken
