"""Flow mode: a sheared patch grown again from its border (issue 14 point 2).

Not in the paper (§5.3 grows each element once, §5.5 only relaxes). Where the growth
front lags the field at the frame's turn limit (``flow_max_turn``), the lattice it
leaves is sheared over a patch: one bond family stretched, the rows too far apart, a
missing half-row spread over it (``benchmarks/flow14w_shear.py``); no later pass
repairs it (the shear band pass sends it back whole, densify finds no room). Here the
largest connected patch of interior sites without six neighbours is taken out, and
grown again (§5.2-§5.4 as in the growth) from the empty ring slots of the elements
around it, and relaxed (§5.5 and the band's network pass); the new patch is kept only
where the interior six share rises and no new hole opens. Where it is not kept, the
patch is taken out once more with the interior elements within ``REGROW_WIDEN`` six
spacings of it (its border then lies in the lattice around the shear, not on the
shear's own stretched bonds) and grown again under the same test: the hexagons over
16 spacings from (14, 2) (``benchmarks/flow14p_heldout.py``) grew the patch of 35
sites again to a six share of 0.856 (0.747 before) but left one point over 0.75 mean
edges from every element, so it was sent back; the patch of 57 widened so gives
0.857 and no hole (``benchmarks/flow15_probe.py``). Patches of 8-11 sites, which the
corner starts keep after the larger ones are grown again, are grown again too, held
also to the widest empty circle (``REGROW_MIN``, ``REGROW_SMALL``; flow17).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from ._flow_holes import close_holes
from ._flow_kernels import boundary_distance
from ._flow_net import NET_BAND, hexagonal_reference, relax_network, six_spacing
from ._flow_net import _six_share as six_share
from ._flow_retry import interior_score, restore, snapshot
from ._objects import DEAD, ELEMENT

__all__ = ["regrow_sheared"]

#: a patch is grown again only where it holds at least this many sites (linked within
#: 1.3 six spacings; an isolated dislocation's 5-7 pair is two). 12 at flow15: the
#: corner starts' patches left after the first regrowth were 8-11 sites, e.g. the
#: hexagons over 16 spacings from (2, 14), six share 0.818 with 8 lowered to 0.878, and
#: the scales over 16 from (2, 2) 0.795 -> 0.838, none of the 30 held-out cases lower
#: (hexagons' sum 13.237 -> 13.360, scales' 13.156 -> 13.264 and their hole gone:
#: ``benchmarks/flow17_screen.py --cases all``; flow17, with the turn guard flow18)
REGROW_MIN = 8
#: patches under this many sites (the smallest before flow17) are held to the widest
#: empty circle too (``REGROW_HOLE``; see :func:`regrow_sheared`)
REGROW_SMALL = 12
#: the frame's turn limits tried for the regrowth, as multiples of ``flow_max_turn``
#: (larger ones turned elements past the field's limit that §5.3's frame keeps)
REGROW_TURNS = (1.0,)
#: a regrowth is sent back where it leaves an empty circle wider than this many six
#: spacings (``benchmarks/grow.py``'s hole) wider than the widest before
REGROW_HOLE = 0.75
#: a patch under ``REGROW_SMALL`` sites is tried only where all its sites lie farther
#: than this many six spacings from the region's edge (the interior line is at two
#: mean edges). A cost cap, not the paper's: the 90 degree field over 30 x 20 spacings
#: (``benchmarks/grow.py --against REV --cases hexflow``) tried a patch of 10 at 2.02
#: spacings, then widened, both sent back, 1.53x its CPU; the least of the patches
#: kept on the held-out fields was 2.21 (the hexagons over 20 spacings from (2, 18);
#: ``benchmarks/flow17_screen.py --cases all``; flow18)
REGROW_EDGE = 2.1
#: how many patches are tried, largest first
REGROW_PATCHES = 3
#: a patch not kept is tried again with the interior elements within this many six
#: spacings of it
REGROW_WIDEN = 1.3


def _patches(g) -> list[list[int]]:
    """The connected groups (within 1.3 six spacings) of interior elements without six
    neighbours at 0.85-1.15 spacings, largest first."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components
    from scipy.spatial import cKDTree

    els = np.asarray([i for i in g.order if g.state[i] == ELEMENT], dtype=np.intp)
    if len(els) < 7:
        return []
    xy = g.pos[els]
    L = g.l
    inner = boundary_distance(g.region, xy) > 2.0 * L if g.region is not None else np.ones(len(els), bool)
    tree = cKDTree(xy)
    S = six_spacing(g)
    hi = np.asarray(tree.query_ball_point(xy, 1.15 * S, return_length=True), dtype=int) - 1
    lo = np.asarray(tree.query_ball_point(xy, 0.85 * S, return_length=True), dtype=int) - 1
    bad = np.flatnonzero(inner & ~((hi == 6) & (lo == 0)))
    if len(bad) < REGROW_MIN:
        return []
    pr = cKDTree(xy[bad]).query_pairs(1.3 * S, output_type="ndarray")
    m = coo_matrix((np.ones(len(pr)), (pr[:, 0], pr[:, 1])), shape=(len(bad), len(bad)))
    nc, lab = connected_components(m, directed=False)
    groups = [els[bad[lab == c]].tolist() for c in range(nc)]
    groups = [q for q in groups if len(q) >= REGROW_MIN]
    groups.sort(key=lambda q: (-len(q), min(q)))
    return groups


