"""Context elements that stay elements: growth on from a finished tile's ornament (issue 19.4).

Wong et al. grow one panel in one run (§4.1): every element may be the parent of the
next, and the largest empty circle adjacent to the ornament is grown into by the
elements around it. A tiled world (:mod:`strew.tiles`) runs the method once per tile,
with the finished neighbours' elements as ``context``. Seen only as the panel's edge
(the panel less their drawn footprint), a later tile treated them as §4.1's boundary:
circles that touch only them are discarded, and the band along them was filled last,
by the smallest elements (flowers, 480 x 480 in tiles of 120: within about s / 2 of a
border only buds; leaves 0.54x, buds 1.28x the interior's share in the +-2 s strips).

In a tiled run each drawn element therefore also carries its proxies, its element
type's user fields, its phase and whether it is sterile, in the private column
:data:`PROXIES_COLUMN` (one record per element drawn in that row: the members of a
group, e.g. a spiral's segments). A later tile rebuilds them as placed elements:
obstacles through their exact proxies, as its own elements are, and parents that its
rules grow from, as if the neighbour's run had gone on. The column is dropped before
a world's tiles reach their sink.

Three more hand-over rules make the cut look like one run's (strew.tiles._keep_groups):

- a tile keeps or drops each rule success whole (:data:`GROUP_COLUMN`, by the mean of
  its elements' centres) and only with its parent's (:func:`keep_whole`): a flower
  dropped beyond the border had left its stem and leaf hanging from the kept parent;
- a tile leaves its later phases' elements (§5's state preconditions: the flowers'
  buds) within half a halo of a later tile to that tile. In one run no bud exists
  while flowers grow; a cut edge of buds and stems gave the later tile's flowers no
  parent, and its buds filled the band;
- a tile leaves to a later tile, within half a halo of it, the rule successes whose
  empty circle touched an element it drops (:func:`cut_touching`, :data:`GOAL_COLUMN`),
  and theirs in turn: they filled pockets against elements beyond the border, and left
  a ragged front into which the later tile's flowers grew on stems too short for a
  leaf (Appendix A's 8-unit rule).

Departure from the paper: Wong et al. grow one panel in one run; this hand-over between
runs is ours. ``python benchmarks/worlds_strips.py --methods ornament --seeds 1
--no-fidelity`` (flowers, 480 x 480, tiles 120), 82a4322 -> now: +-2 s strips density
1.006x -> 0.997x, stem 1.002x -> 0.986x, leaf 0.536x -> 0.960x, flower 0.857x ->
1.028x, bud 1.276x -> 1.020x; +-1 s density 0.950x -> 0.966x, leaf 0.527x -> 0.909x,
flower 0.637x -> 1.018x, bud 1.604x -> 0.983x (the untiled control on the same lines:
+-2 s flower 0.936x, +-1 s leaf 1.066x); elements 21,354 -> 21,258 (untiled 21,369);
tiled CPU 119.7 s -> 65.1 s (a later tile no longer grows a second front from a seed).
"""

from __future__ import annotations

import copy
from typing import Any

import numpy as np

from ._pattern import Element, Pattern
from ._proxies import Proxy

__all__ = ["GOAL_COLUMN", "GROUP_COLUMN", "PARENT_COLUMN", "PROXIES_COLUMN", "element_record", "elements_from", "records_column"]

PROXIES_COLUMN = "ornament_proxies"
"""The private column of a tiled ornament's tile: per row, a tuple of element records."""

GROUP_COLUMN = "ornament_group"
"""The private column of a tiled ornament's tile: per row, the rule success that placed
it (the placement index of its first child). A tile keeps or drops such a group whole
(strew.tiles._keep_groups): a flower dropped beyond the border left its stem and leaf
dangling from the kept parent, fencing the band along the border off from new flowers."""

GOAL_COLUMN = "ornament_goal"
"""The private column of a tiled ornament's tile: per row, the empty circle ``(x, y,
radius)`` that its rule success grew into (NaNs for none). A tile drops its successes
whose circle touched an element it drops (strew.tiles._keep_groups, :func:`cut_touching`):
they filled a pocket whose other side the tile drops."""


PARENT_COLUMN = "ornament_parent"
"""The private column of a tiled ornament's tile: per row, the ``element`` of the row that
draws its parent (-1 for none drawn in the tile: a seed, a context element). It differs
from the public ``parent`` (the parent's placement index) where the parent is a group's
member: a spiral branches from any arm of its parent spiral, and a spiral's row is its
first arm (Pattern.group), so ``parent`` named a row for 7 of 131 spirals (60 x 60,
seed 0). strew.tiles places a success at its parent's row (_at_parent) and keeps it only
with that row (:func:`keep_whole`): by ``parent`` a spiral was placed by its own centre
and its parent's cut was lost, so a tile kept spirals whose parent spiral it dropped."""


