"""Flow mode: the passes after the growth tried a second way, the better kept
(issue 14 point 2).

Not in the paper. Where the field's rows fan out from the 90 degree field's corner
(2,18) (``benchmarks/grow.py --structure --flow-only``) a band of about 15 rows stays
whole but sheared (:mod:`strew.grow._flow_shear`): fitted back to the hexagonal star
by Eq. 5 alone it reached 0.732 of the interior with six neighbours (0.581 kept), but
the fit opens gaps, so :func:`strew.grow._flow_shear.reshape_shear`'s guard undid the
band whole. Here the grower's whole state is kept (:func:`snapshot`) before the
passes that follow the last relaxation, and they run twice:

1. as before: :func:`~strew.grow._flow_stretch.insert_stretched`,
   :func:`~strew.grow._flow_shear.reshape_shear`,
   :func:`~strew.grow._flow_holes.close_holes`;
2. from the same state again: the sheared bands fitted first with no gap guard (the
   shear carried out of the band: its gaps are where the lattice needs the extra
   half-rows of its dislocations), then ``insert_stretched`` and ``close_holes``,
   which put elements into the stretched bonds and the gaps; in this try no placed
   element turns (``flow_hole_turn`` and ``flow_stretch_turn`` 0: with their turns
   an element of the 90 degree field's lattice left the 12 degrees around the field
   that ``tests/grow/test_grow_flow_turn.py`` asks).

The second is kept only where it leaves more interior sites (over two mean edges
inside the region) with six elements at 0.85-1.15 mean edges and none nearer, and no
more points of the interior farther than 0.75 mean edges from every element (the
holes' points); else the state after the first is put back exactly (:func:`restore`:
positions, graph, index, the random stream). Both keep every outline inside the
region and off the others (each pass does).

Departs from §5.4-5.5 as those passes do (after the growth), and from the paper's
single pass: the passes' result is compared and one of two kept.
"""

from __future__ import annotations

import copy
from dataclasses import replace

import numpy as np

from ._flow_holes import close_holes
from ._flow_shear import reshape_shear
from ._flow_stretch import insert_stretched
from ._objects import ELEMENT

__all__ = ["retry_shear", "snapshot", "restore", "interior_score"]

# shared, not copied: read only during the passes (the exemplar's reference, the
# parameters, the progress reporter)
_SHARED = ("ref", "p", "rep")


def snapshot(g) -> dict:
    """A deep copy of the grower's state (everything but the reference, parameters
    and reporter)."""
    d = vars(g)
    memo = {id(d[k]): d[k] for k in _SHARED if k in d}
    memo[id(g)] = g  # (anything pointing back at the grower keeps pointing at it)
    # the largest containers copied one level deep (their items are immutable: shapely
    # outlines, position tuples, ring offset tuples), kept in the memo so that the
    # index's references to the same containers get the same copies
    for k in ("geom", "xy"):
        memo[id(d[k])] = list(d[k])
    memo[id(d["adj"])] = [set(a) for a in d["adj"]]
    memo[id(d["edges"])] = set(d["edges"])
    memo[id(d["target"])] = [None if t is None else dict(t) for t in d["target"]]
    return copy.deepcopy(dict(d), memo)


def restore(g, snap: dict) -> None:
    """Put back a :func:`snapshot` (the snapshot itself is used, not copied)."""
    d = vars(g)
    d.clear()
    d.update(snap)


def _region_grid(g) -> np.ndarray | None:
    """The quarter-edge grid of :func:`interior_score`'s holes over a region (None
    without one: the grid then spans the elements)."""
    rg = g.region
    if rg is None:
        return None
    L = g.l
    x0, y0, x1, y1 = (float(v) for v in rg.bounds)
    grid = np.mgrid[x0 + 2 * L : x1 - 2 * L : 0.25 * L, y0 + 2 * L : y1 - 2 * L : 0.25 * L].reshape(2, -1).T
    if len(grid):
        # (the distance only for the points inside: the same points as both tests on all)
        grid = grid[rg.contains(grid)]
        grid = grid[rg.distance_to_boundary(grid) > 2.0 * L]
    return grid


def interior_score(g, grid: np.ndarray | None = None) -> tuple[int, int]:
    """(sites over two mean edges inside the region with six elements at 0.85-1.15
    mean edges and none nearer, points of a quarter-edge grid there farther than 0.75
    mean edges from every element); ``grid``: :func:`_region_grid`'s, made once for
    two scores of one region."""
    from scipy.spatial import cKDTree

    L = g.l
    els = [i for i in g.order if g.state[i] == ELEMENT]
    if len(els) < 7:
        return 0, 0
    xy = g.pos[els]
    tree = cKDTree(xy)
    rg = g.region
    if rg is not None:
        q = xy[rg.distance_to_boundary(xy) > 2.0 * L]
        if grid is None:
            grid = _region_grid(g)
    else:
        q = xy
        (x0, y0), (x1, y1) = xy.min(axis=0), xy.max(axis=0)
        grid = np.mgrid[x0 + 2 * L : x1 - 2 * L : 0.25 * L, y0 + 2 * L : y1 - 2 * L : 0.25 * L].reshape(2, -1).T
    hi = np.asarray(tree.query_ball_point(q, 1.15 * L, return_length=True), dtype=int) - 1
    lo = np.asarray(tree.query_ball_point(q, 0.85 * L, return_length=True), dtype=int) - 1
    six = int(((hi == 6) & (lo == 0)).sum())
    far = int((tree.query(grid, distance_upper_bound=0.75 * L)[0] > 0.75 * L).sum()) if len(grid) else 0
    return six, far


def _passes(g, target: int, first: bool) -> None:
    """The passes after the last relaxation; ``first``: the sheared bands fitted
    first, with no gap guard, and no second fit after the insertions (the second fit
    of ``first`` raised the twelve flow cases' six-neighbour sum a little more, 10.091
    against 10.057, both with turns, but the flow speed fell to 0.73-0.92x of a12a5fb's,
    against 0.82-0.87x: ``python benchmarks/grow.py --against a12a5fb --cases hexflow``)."""
    p = g.p
    if first:
        reshape_shear(g, gap=None)
        # (and no element turns: with the turns of up to ``flow_hole_turn`` that the
        # insertions allow, an element of the 90 degree field's lattice left the 12
        # degrees around the field that tests/grow/test_grow_flow_turn.py asks)
        g.p = replace(p, flow_hole_turn=0.0, flow_stretch_turn=0.0)
    try:
        if len(g.order) < target and p.flow_stretch_min is not None:
            insert_stretched(g, target)
        if not first:
            reshape_shear(g)
        if len(g.order) < target:
            close_holes(g, target)
    finally:
        g.p = p


def retry_shear(g, target: int) -> bool:
    """The passes after the last relaxation, run both ways (see the module); True when
    the second was kept."""
    before = snapshot(g)
    grid = _region_grid(g)
    _passes(g, target, first=False)
    six0, far0 = interior_score(g, grid)
    # (the first try's state itself is kept aside, not a copy: putting back ``before``
    # replaces every attribute, and the second try changes only ``before``'s copies,
    # so the first try's objects stay as they were; one deep copy fewer)
    kept = dict(vars(g))
    restore(g, before)
    _passes(g, target, first=True)
    six1, far1 = interior_score(g, grid)
    if six1 > six0 and far1 <= far0:
        return True
    restore(g, kept)
    return False