def _widen(g, patch: list[int]) -> list[int]:
    """The patch and the interior elements within ``REGROW_WIDEN`` six spacings of it,
    sorted."""
    from scipy.spatial import cKDTree

    els = np.asarray([i for i in g.order if g.state[i] == ELEMENT], dtype=np.intp)
    xy = g.pos[els]
    inner = boundary_distance(g.region, xy) > 2.0 * g.l if g.region is not None else np.ones(len(els), bool)
    near = cKDTree(g.pos[np.asarray(patch, dtype=np.intp)]).query(xy)[0] < REGROW_WIDEN * six_spacing(g)
    return sorted(set(patch) | set(els[inner & near].tolist()))


def _widest(g) -> float:
    """The widest empty circle (the largest Delaunay circumradius) centred over two mean
    edges inside the region, in six spacings (0 with no region or under three
    elements)."""
    from scipy.spatial import Delaunay

    els = np.asarray([i for i in g.order if g.state[i] == ELEMENT], dtype=np.intp)
    if g.region is None or len(els) < 3:
        return 0.0
    xy = g.pos[els]
    tri = xy[Delaunay(xy).simplices]
    a, b, c = tri[:, 0], tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]
    d = 2.0 * (b[:, 0] * c[:, 1] - b[:, 1] * c[:, 0])
    ok = np.abs(d) > 1e-12
    b, c, d, a = b[ok], c[ok], d[ok], a[ok]
    bb, cc = (b * b).sum(1), (c * c).sum(1)
    u = np.c_[(c[:, 1] * bb - b[:, 1] * cc) / d, (b[:, 0] * cc - c[:, 0] * bb) / d]
    cen = a + u
    inner = g.region.contains(cen)
    inner[inner] = boundary_distance(g.region, cen[inner]) > 2.0 * g.l
    return float(np.hypot(*u[inner].T).max() / six_spacing(g)) if inner.any() else 0.0


def _interior(g, patch: list[int]) -> bool:
    """All the patch's sites farther than ``REGROW_EDGE`` six spacings from the region's
    edge (True without a region)."""
    if g.region is None:
        return True
    xy = g.pos[np.asarray(patch, dtype=np.intp)]
    return bool(boundary_distance(g.region, xy).min() > REGROW_EDGE * six_spacing(g))


def _turn_ok(g, p) -> bool:
    """The lattice's turn from the field within the band pass's limit
    (``flow_net_turn`` over the turn as grown; :func:`strew.grow._flow_net._misalignment`)."""
    from ._flow_net import _misalignment

    t0 = getattr(g, "flow_net_turn0", None)
    return t0 is None or p.flow_net_turn is None or _misalignment(g) <= t0 + p.flow_net_turn


