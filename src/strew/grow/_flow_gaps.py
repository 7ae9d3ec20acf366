"""Flow mode: gaps left where a bent lattice opened up (issue 14 point 2).

Not in the paper. Where the field bends the rows (§5.3), growth running away from
their centre of curvature stretches the lattice, and it leaves empty circles of about
0.75-0.85 spacings radius (a perfect hexagonal lattice: 0.58): too wide for the lattice
and too narrow for an element (a hexagon of the suite's lattice is 0.86 spacings across
its flats), where seeds died because their elements overlapped the ring around them.
After the growth two passes shrink them, each change all or nothing:

- :func:`fill_holes` puts an element into a gap, pushing the elements around it out;
- :func:`close_gaps` gives a square cell (four elements around a gap, the core a new
  row leaves where it begins) a bond across its shorter diagonal, of one spacing, which
  the last relaxation (§5.5) pulls together into the two triangles of a 5-7 pair.

Neither reaches the causes (the stretch itself; see ``benchmarks/grow.py
--structure``): they halve the holes and leave the six-neighbour share as it was.
"""

from __future__ import annotations

import math

import numpy as np

from .._kernels.geometry import circumcircles
from ._flow_kernels import boundary_distance
from ._objects import ELEMENT

__all__ = ["close_gaps", "fill_holes", "side_stream"]


def _circumcircles(g):
    """The placed elements, their Delaunay triangles and the triangles' circumradii."""
    from scipy.spatial import QhullError

    from ._flow_net import triangulation

    els = np.asarray([i for i in g.order if g.state[i] == ELEMENT], dtype=np.int64)
    if len(els) < 4:
        return None
    pts = g.pos[els]
    try:
        tri = triangulation(pts, g)  # (the one kept where these positions were triangulated: the same)
    except QhullError:  # all on one line: no cell
        return None
    s = tri.simplices
    a, b, c = (pts[s[:, q]] for q in range(3))
    la, lb, lc = np.hypot(*(b - c).T), np.hypot(*(c - a).T), np.hypot(*(a - b).T)
    area2 = np.abs((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))
    r = la * lb * lc / np.maximum(2 * area2, 1e-300)
    return els, pts, tri, np.c_[la, lb, lc], r