def _slots(cls: type) -> list[str]:
    names: list[str] = []
    for c in cls.__mro__:
        for s in getattr(c, "__slots__", ()):
            if s != "_geom" and s not in names:
                names.append(s)
    return names


def _plain(v: Any) -> Any:
    return np.array(v, dtype=float) if isinstance(v, np.ndarray) else copy.copy(v)


def element_record(el: Element, pattern: Pattern) -> tuple:
    """``(type, phase, sterile, fields, proxies)`` of a placed element, plain data."""
    et = pattern.types[el.type]
    fields = tuple((k, copy.deepcopy(getattr(el, k))) for k in et.fields)
    proxies = tuple(tuple((s, _plain(getattr(p, s))) for s in _slots(type(p))) for p in el.proxies)
    return (el.type, el.phase, bool(el.sterile), fields, proxies)


def records_column(groups: list[list[Element]], pattern: Pattern) -> np.ndarray:
    """(n,) object array: per drawn row, the records of the elements it draws."""
    col = np.empty(len(groups), dtype=object)
    for i, g in enumerate(groups):
        col[i] = tuple(element_record(e, pattern) for e in g)
    return col


def elements_from(column: Any, pattern: Pattern) -> list[Element]:
    """Elements rebuilt from :data:`PROXIES_COLUMN` values (rows without records are
    skipped), marked ``context`` (not drawn, not counted)."""
    out: list[Element] = []
    for recs in column:
        if not recs:
            continue
        for type_name, phase, sterile, fields, proxies in recs:
            et = pattern.types.get(type_name)
            if et is None or len(et.proxies) != len(proxies):
                continue
            el = Element(et)
            for pr, state in zip(el.proxies, proxies):
                if not isinstance(pr, Proxy):
                    continue
                for s, v in state:
                    setattr(pr, s, _plain(v))
                pr._geom = None
            for k, v in fields:
                setattr(el, k, copy.deepcopy(v))
            el.sterile = bool(sterile)
            el.phase = phase
            el.context = True  # type: ignore[attr-defined]
            out.append(el)
    return out


def keep_whole(element: Any, parent: Any, group: Any, placed: np.ndarray) -> np.ndarray:
    """(n,) bool: which drawn rows a tile keeps, in whole rule successes.

    ``placed`` (per row) is the tile's keep-rule by the row's own centre. A rule success
    (:data:`GROUP_COLUMN`: a flower, its stem and its leaf) is kept when the mean of its
    rows' centres is placed so and its parent's success was kept: a stem then never
    dangles, neither from a kept parent towards a dropped flower nor from a dropped
    parent (Wong et al. grow one tree of elements, §4.1; a tile's share of it is a
    subtree cut whole). Parents not drawn in the tile (its seeds, context elements) count
    as kept. Groups are numbered in placement order, so parents come first.
    """
    element = np.asarray(element, np.int64)
    parent = np.asarray(parent, np.int64)
    group = np.asarray(group, np.int64)
    n = len(group)
    if not n:
        return np.zeros(0, bool)
    ids, inv = np.unique(group, return_inverse=True)
    cnt = np.bincount(inv)
    votes = np.bincount(inv, weights=np.asarray(placed, float)) / cnt
    # the group of each drawn element, and the parent element of each group
    group_of = dict(zip(element.tolist(), inv.tolist()))
    par = np.full(len(ids), -1, np.int64)
    par[inv] = parent
    ok = np.zeros(len(ids), bool)
    for g in range(len(ids)):  # ids ascending: a parent's group precedes its children's
        p = int(par[g])
        pg = group_of.get(p, -1) if p >= 0 else -1
        ok[g] = votes[g] >= 0.5 and (pg < 0 or pg == g or bool(ok[pg]))
    return ok[inv]


