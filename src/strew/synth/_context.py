"""Context elements as already-synthesized neighbours (§5.1, §5.2 with a frozen output).

Region growing continues the output it has: seeds are horizon elements, candidates
are matched to their neighbourhoods, and the expanded horizon's frozen elements
constrain the optimisation (§5.2). Elements given as ``context`` (a finished
neighbouring tile, or the ghost copies that wrap a periodic tile) are put into the
output as such elements: each is given the exemplar element of its kind whose
neighbourhood is most like its own (Eq. 1), so that it has attributes, radii (§4.1)
and free space (Eq. 3) like a synthesized element. They are seen by neighbourhood
matching, collisions and free space, seed the growth into the region, and are never
moved, removed or output (``SynthState.fixed``).
"""

from __future__ import annotations

import numpy as np
import shapely

from ..arrangement import Arrangement
from ._state import SynthState

__all__ = ["add_context", "add_holes", "fill_with_context"]


def add_context(state: SynthState, context: Arrangement, region_geometry=None) -> np.ndarray:
    """Add the elements of ``context`` near the region to ``state`` as fixed neighbours.

    Only elements within twice the largest neighbourhood radius of the region take part
    (those further away neither pair with nor constrain anything there), and only
    elements whose kind name is a kind of the selection; the others stay what the caller
    made of them (obstacles: the region less their footprint).

    Parameters
    ----------
    state : SynthState
        Empty or not; its region is where growth goes.
    context : Arrangement
    region_geometry : shapely geometry, optional
        The area the elements must be near (default ``state.region``).

    Returns
    -------
    (m,) int
        Indices of the context elements in ``state``.
    """
    prep = state.prep
    if len(context) == 0:
        return np.zeros(0, np.int64)
    names = list(prep.shapes)
    sel = prep.selected_elements & ~prep.void
    geom = region_geometry if region_geometry is not None else (state.region.geometry if state.region is not None else None)
    xy = np.asarray(context.xy, float)
    near = np.ones(len(context), bool)
    if geom is not None:
        reach = 2.0 * float(prep.rbar[sel].max()) + 2.0 * float(prep.r[sel].max())
        near = shapely.dwithin(geom, shapely.points(xy), reach)
    if "void" in context.columns:
        near &= ~np.asarray(context["void"], bool)
    ctx_names = np.asarray(context.kinds, dtype=object)[np.asarray(context.kind, np.int64)]
    # candidate exemplar elements per kind name: interior ones (whole neighbourhoods) first
    interior = np.zeros(len(prep.kind), bool)
    for ids in prep.interior:
        interior[ids] = True
    pools: dict[str, np.ndarray] = {}
    for nm in set(ctx_names[near]):
        if nm not in names:
            continue
        of_kind = sel & (prep.kind == names.index(nm))
        pool = np.flatnonzero(of_kind & interior)
        if len(pool) == 0:
            pool = np.flatnonzero(of_kind)
        if len(pool):
            pools[nm] = pool
    take = np.flatnonzero(near & np.isin(ctx_names, list(pools)))
    if len(take) == 0:
        return np.zeros(0, np.int64)
    # provisional attributes: the first candidate of the kind; then the best match (Eq. 1)
    first = np.array([pools[nm][0] for nm in ctx_names[take]], np.int64)
    idx = state.add(first, xy[take], horizon=True, fixed=True)
    width = max(len(p) for p in pools.values())
    cands = np.full((len(take), width), -1, np.int64)
    for row, nm in enumerate(ctx_names[take]):
        p = pools[nm]
        cands[row, : len(p)] = p
    from ._optimize import match_neighborhoods

    best, *_ = match_neighborhoods(state, idx, None, candidates=cands)
    ok = best >= 0
    if ok.any():
        state.reassign(idx[ok], best[ok])
    add_holes(state, context.meta.get("synth_holes") or [], pools)
    return idx


def add_holes(state: SynthState, holes: list, pools: dict[str, np.ndarray]) -> int:
    """Put a copy of each hole's kind at its centre, as an output element that seeds growth.

    ``holes`` are ``[x, y, r, kind name]`` of the medium and large elements a finished
    neighbouring tile made and dropped (``strew.tiles``, ``meta["synth_holes"]``). Each
    copy is given the exemplar element of its kind (from ``pools``) whose neighbourhood
    is most like its own (Eq. 1), as the context is, then added one at a time, larger
    kinds first, where it collides with nothing and lies in the region; it is a horizon
    element like any other (§5.1), not fixed. Not in the paper (§5.4 grows one region
    from one seed): without it the later tile's small elements filled those places first
    (see ``strew.tiles``).

    Returns
    -------
    int
        Copies added.
    """
    if not holes:
        return 0
    # larger kinds first (stable within a kind): a copy is matched to an exemplar element
    # that may be larger than the dropped one, and a medium copy added first blocked the
    # large copy next to it, whose place the medium elements then took (three_sizes,
    # helper synth19f: 2.5-3.5 s into the later tile medium 1.20-1.23x, large 0.77-0.81x)
    size = {nm: float(state.prep.r[p].mean()) for nm, p in pools.items()}
    holes = [holes[i] for i in np.argsort([-size.get(str(h[3]), 0.0) for h in holes], kind="stable")]
    xy = np.array([h[:2] for h in holes], float)
    names = [str(h[3]) for h in holes]
    ok = np.array([nm in pools for nm in names]) & state.in_domain(xy)
    if not ok.any():
        return 0
    xy = xy[ok]
    names = [nm for nm, o in zip(names, ok) if o]
    first = np.array([pools[nm][0] for nm in names], np.int64)
    idx = state.add(first, xy, horizon=True, fixed=False)
    cands = np.full((len(names), max(len(pools[nm]) for nm in names)), -1, np.int64)
    for row, nm in enumerate(names):
        cands[row, : len(pools[nm])] = pools[nm]
    from ._optimize import match_neighborhoods

    best, *_ = match_neighborhoods(state, idx, None, candidates=cands)
    src = np.where(best >= 0, best, first)
    gone = np.zeros(state.n, bool)
    gone[idx] = True
    state.remove(gone)
    added = 0
    for p, s in zip(xy, src):
        if not state.conflicts(p[None], np.array([s]))[0]:
            state.add(np.array([s]), p[None], horizon=True, fixed=False)
            added += 1
    return added


def fill_with_context(state: SynthState, **kwargs) -> int:
    """Fill the region growing from the context first (§5.4 filler, started from the
    frozen neighbours instead of a patch); parts of the region that growth did not reach
    are then seeded with a patch at their centre, as :func:`strew.synth.fill` does.

    Returns
    -------
    int
        Elements added (voids included).
    """
    from ._grow import _first_point, grow, seed_patch

    before = state.n
    state.brush_points = np.zeros((0, 2))
    state.brush_radii = np.zeros(0)
    if state.horizon.any():
        grow(state, **kwargs)
    reach = float(state.prep.rbar.max())
    for p in _first_point(state):
        if state.n and np.min(np.hypot(*(state.pos - np.asarray(p)).T)) <= reach:
            continue  # growth reached this part already
        seed_patch(state, p)
        grow(state, **kwargs)
    return state.n - before
