"""Flow mode: the sheared bands of a bent lattice fitted back to the exemplar's
hexagonal star by Eq. 5 (issue 14 point 2).

Not in the paper. Where the field's rows fan out (from the 90 degree field's corner
(2,18), ``benchmarks/grow.py --structure --flow-only``) the lattice stays whole but
sheared: in one band of about 15 rows its three bond directions are 1.15-1.2, about
1.08 and about 0.9 mean edges long, so that most sites fail the six-neighbour test
(``ns_stretch``). Its density is only about 7% below the lattice's (a triangle of
those sides has 1.07 times the area), so a half-row of new elements does not fit: a
half-row put at once at the middles of the long bonds across the band, the window
relaxed as :func:`strew.grow._flow_stretch.insert_stretched` relaxes one, left its
sites 0.70-0.80 mean edges free, and with the compressed pairs held at one edge the
fitted outlines overlapped (issue 14 point 2, helper flow14f). The shear itself is
undone here instead:

- the band: every placed element with a Delaunay bond over ``flow_shear_min`` mean
  edges, and those within ``flow_shear_window`` mean edges of one, not held (Eq. 6)
  and over one mean edge inside the region; each connected band separately;
- each element's hexagonal star: the angle of the mean of ``exp(6 i theta)`` over its
  bonds (under 1.4 mean edges), divided by 6;
- Eq. 5 over the band, each bond's term wanting one mean edge in the direction of its
  element's star nearest the bond's (the exemplar's ring, as §5.5, but in the
  element's fitted frame rather than the field's), the elements around held;
- the moves are made as :meth:`strew.grow._relax_window._RelaxWindow.relax_window`
  makes them (a move out of the region is not made; elements that then overlap go back
  with those they overlap; nothing turns);
- all or nothing per band: where the moves open a gap (a point of a quarter-edge grid
  around the band, over two mean edges inside the region, farther than 0.7 mean
  edges from every element, that was not before; the holes counted by
  ``benchmarks/grow.py``: 0.75 spacings), or do not raise the number of the band's
  sites with six neighbours at 0.85-1.15 mean edges, the band goes back whole.

It runs after :func:`strew.grow._flow_stretch.insert_stretched` and before
:func:`strew.grow._flow_holes.close_holes` (run before the insertions, it gave more
holes: 3 against 2 over the twelve flow cases). The moved elements do not turn (with
the turns of ``close_holes``, up to 30 degrees, elements left the 12 degrees around
the field that ``tests/grow/test_grow_flow_turn.py`` asks).

Departs from §5.5 (Eq. 5's targets are each element's matched ring in the field's
frame, here a regular star in the frame fitted to its bonds) and, as
:func:`strew.grow._flow_holes.close_holes`, runs as a pass after the growth.
"""

from __future__ import annotations

import numpy as np

from ._flow_gaps import _bonds
from ._flow_kernels import boundary_distance
from ._near_kernels import ball_counts, far_from
from ._objects import ELEMENT
from ._relax import relax_positions

__all__ = ["reshape_shear"]