def keep_ancestors(
    element: Any, parent: Any, group: Any, placed: np.ndarray, far: np.ndarray, barred: np.ndarray | None = None
) -> np.ndarray:
    """(n,) bool: ``placed`` with the rows of every ancestor of a lost success set, so that
    :func:`keep_whole` keeps that success. A success is lost where :func:`keep_whole`
    drops it only for an ancestor's sake (its own rows vote it placed) and one of its rows
    is ``far`` (beyond every later tile's region, strew.tiles._keep_groups): no tile grows
    there again, and its subtree left a hole in the finished tile.

    Wong et al. grow one tree of elements in one run (§4.1): a success kept with its
    ancestors is what one run would have drawn there; the ancestors kept past the border
    (or within half a halo of it, strew.tiles._LATE_BAND) lie in the tile's grown
    rectangle, and the later tile grows around them as around the rest of its context.
    Without it (d6d394e), the vase, seed 1, dropped 43 rows (hooks, teardrops) a halo or
    more from every later tile at tile 72 and 162 at tile 84, holes in the tiles' cores
    (benchmarks/vas19v_vines.py). Departure from the paper: the hand-over between runs is
    ours.

    ``barred`` (per row, optional) marks rows never kept as an ancestor: a lost success
    whose chain of ancestors holds a barred row that ``placed`` does not keep stays lost,
    and none of that chain is kept for it. strew.tiles._keep_groups bars, for a pattern
    with tile anchors (the vase's grid flowers), the later phases' rows inside a later
    tile that come within a flower's radius of a grid point (covers_anchor_grid): with the halo's open edges the hooks grew chains from past the border back into
    the tile, and their ancestors, kept 8 units into the later tile, covered grid points
    whose flowers that tile (its vines phase, §5) had not delivered yet (world seeds 15,
    16, tile 48: 5 of 128 grid points empty; benchmarks/w25_keep.py). Departure from the
    paper (§4.1, §5: one run delivers every grid flower before any hook): ours.
    """
    element = np.asarray(element, np.int64)
    parent = np.asarray(parent, np.int64)
    group = np.asarray(group, np.int64)
    placed = np.asarray(placed, bool)
    if not len(group):
        return placed.copy()
    kept = keep_whole(element, parent, group, placed)
    ids, inv = np.unique(group, return_inverse=True)
    votes = np.bincount(inv, weights=placed.astype(float)) / np.bincount(inv)
    lost = np.zeros(len(ids), bool)
    lost[inv[~kept & np.asarray(far, bool)]] = True
    lost &= votes >= 0.5
    if not lost.any():
        return placed.copy()
    group_of = dict(zip(element.tolist(), inv.tolist()))
    par = np.full(len(ids), -1, np.int64)
    par[inv] = parent
    bar_g = np.zeros(len(ids), bool)
    if barred is not None:
        # a group is barred where one of its rows is barred and not placed by itself
        bar_g[inv[np.asarray(barred, bool) & ~placed]] = True
    keep_g = np.zeros(len(ids), bool)
    for g in np.flatnonzero(lost):
        chain = []
        p = group_of.get(int(par[g]), -1) if par[g] >= 0 else -1
        while p >= 0 and p != g and not keep_g[p] and p not in chain:
            chain.append(p)
            g, p = p, (group_of.get(int(par[p]), -1) if par[p] >= 0 else -1)
        if not bar_g[chain].any():
            keep_g[chain] = True
    return placed | keep_g[inv]


def parent_rows(pattern: Any, records: Any) -> np.ndarray:
    """(n,) bool: the rows that draw an element of a type some rule grows from (the
    flowers' flower and bud, not their stem and leaf).

    strew.tiles._keep_groups places a rule success by the mean of these rows' centres
    (all rows where a success has none), its growing tip; a success whose every row is
    one (willow, whose every type parents a rule) by its parent's centre instead
    (strew.tiles._at_parent). The mean of all its rows shifted towards an optional child: a flower's
    leaf, at its stem's midpoint, pulled the mean of a success growing into a later tile
    back by a third of the stem, so that the finished tile kept successes with a leaf
    whose flower lay past the border (flowers at 0-2 units past it placed by the finished
    tile: 46 % of those with a leaf, 7 % of the others at 3e74fcd; 1 % with this rule;
    benchmarks/orn19k_direction.py). Departure from the paper: Wong et al. grow one
    panel in one run (§4.1); this hand-over between runs is ours.
    """
    from ._pattern import load_pattern

    pat = load_pattern(pattern)
    return _rows_of(records, {r.parent for r in pat.rules})


def _rows_of(records: Any, names: set) -> np.ndarray:
    """(n,) bool: the rows whose proxy records draw an element of a type in ``names``."""
    return np.array([bool(recs) and any(rec[0] in names for rec in recs) for recs in records], bool)


def anchor_rows(pattern: Any, records: Any) -> np.ndarray:
    """(n,) bool: the rows that draw an element of one of the pattern's tile anchors (the
    element types named by its ``tile_anchors`` attribute; none by default).

    strew.tiles._keep_groups places a rule success holding such a row at the mean of these
    rows' centres, not at its growing tip (parent_rows, strew.tiles._at_parent). The vase
    names its flowers: a vine delivers its flower to a grid point fixed in the world (Wong
    et al. §5, "predefined locations on the grid"), so the tile holding that grid point owns
    the flower and the vine that brings it. Placed at its parent, a finished tile kept the
    vines it grew from its flowers across the border to the grid points up to a halo past it,
    and every such vine crossed the border at one place of the grid: tile 72 (seed 1), 22
    of the 24 vines centred within 1 s of a border (the untiled control: 10), all 0-0.5 s past
    it, where the grid's midpoints 143 = 6.5 x 22 lie next to the border 144; hooks in the
    +-1 s strip 0.972 of the control's share. Placed at the flower (with keep_ancestors),
    tiled / untiled control: T72 +-1 s density 0.969 -> 0.980, hook 0.972 -> 0.992, 10 vines
    in the strip; T60 +-1 s 1.036 -> 0.973, +-2 s 1.028 -> 1.007 (benchmarks/vas19s_compare.py,
    vas19v_vines.py). Departure from the paper: Wong et al. grow one panel in one run
    (§4.1); this hand-over between runs is ours.
    """
    from ._pattern import load_pattern

    pat = load_pattern(pattern)
    names = set(getattr(pat, "tile_anchors", ()) or ())
    if not names:
        return np.zeros(len(records), bool)
    return _rows_of(records, names)