def _bonds(g):
    """(els, pts, e): the placed elements, their positions and their Delaunay bonds,
    ``e`` of shape (m, 2) with rows of indices into ``els`` (each once, lower first);
    None with fewer than 4 placed elements."""
    cc = _circumcircles(g)
    if cc is None:
        return None
    els, pts, tri, _, _ = cc
    s = tri.simplices
    e = np.sort(np.r_[s[:, [0, 1]], s[:, [1, 2]], s[:, [0, 2]]], axis=1).astype(np.int64)
    # (the rows' unique set by one key each, lower end first: the order of
    # ``np.unique(e, axis=0)``, without its sort of row records)
    n = len(pts)
    k = np.unique(e[:, 0] * n + e[:, 1])
    return els, pts, np.c_[k // n, k % n].astype(s.dtype)


def _wide_circles(g, lo: float):
    """(ux, uy, sel): the Delaunay triangles' circumcentres and the indices of those
    whose empty circle is wider than ``lo`` and narrower than 1.5 mean edges, widest
    first; None with fewer than 4 placed elements."""
    cc = _circumcircles(g)
    if cc is None:
        return None
    _, pts, tri, _, r = cc
    s = tri.simplices
    a, b, c = (pts[s[:, q]] for q in range(3))
    cen, _, ok = circumcircles(a, b, c)
    ux, uy = np.full(len(s), np.nan), np.full(len(s), np.nan)
    ux[ok], uy[ok] = cen[:, 0], cen[:, 1]
    sel = np.flatnonzero(ok & (r > lo) & (r < 1.5 * g.l))
    return ux, uy, sel[np.argsort(-r[sel], kind="stable")]


def reference_gap(g) -> float:
    """The widest empty circle (radius) of the exemplar's interior: the circumradius of
    its Delaunay triangles whose centre lies over 1.5 mean edges inside its frame; 0
    when it has none. A grown gap is filled or closed only when wider than this by a
    tenth: the gaps of irregular exemplars (stones, two sizes) are their pattern (with
    the spacing-based bounds alone, flow mode put 5 % more elements into two and three
    sizes and sparse voids)."""
    cached = getattr(g, "_reference_gap", None)
    if cached is not None:
        return cached
    from scipy.spatial import Delaunay, QhullError

    ex = g.ref.exemplar
    out = 0.0
    if len(ex) >= 4:
        try:
            tri = Delaunay(ex.xy)
        except QhullError:
            tri = None
        if tri is not None:
            a, b, c = (ex.xy[tri.simplices[:, q]] for q in range(3))
            cen, r, _ = circumcircles(a, b, c)
            if ex.region is not None:
                inner = boundary_distance(ex.region, cen) > 1.5 * g.l
                inner &= ex.region.contains(cen)
            else:
                inner = np.ones(len(r), dtype=bool)
            if inner.any():
                out = float(r[inner].max())
    g._reference_gap = out
    return out


def fill_holes(g) -> int:
    """An element put into each gap wider than ``flow_fill_min`` spacings (empty
    circle's radius) where the elements around it can make room; how many.

    The elements within ``flow_fill_spread`` spacings beyond ``flow_fill_reach`` of
    the gap's centre are pushed out radially: the nearest to ``flow_fill_reach``
    spacings (by at most ``flow_fill_push``), the farther ones less, down to none. A
    seed there joined to the ring around it is then matched (§5.2) and placed (§5.4)
    as any other. Unless every pushed outline stays inside the region and off every
    other, and the placement succeeds, all of it is undone.
    """
    p = g.p
    lo, want = max(p.flow_fill_min * g.l, 1.1 * reference_gap(g)), p.flow_fill_reach * g.l
    wide = _wide_circles(g, lo) if lo < want else None
    if wide is None:
        return 0
    ux, uy, sel = wide
    made = 0
    done: list[tuple[float, float]] = []
    for q in sel.tolist():
        cx, cy = float(ux[q]), float(uy[q])
        if any((cx - x) ** 2 + (cy - y) ** 2 < (0.75 * g.l) ** 2 for x, y in done):
            continue
        if g.in_domain(cx, cy) and _fill_one(g, cx, cy, lo, want):
            made += 1
            done.append((cx, cy))
    return made


def _fill_one(g, cx: float, cy: float, lo: float, want: float) -> bool:
    p = g.p
    ring = [o for o in g.near(cx, cy, want + 0.05 * g.l, (ELEMENT,)) if g.orig_of[o] == o]
    if len(ring) < 3:
        return False
    dist = {o: math.hypot(g.xy[o][0] - cx, g.xy[o][1] - cy) for o in ring}
    d0 = min(dist.values())
    if d0 <= lo or want - d0 > p.flow_fill_push * g.l:
        return False
    if g.boundary is not None and any(g.crosses_boundary((cx, cy), g.xy[o]) for o in ring):
        return False
    far = want + p.flow_fill_spread * g.l
    moves: dict[int, tuple[float, float]] = {}
    for o in g.near(cx, cy, far, (ELEMENT,)):
        if g.orig_of[o] != o:
            continue
        dd = math.hypot(g.xy[o][0] - cx, g.xy[o][1] - cy)
        if dd >= far:
            continue
        if g.fixed[o]:
            return False
        f = (dd + (want - d0) * (far - dd) / (far - d0)) / max(dd, 1e-12)
        moves[o] = (cx + (g.xy[o][0] - cx) * f, cy + (g.xy[o][1] - cy) * f)
    new_geom = {}
    for o, (x, y) in moves.items():
        if not g.in_domain(x, y) or (g.boundary is not None and g.crosses_boundary(g.xy[o], (x, y))):
            return False
        ng = g.element_geometry(int(g.kind[o]), x, y, float(g.rot[o]), float(g.scl[o]))
        if not g.fits_domain(ng):
            return False
        new_geom[o] = ng
    skip = set(moves)
    for o, (x, y) in moves.items():
        if g.overlaps_any(new_geom[o], int(g.kind[o]), x, y, float(g.scl[o]), skip=skip):
            return False
    mv = list(moves)
    for i in range(len(mv)):
        gi = new_geom[mv[i]]
        for j in range(i + 1, len(mv)):
            if gi.intersects(new_geom[mv[j]]) and not gi.touches(new_geom[mv[j]]):
                return False
    old = {o: (g.xy[o][0], g.xy[o][1], g.geom[o]) for o in moves}
    for o, (x, y) in moves.items():
        g._move(o, x, y)
        g.geom[o] = new_geom[o]
    # edges across the gap go; the new element is joined to the ring around it
    removed = []
    for i in ring:
        for j in list(g.adj[i]):
            if j in dist and i < j and _seg_dist(g.xy[i], g.xy[j], (cx, cy)) < 0.5 * g.l:
                g.remove_edge(i, j)
                removed.append((i, j))
    kinds = [int(g.kind[o]) for o in sorted(ring)]
    s = g.new_object(cx, cy, max(sorted(set(kinds)), key=kinds.count))
    for o in sorted(ring):
        if not g.crosses_edges(s, (cx, cy), o, g.xy[o]):
            g.add_edge(s, o)
    g._out_of_domain = False
    pick = g.choose(s)
    if pick is not None and g.place(s, *pick):
        g.dirty.update(moves)
        return True
    g.kill(s)
    for i, j in removed:
        g.add_edge(i, j)
    for o, (x, y, geom) in old.items():
        g._move(o, x, y)
        g.geom[o] = geom
    return False


def _seg_dist(pa, pb, q) -> float:
    """Distance from point ``q`` to segment ``pa``-``pb``."""
    ax, ay = pa
    dx, dy = pb[0] - ax, pb[1] - ay
    L2 = dx * dx + dy * dy
    t = 0.0 if L2 <= 0 else min(1.0, max(0.0, ((q[0] - ax) * dx + (q[1] - ay) * dy) / L2))
    return math.hypot(ax + t * dx - q[0], ay + t * dy - q[1])


def close_gaps(g) -> int:
    """A bond across the shorter diagonal of each square cell; how many.

    A cell is two Delaunay triangles of the placed elements that share the longest edge
    of one whose circumradius exceeds ``flow_close_min`` spacings; its shorter diagonal,
    if under ``flow_close_max`` spacings, becomes an edge with a target offset of one
    mean edge along it (§5.5's Eq. 5 term), the other diagonal's edge is dropped, and
    both ends are left to the last relaxation window (whose overlap guard holds).
    """
    cc = _circumcircles(g)
    if cc is None:
        return 0
    els, _, tri, lens, r = cc
    s = tri.simplices
    p = g.p
    made = 0
    used: set[int] = set()
    for t in np.flatnonzero(r > max(p.flow_close_min * g.l, 1.1 * reference_gap(g))).tolist():
        if t in used:
            continue
        q = int(np.argmax(lens[t]))
        t2 = int(tri.neighbors[t, q])
        if t2 < 0 or t2 in used:
            continue
        w = int(els[s[t, q]])
        u, v = int(els[s[t, (q + 1) % 3]]), int(els[s[t, (q + 2) % 3]])
        z = int(els[[x for x in s[t2].tolist() if int(els[x]) not in (u, v)][0]])
        dwz, duv = math.dist(g.xy[w], g.xy[z]), math.dist(g.xy[u], g.xy[v])
        if min(dwz, duv) > p.flow_close_max * g.l:
            continue
        (a, b), (c, d) = ((w, z), (u, v)) if dwz < duv else ((u, v), (w, z))
        if g.fixed[a] and g.fixed[b]:
            continue
        if g.boundary is not None and g.crosses_boundary(g.xy[a], g.xy[b]):
            continue
        if g.has_edge(c, d):
            g.remove_edge(c, d)
            for x, y in ((c, d), (d, c)):
                if g.target[x] is not None:
                    g.target[x].pop(y, None)
        if not g.has_edge(a, b):
            g.add_edge(a, b)
        (ax, ay), (bx, by) = g.xy[a], g.xy[b]
        n = max(math.hypot(bx - ax, by - ay), 1e-300)
        ux, uy = (bx - ax) / n * g.l, (by - ay) / n * g.l
        if g.target[a] is not None:
            g.target[a][b] = (ux, uy)
        if g.target[b] is not None:
            g.target[b][a] = (-ux, -uy)
        g.dirty.update((a, b))
        used.update((t, t2))
        made += 1
    return made


def side_stream(rng: np.random.Generator) -> np.random.Generator:
    """A generator for the passes that leaves ``rng``'s state as it is: its bit
    generator jumped ahead where it can jump (PCG64, MT19937, Philox), else a copy."""
    bg = rng.bit_generator
    jumped = getattr(bg, "jumped", None)
    if jumped is not None:
        return np.random.Generator(jumped())
    c = type(bg)()
    c.state = bg.state
    return np.random.Generator(c)