def reshape_shear(g, gap: float = 0.7) -> int:
    """Fit the sheared bands back to the hexagonal star (Eq. 5); how many elements
    moved. ``gap``: a band goes back whole where its moves open a point farther than
    this many mean edges from every element."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components
    from scipy.spatial import cKDTree

    p = g.p
    L = g.l
    bonds = _bonds(g)
    if bonds is None:
        return 0
    els, pts, e = bonds
    d = pts[e[:, 1]] - pts[e[:, 0]]
    ln = np.hypot(d[:, 0], d[:, 1])
    keep = ln < 1.4 * L
    e, d, ln = e[keep], d[keep], ln[keep]
    n = len(els)
    hot = np.zeros(n, dtype=bool)
    hot[e[ln > p.flow_shear_min * L].ravel()] = True
    if not hot.any():
        return 0
    free = cKDTree(pts[hot]).query(pts)[0] < p.flow_shear_window * L
    free &= ~np.asarray([bool(g.fixed[o]) for o in els.tolist()], dtype=bool)
    if g.region is not None:
        free &= boundary_distance(g.region, pts) > 1.0 * L
    # each element's star, and each bond's term: one mean edge along the star's
    # direction nearest the bond's
    th = np.arctan2(d[:, 1], d[:, 0])
    z = np.zeros(n, dtype=complex)
    np.add.at(z, e[:, 0], np.exp(6j * th))
    np.add.at(z, e[:, 1], np.exp(6j * (th + np.pi)))
    phi = np.angle(z) / 6
    src = np.r_[e[:, 0], e[:, 1]]
    dst = np.r_[e[:, 1], e[:, 0]]
    ang = np.r_[th, th + np.pi]
    tgt = phi[src] + np.round((ang - phi[src]) / (np.pi / 3)) * (np.pi / 3)
    off = L * np.c_[np.cos(tgt), np.sin(tgt)]
    fe = e[free[e[:, 0]] & free[e[:, 1]]]
    lab = connected_components(coo_matrix((np.ones(len(fe)), (fe[:, 0], fe[:, 1])), shape=(n, n)), directed=False)[1]
    moved = 0
    for band in np.unique(lab[free]).tolist():
        moved += _reshape_band(g, els, free & (lab == band), src, dst, off, gap)
    return moved


def saved_moves(g, els) -> dict[int, tuple]:
    """Where the elements ``els`` are now, keyed by element, as :func:`undo_moves`
    puts them back (x, y, outline, rotation)."""
    return {o: (*g.xy[o], g.geom[o], float(g.rot[o])) for o in els}


def undo_moves(g, old: dict[int, tuple]) -> None:
    """Put the elements of ``old`` (from :func:`fitted_moves`) back where they were,
    with their outlines and rotations."""
    for o, (x, y, geom, rot) in old.items():
        if g.xy[o] != (x, y):
            g._move(o, x, y)
        g.geom[o] = geom
        g.rot[o] = rot


def fitted_moves(g, els: np.ndarray, pts: np.ndarray, qs) -> tuple[dict[int, tuple[float, float]], dict[int, tuple]]:
    """The elements ``els[q]`` (``q`` in ``qs``) that a fit moves to ``pts[q]`` (shape
    (len(els), 2)) by more than a billionth of an edge: their new positions and what
    undoing the move needs (old x, y, outline, rotation), keyed by element."""
    moves: dict[int, tuple[float, float]] = {}
    old: dict[int, tuple] = {}
    tiny = 1e-9 * g.l
    qa = np.asarray(qs, dtype=np.intp) if isinstance(qs, np.ndarray) else np.fromiter(qs, dtype=np.intp)
    if not len(qa):
        return moves, old
    # (which moved farther than ``tiny``, over all of them at once: the same float64
    # sums and comparison as one element at a time, ``g.pos`` holding ``g.xy``'s
    # values; the network passes ask this of every element at each pass, issue 14
    # point 5)
    cur = g.pos[els[qa]]
    fit = pts[qa]
    far = np.abs(fit[:, 0] - cur[:, 0]) + np.abs(fit[:, 1] - cur[:, 1]) > tiny
    for q in qa[far].tolist():
        o = int(els[q])
        ox, oy = g.xy[o]
        moves[o] = (float(pts[q, 0]), float(pts[q, 1]))
        old[o] = (ox, oy, g.geom[o], float(g.rot[o]))
    return moves, old


def _reshape_band(g, els, fb, src, dst, off, gap: float = 0.7) -> int:
    """Fit the free elements ``fb`` of ``els`` (Eq. 5 with the terms ``src``, ``dst``,
    ``off``) and move them, all or nothing; how many moved."""
    L = g.l
    use = fb[src] | fb[dst]
    new = relax_positions(g.pos[els], src[use], dst[use], off[use], fb)
    moves, old = fitted_moves(g, els, new, np.flatnonzero(fb).tolist())
    if not moves:
        return 0
    mv = np.asarray([old[o][:2] for o in moves])
    (x0, y0), (x1, y1) = mv.min(axis=0) - 2 * L, mv.max(axis=0) + 2 * L
    grid = np.mgrid[x0:x1:0.25 * L, y0:y1:0.25 * L].reshape(2, -1).T
    if g.region is not None:
        # (a gap within two edges of the region's edge is the edge's, see close_holes)
        # (the distance only for the points inside: the same points as both tests on all)
        grid = grid[g.region.contains(grid)]
        grid = grid[boundary_distance(g.region, grid) > 2.0 * L]
    before = _far(g, grid, gap * L)
    sites = sorted({j for o in moves for j in g.near(*old[o][:2], 1.5 * L, (ELEMENT,))})
    six = _six(g, sites)
    _settle(g, moves, old)
    if (_far(g, grid, gap * L) & ~before).any() or _six(g, sites) <= six:
        undo_moves(g, old)
        return 0
    return sum(1 for o in moves if g.xy[o] != old[o][:2])


def _six(g, sites: list[int]) -> int:
    """How many of ``sites`` have six elements at 0.85-1.15 mean edges and none nearer."""
    els = [i for i in g.order if g.state[i] == ELEMENT]
    xy = g.pos[sites]
    hi, lo = ball_counts(g.pos[els], xy, 1.15 * g.l, 0.85 * g.l)  # (cKDTree's counts, compiled: _near_kernels)
    return int(((hi - 1 == 6) & (lo - 1 == 0)).sum())


def _far(g, grid, r: float):
    """Which points of ``grid`` lie farther than ``r`` from every placed element."""
    els = [i for i in g.order if g.state[i] == ELEMENT]
    return far_from(g.pos[els], grid, r)  # (cKDTree's query, compiled: _near_kernels)


def _settle(g, moves: dict, old: dict) -> None:
    """Make the fitted ``moves``: a move out of the region is not made, and elements
    that then overlap another go back to where they were (``old``) with those they
    overlap, until no overlap is left (the positions before had none, so this ends).
    Nothing turns: each element keeps its frame (§5.3)."""
    check = []
    for o, (x, y) in moves.items():
        if not g.in_domain(x, y) or (g.boundary is not None and g.crosses_boundary(old[o][:2], (x, y))):
            continue
        geom = g.element_geometry(int(g.kind[o]), x, y, float(g.rot[o]), float(g.scl[o]))
        if not g.fits_domain(geom):
            continue
        g._move(o, x, y)
        g.geom[o] = geom
        check.append(o)
    while check:
        hits = g.overlapping_each(check)  # (the same pairs: used as sets)
        back: set[int] = set()
        for o, hs in hits.items():
            back.add(o)
            back.update(g.orig_of[h] for h in hs if g.orig_of[h] in old)
        back = {o for o in back if (g.xy[o], float(g.rot[o])) != (old[o][:2], old[o][3])}
        if not back:
            break
        for o in sorted(back):
            x, y, geom, rot = old[o]
            if g.xy[o] != (x, y):
                g._move(o, x, y)
            g.geom[o] = geom
            g.rot[o] = rot
        check = sorted({j for o in back for j in g.near(*old[o][:2], 2.0 * g.l, (ELEMENT,)) if j in old} | back)