def covers_anchor_grid(pattern: Any, records: Any, rows: np.ndarray) -> np.ndarray:
    """(n,) bool: of ``rows``, those whose elements come within the anchor's radius of a
    point of the pattern's anchor grid (``tile_anchor_grid = (spacing, radius)``: the
    vase's flower grid, fixed in the world, §5); all False without one."""
    import shapely

    from ._pattern import load_pattern

    pat = load_pattern(pattern)
    out = np.zeros(len(records), bool)
    grid = getattr(pat, "tile_anchor_grid", None)
    if grid is None:
        return out
    g, r = float(grid[0]), float(grid[1])
    for i in np.flatnonzero(rows):
        for el in elements_from([records[i]], pat):
            for pr in el.proxies:
                geo = pr.geometry
                x0, y0, x1, y1 = geo.bounds
                ii = np.arange(np.floor((x0 - r) / g), np.ceil((x1 + r) / g) + 1)
                jj = np.arange(np.floor((y0 - r) / g), np.ceil((y1 + r) / g) + 1)
                pts = shapely.points(*(np.stack(np.meshgrid(ii * g, jj * g), -1).reshape(-1, 2).T))
                if (shapely.distance(geo, pts) < r).any():
                    out[i] = True
    return out


def late_phase(pattern: Any, phase: Any) -> np.ndarray:
    """(n,) bool: rows placed after the pattern's first phase (§5's state preconditions:
    the flowers' buds), False for a pattern without phases."""
    from ._pattern import load_pattern

    pat = load_pattern(pattern)
    ph = np.asarray(phase, dtype=object)
    if not pat.phases:
        return np.zeros(len(ph), bool)
    first = pat.phases[0].name
    return np.array([p not in (first, "", None) for p in ph], bool)


CUT_TOUCH = 0.1
"""A tile also leaves to a later tile its successes whose empty circle touched (within
this fraction of its radius) an element placed before them that the tile drops
(:func:`cut_touching`); 0 turns the rule off."""


def cut_touching(pattern: Any, records: Any, group: Any, goal: Any, kept: np.ndarray) -> np.ndarray:
    """(n,) bool: the kept rows whose rule success grew into an empty circle
    (:data:`GOAL_COLUMN`) that touched, within :data:`CUT_TOUCH` of its radius, a row
    the tile drops (``~kept``) placed before that success.

    Wong et al. grow into the largest empty circle first (§4.1): such a circle was as
    small as it was because of the dropped element, and the space it filled is, once that
    element is gone, part of a larger gap. Kept, the success leaves the later tile a
    pocket of the cut that its flowers grow into on stems too short for a leaf (Appendix
    A's 8-unit rule); dropped, the later tile grows through the larger gap as one run
    would. Departure from the paper: it grows one panel in one run; this hand-over
    between runs is ours.
    """
    import shapely

    n = len(kept)
    out = np.zeros(n, bool)
    if not n or CUT_TOUCH <= 0 or kept.all() or not kept.any():
        return out
    from ._pattern import load_pattern

    pat = load_pattern(pattern)
    group = np.asarray(group, np.int64)
    drop = np.flatnonzero(~kept)
    geoms, gid = [], []
    for i in drop:
        for el in elements_from([records[i]], pat):
            for pr in el.proxies:
                geoms.append(pr.geometry)
                gid.append(group[i])
    if not geoms:
        return out
    gid_a = np.asarray(gid, np.int64)
    tree = shapely.STRtree(geoms)
    rows = np.flatnonzero(kept)
    g = np.array([tuple(v) if v is not None else (np.nan, np.nan, np.nan) for v in np.asarray(goal, dtype=object)[rows]], float).reshape(len(rows), 3)
    ok = np.isfinite(g).all(axis=1)
    rows, g = rows[ok], g[ok]
    if not len(rows):
        return out
    pts = shapely.points(g[:, :2])
    q, hit = tree.query(pts, predicate="dwithin", distance=g[:, 2] * (1.0 + CUT_TOUCH))
    earlier = gid_a[hit] < group[rows[q]]
    out[rows[q[earlier]]] = True
    return out
