"""Flow mode: the grower's state kept and put back, and the interior score the flow
passes compare (issue 14 point 2; :mod:`strew.grow._flow_densify` uses them).

Not in the paper. :func:`snapshot` keeps the grower's whole state, :func:`restore`
puts it back exactly (positions, graph, index, the random stream), and
:func:`interior_score` counts the interior sites (over two mean edges inside the
region) with six elements at 0.85-1.15 mean edges and none nearer, and the points of
the interior farther than 0.75 mean edges from every element (the holes' points).

Until 8224b5f this module also ran the passes after the last relaxation twice
(``retry_shear``: the second way with the sheared bands fitted first and no gap
guard, the better kept). Once the band's last network pass
(:func:`strew.grow._flow_net.relax_network` with ``band``) was on, the retry changed
one of the twelve flow cases of ``benchmarks/grow.py --structure --flow-only``, the
90 degree field from the centre, and lowered it (0.904 against 0.921 without), and
of the seven alternate start points only (28, 18) spacings (0.846 against 0.858,
whose one hole without the retry the band pass's grid check now sends back): it was
removed (``benchmarks/flow14n_probe.py``).
"""

from __future__ import annotations

import numpy as np

from ._flow_kernels import boundary_distance
from ._near_kernels import ball_counts, far_from
from ._objects import ELEMENT
from ._state_copy import deep_copy_state

__all__ = ["snapshot", "restore", "interior_score"]

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
    return deep_copy_state(d, memo)  # (copy.deepcopy(dict(d), memo), the plain containers copied in one call each)


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
        grid = grid[boundary_distance(rg, grid) > 2.0 * L]
    return grid


def interior_score(g, grid: np.ndarray | None = None) -> tuple[int, int]:
    """(sites over two mean edges inside the region with six elements at 0.85-1.15
    spacings (``_flow_net.six_spacing``) and none nearer, points of a quarter-edge grid there farther than 0.75
    mean edges from every element); ``grid``: :func:`_region_grid`'s, made once for
    two scores of one region."""
    L = g.l
    els = [i for i in g.order if g.state[i] == ELEMENT]
    if len(els) < 7:
        return 0, 0
    xy = g.pos[els]
    rg = g.region
    if rg is not None:
        q = xy[boundary_distance(rg, xy) > 2.0 * L]
        if grid is None:
            grid = _region_grid(g)
    else:
        q = xy
        (x0, y0), (x1, y1) = xy.min(axis=0), xy.max(axis=0)
        grid = np.mgrid[x0 + 2 * L : x1 - 2 * L : 0.25 * L, y0 + 2 * L : y1 - 2 * L : 0.25 * L].reshape(2, -1).T
    from ._flow_net import six_spacing

    S = six_spacing(g)
    # (cKDTree's counts and query, compiled: _near_kernels)
    hi, lo = ball_counts(xy, q, 1.15 * S, 0.85 * S)
    hi, lo = hi - 1, lo - 1
    six = int(((hi == 6) & (lo == 0)).sum())
    far = int(far_from(xy, grid, 0.75 * L).sum()) if len(grid) else 0
    return six, far