def _take_out(g, patch: list[int]) -> list[int]:
    """The patch's elements taken out (edges, ring targets, index, order); the elements
    left around it, sorted."""
    gone = set(patch)
    around: set[int] = set()
    for o in patch:
        for j in list(g.adj[o]):
            if g.target[j] is not None:
                g.target[j].pop(o, None)
            g.remove_edge(o, j)
            if j not in gone and g.state[j] == ELEMENT:
                around.add(j)
        g.state[o] = DEAD
        g.index.remove(o)
    g.order[:] = [i for i in g.order if i not in gone]
    return sorted(around)


def regrow_sheared(g, target: int, rep) -> int:
    """Grow the sheared patches again (see the module); how many were kept."""
    p0 = g.p
    kept = 0
    tried: set[tuple[int, ...]] = set()
    for _ in range(REGROW_PATCHES):
        if len(g.order) >= target:
            break
        groups = [q for q in _patches(g) if tuple(sorted(q)) not in tried and (len(q) >= REGROW_SMALL or _interior(g, q))]
        if not groups:
            break
        patch = groups[0]
        tried.add(tuple(sorted(patch)))
        share0 = six_share(g)
        far0 = interior_score(g)[1]
        # (a patch under ``REGROW_SMALL`` sites, and its widened patch, also kept only
        # where it leaves no empty circle wider than a hole's, 0.75 six spacings, or
        # than the widest before: the quarter-edge grid of interior_score can miss one
        # by a third of an edge, and the scales along the 90 degree field over 30
        # spacings kept the widened regrowth of a patch of 9 that left one of 0.774
        # spacings, benchmarks/grow.py's hole. Not on the larger patches: there it sent
        # back regrowths flow15 keeps, e.g. the hexagons over 16 spacings from (14, 2)
        # 0.857 -> 0.747, the scales over 20 from (18, 2) 0.881 -> 0.780. flow17)
        wide0 = max(_widest(g), REGROW_HOLE) if len(patch) < REGROW_SMALL else np.inf
        base = snapshot(g)
        # the turn limits tried in turn, the first regrowth that raises the six share
        # with no new hole kept (its holes' elements turned no further than the
        # frame's limit, ``flow_max_turn``, not ``flow_hole_turn``: an element turned
        # past it is off §5.3's frame)
        # (then the patch widened by the lattice around it: the module's docstring)
        for f, wide in [(f, w) for f in REGROW_TURNS for w in (False, True)]:
            restore(g, base)
            base = snapshot(g)  # (a snapshot is used, not copied, when put back)
            g.p = replace(p0, flow_max_turn=f * p0.flow_max_turn, flow_hole_turn=p0.flow_max_turn)
            _regrow(g, _widen(g, patch) if wide else patch, target, rep)
            g.p = p0
            sh, far = six_share(g), interior_score(g)[1]
            # (a patch under REGROW_SMALL also kept only where the lattice's turn from
            # the field stays within the band pass's limit, flow_net_turn over the turn
            # as grown: without it the hexagons over 20 spacings from the centre kept a
            # regrowth to a six share of 0.942 whose turn p90 was 17.37 degrees against
            # 16.84 + 0.5, test_grow_flow14p_turn; with it 0.929 as before. flow17/18)
            small_ok = wide0 == np.inf or (_widest(g) <= wide0 and _turn_ok(g, p0))
            if sh > share0 + 1e-12 and far <= far0 and small_ok:
                kept += 1
                break
        else:
            restore(g, base)
    return kept


def _regrow(g, patch: list[int], target: int, rep) -> None:
    """The patch taken out and grown again from the empty slots of the rings around
    it (§5.2-§5.4), relaxed (§5.5 and the band's network pass), and its holes closed
    as after the growth (:func:`strew.grow._flow_holes.close_holes`)."""
    around = _take_out(g, patch)
    for s in around:
        if g.state[s] == ELEMENT:
            g.seed_empty_slots(s)
    g.advance(rep, target)
    g.settle()
    net = bool(g.p.flow_net_rounds and g.p.relax and hexagonal_reference(g.ref))
    if net:
        relax_network(g, band=NET_BAND)
    if len(g.order) < target and close_holes(g, target) and net:
        relax_network(g, band=NET_BAND)
    if len(g.order) < target and close_holes(g, target, push=True) and net:
        relax_network(g, band=NET_BAND)
