"""``vase``: flowers on a grid, delivered by a curving vine; hooks and teardrops fill the
rest (Wong et al. 1998, §5, Fig. 9, after a red Chinese vase).

"The pattern has two types of stylized flowers laid down in a grid pattern and connected
by curving stems. The remaining space is filled with small hook-shaped curves, which
themselves are adorned with smaller teardrop shapes. [...] the large vine appears to
deliver its flowers to predefined locations on the grid" (§5). Two phases (§5's state
preconditions):

``vines``
    From the point of a vine (or the seed) nearest the empty circle C, a cubic Bézier vine
    curves to the free grid point nearest C's centre, and a flower opens there: a
    ``lotus`` or a ``peony``, by the grid point's parity. The grid (spacing
    :data:`GRID`) is fixed in the panel's coordinates: the flowers land on it wherever
    the vine comes from.
``hooks``
    A small hook curls from the nearest element into C, ending in a teardrop (from the
    seed too, in a panel where no grid point can hold a flower).

This file is a complete rule file: copy it to start your own.
"""

from __future__ import annotations

import math

import numpy as np

from strew.ornament import FAILURE, SUCCESS, Bezier, Circle, Mark, Pattern, Point, angle_of, tapered_stroke, unit

GRID = 22.0  # spacing of the flowers' grid
FLOWER_RADIUS = 6.0
REACH = 1.6 * GRID  # longest vine
MIN_VINE = FLOWER_RADIUS + 1.0  # shortest vine (its chord, start to flower centre)
HOOK_MAX = 7.0  # longest hook
SHRINK = 0.8  # a hook that does not fit tries this much shorter (hook)
RED = "#a3231f"
GOLD = "#d9a441"

pattern = Pattern(
    "vase",
    state={"flowers": []},
    min_radius=1.5,
    phases=[("vines", 5.0), ("hooks", None)],
    description="Fig. 9: lotus and peony flowers on a grid joined by a vine; hooks with teardrops fill the rest.",
    draw_order=["vine", "hook", "lotus", "peony", "teardrop"],
)

# a tiled world (strew.tiles) places a vine's success at the flower it delivers, on the
# grid fixed in the world: the tile holding the grid point owns it (anchor_rows in
# strew.ornament._context; not in the paper, which grows one panel in one run)
pattern.tile_anchors = ("lotus", "peony")
# the anchors' grid (spacing, flower radius): strew.ornament._context.covers_anchor_grid
pattern.tile_anchor_grid = (GRID, FLOWER_RADIUS)

# a tiled world (strew.tiles) keeps each tile's vines phase (vines and the flowers they
# deliver) up to half a halo past its border, with the halo's edges towards later tiles
# open, so that the vine structure near a border is one run's, grown before any hook
# (strew.tiles._first_phase_rows, as hierarchy; not in the paper, which grows one panel
# in one run)
pattern.tile_keeps_first_phase = True

pattern.element("seed", Point)
pattern.element("vine", Bezier, depth=0)
pattern.element("lotus", Circle)
pattern.element("peony", Circle)
pattern.element("hook", Bezier, turn=1.0)
pattern.element("teardrop", Circle)


def _nearest_on(el, target):
    """The point of element ``el``'s curve (or centre) nearest ``target``, with the
    tangent there: ((2,), (2,))."""
    pr = el.proxy
    if isinstance(pr, Bezier):
        ts = np.linspace(0.1, 1.0, 19)
        pts = pr.point_at(ts)
        k = int(np.argmin(np.hypot(*(pts - target).T)))
        return pts[k], pr.tangent_at(float(ts[k]))
    c = np.asarray(pr.center, dtype=float)
    d = target - c
    n = float(np.hypot(*d))
    u = d / n if n > 0 else np.array([1.0, 0.0])
    r = pr.radius if isinstance(pr, Circle) else 0.0
    return c + r * u, u


def _free_grid_point(ctx, near, start=None):
    """The grid point nearest ``near`` that holds no flower yet, inside the panel; with
    ``start``, the nearest of those within the vine's reach (:data:`REACH`) of it and
    farther from it than the shortest vine (:data:`MIN_VINE`)."""
    i0, j0 = round(near[0] / GRID), round(near[1] / GRID)
    best = None
    for i in range(i0 - 1, i0 + 2):
        for j in range(j0 - 1, j0 + 2):
            if (i, j) in ctx.state.flowers:
                continue
            p = np.array([i * GRID, j * GRID])
            # a grid point at the vine's start can hold no vine (grow_vine's length test):
            # chosen, it failed every try. The seed's goals lie beyond the reach (C touches
            # the seed, §4.1), so the seed's vine looked near the chord's point REACH - GRID
            # out, and the grid point at the seed itself was the nearest for every C where
            # the panel's centre falls on the grid: the square panels 264 and 352 grew no
            # flower at all (160..400 step 8, rng 1; the others 15.5-19.9 per 10^4)
            if start is not None and not MIN_VINE < float(np.hypot(*(p - start))) <= REACH:
                continue
            d = float(np.hypot(*(p - near)))
            if best is None or d < best[0]:
                best = (d, (i, j), p)
    return best


def _grid_points_in_panel(ctx, near, start):
    """The free grid points within the vine's reach of ``start`` (farther than
    :data:`MIN_VINE`, up to :data:`REACH`) whose flower lies inside the panel, nearest
    ``near`` first, as :func:`_free_grid_point`'s tuples.

    For an empty circle C whose centre lies past the panel (a tiled world's open halo
    edges, strew.tiles._open_edges; never in one run, where §4.1 discards a circle the
    boundary stops). Not in §5, whose C always lies in the panel: the grid points nearest
    such a C lie past the panel's edge or within a flower's radius of it, so its flower
    failed ``ctx.inside`` and C went on the exclude list. A first-phase tile of a tiled
    vase whose four halo edges are all open (every neighbour later) found every vines-phase
    C past an edge, the largest first (radius 48, 12 past the edge, at tile 48): its seed
    grew no vine and no flower, and the later tiles around it none either (helper wv2,
    tile 48's tile 10: 21 of 64 grid points empty). C still touches the seed (§4.1), so the
    grid points in its neighbourhood within the vine's reach are the ones to deliver to.
    """
    lo = np.floor((start - REACH) / GRID).astype(int)
    hi = np.ceil((start + REACH) / GRID).astype(int)
    out = []
    for i in range(lo[0], hi[0] + 1):
        for j in range(lo[1], hi[1] + 1):
            if (i, j) in ctx.state.flowers:
                continue
            p = np.array([i * GRID, j * GRID])
            if not MIN_VINE < float(np.hypot(*(p - start))) <= REACH:
                continue
            if not ctx.inside(Circle().set(p, FLOWER_RADIUS)):
                continue
            out.append((float(np.hypot(*(p - near))), (i, j), p))
    out.sort(key=lambda f: f[0])
    return out


def _over_free_grid_point(ctx, vine, ij):
    """Whether ``vine`` passes within a flower's radius of a free grid point other than
    its own ``ij``: no flower fits there once it does."""
    pts = vine.proxy.point_at(np.linspace(0.0, 1.0, 21))
    lo = np.floor((pts.min(axis=0) - FLOWER_RADIUS) / GRID).astype(int)
    hi = np.ceil((pts.max(axis=0) + FLOWER_RADIUS) / GRID).astype(int)
    for i in range(lo[0], hi[0] + 1):
        for j in range(lo[1], hi[1] + 1):
            if (i, j) == ij or (i, j) in ctx.state.flowers:
                continue
            if float(np.hypot(*(pts - np.array([i * GRID, j * GRID])).T).min()) < FLOWER_RADIUS:
                return True
    return False


# whether a vine towards a C past the panel may not pass over a free grid point (w25)
_AVOID_OVER = True


def grow_vine(ctx, parent, start, tangent, depth):
    g = ctx.goal.center
    if ctx.boundary_distance(g) <= 0:
        # C's centre lies past the panel (a tiled world's open halo edges): the grid
        # points in the panel within reach, nearest C's centre first, until one takes its
        # vine; a vine that would pass over another free grid point is refused, as the
        # grid point would stay empty for good (tile 60's tile 0: its seed's vine towards
        # a C past the open edge crossed (44, 44), which no flower reached after)
        for found in _grid_points_in_panel(ctx, g, start):
            if _deliver(ctx, parent, start, tangent, depth, found, _AVOID_OVER):
                return SUCCESS
        return FAILURE
    # the free grid point nearest C's centre that the vine can reach. Nearest C's centre
    # alone, the seed's first vine failed in a panel whose largest circles lie farther
    # from the seed than REACH (§4.1: C touches the seed, centred its radius away): the
    # grid point nearest C was out of reach for every C, the vines' phase ended with no
    # flower (a 157.5 x 157.5 panel, seed at its centre: 0 flowers; a tiled world's phase-0
    # tiles, and so every tile, grew none)
    found = _free_grid_point(ctx, g, start)
    to_c = g - start
    far = float(np.hypot(*to_c))
    if found is None and far > REACH - GRID:
        # C lies beyond the vine's reach: the free grid point within reach nearest the
        # point of the chord towards C's centre where the reach ends
        found = _free_grid_point(ctx, start + (REACH - GRID) / far * to_c, start)
    if found is None:
        return FAILURE
    return _deliver(ctx, parent, start, tangent, depth, found, False)


def _deliver(ctx, parent, start, tangent, depth, found, avoid):
    """Grow the vine from ``start`` to the flower at grid point ``found`` (a tuple of
    :func:`_free_grid_point`); ``avoid``: refuse a vine over another free grid point."""
    g, rho = ctx.goal.center, ctx.goal.radius
    _, ij, p = found
    # the grid point must lie in C's neighbourhood, and within the vine's reach
    if float(np.hypot(*(p - g))) > rho + 0.5 * GRID or float(np.hypot(*(p - start))) > REACH:
        return FAILURE
    flower = ctx.new_child("lotus" if (ij[0] + ij[1]) % 2 == 0 else "peony")
    flower.proxy.set(p, FLOWER_RADIUS)
    if ctx.intersects(flower) or not ctx.inside(flower):
        ctx.dynamic.remove(flower)
        return FAILURE
    chord = p - start
    length = float(np.hypot(*chord))
    if length <= MIN_VINE:
        ctx.dynamic.remove(flower)
        return FAILURE
    end = p - FLOWER_RADIUS * unit(chord)
    t_a = tangent if float(np.dot(tangent, chord)) >= 0 else -tangent
    # the vine arrives curving (a quarter-turn swing), as the vase's stems do
    side = 1.0 if ctx.rng.random() < 0.5 else -1.0
    a = angle_of(chord) + side * 0.5
    vine = ctx.new_child("vine", depth=depth)
    vine.proxy.set_points(start, start + 0.4 * length * t_a, end - 0.4 * length * np.array([math.cos(a), math.sin(a)]), end)
    if ctx.intersects(vine, ignore=[parent]) or not ctx.inside(vine) or (avoid and _over_free_grid_point(ctx, vine, ij)):
        ctx.dynamic.remove(flower)
        ctx.dynamic.remove(vine)
        return FAILURE
    ctx.state.flowers.append(ij)
    return SUCCESS


@pattern.rule("seed", phase="vines")
def seed_to_vine(ctx, seed):
    start = seed.proxy.center
    if _flower_at_seed(ctx, seed, start):
        return SUCCESS
    if grow_vine(ctx, seed, start, unit(ctx.goal.center - start), 0):
        seed.sterile = True
        return SUCCESS
    return FAILURE


def _flower_at_seed(ctx, seed, start):
    """Open a flower, with no vine, at the free grid point within :data:`MIN_VINE` of the
    seed, if there is one and it fits; the seed is then spent."""
    # Not in §5 (whose panel's seed need not lie near the grid): a grid point within
    # MIN_VINE of the seed can hold no vine from the seed (grow_vine's length test), and a
    # flower there from any other vine contains the seed's point (or the seed's vine's
    # start) when it lies within FLOWER_RADIUS, so the grid point stayed empty for good:
    # untiled panels 221 / 225 / 227 (seed 0.7 / 3.5 / 4.9 from grid point (5, 5)) missed
    # it, 80 tries aimed there in 225 all hit the seed; in a tiled world every first-phase
    # tile whose seed lies that near a grid point (tile 60: (154, 154) in every seed). The
    # seed opens the flower itself, as the vine's start would: the vase's stems grow on
    # from it (vine_to_vine).
    found = _free_grid_point(ctx, start)
    if found is None or found[0] > MIN_VINE:
        return False
    _, ij, p = found
    flower = ctx.new_child("lotus" if (ij[0] + ij[1]) % 2 == 0 else "peony")
    flower.proxy.set(p, FLOWER_RADIUS)
    if ctx.intersects(flower, ignore=[seed]) or not ctx.inside(flower):
        ctx.dynamic.remove(flower)
        return False
    ctx.state.flowers.append(ij)
    seed.sterile = True
    return True


@pattern.rule("vine lotus peony", phase="vines")
def vine_to_vine(ctx, parent, *_):
    start, tangent = _nearest_on(parent, ctx.goal.center)
    depth = parent.depth + 1 if parent.type == "vine" else 1
    return grow_vine(ctx, parent, start, tangent, depth)


@pattern.rule("seed vine lotus peony hook teardrop", phase="hooks")
def hook(ctx, parent, *_):
    g, rho = ctx.goal.center, ctx.goal.radius
    start, _ = _nearest_on(parent, g)
    chord = g - start
    far = float(np.hypot(*chord))
    # Not in §5 / Appendix A (whose goal is always the empty circle itself): the hook is
    # scaled to the empty circle at the goal's centre (its clearance, as §4.1 measured C),
    # not to a wider goal. In one run the goal is that circle and nothing changes; in a
    # tiled world a later tile raises a goal to the circle its finished neighbour grew
    # into there (strew.ornament._engine._handed_over, issue 19.4), which for willow's
    # refill makes up for circles narrower than the interior's. The vase's refill circles
    # are as wide as the interior's (tile 84, seed 1: mean radius 2.3-2.6 in the later
    # tiles' tries 0-10.5 units into the finished side, 2.3-2.5 in the first tiles' at the
    # same distances), the raise was 2.4-2.9x on 50-63 % of those tries, and the raised
    # hooks, longer with larger teardrops, left the strips sparse. Tiled / untiled control,
    # tile 84: +-2 s density 0.905 -> 1.013, +-1 s 0.983 -> 1.005, elements 21,062 ->
    # 21,498 (control 21,934): the same world as with the hand-over off altogether
    # (benchmarks/vas19s_nohand.py; vas19u_trace.py, vas19u_deficit.py, vas19s_compare.py).
    room = ctx.clearance(g)
    if room > 0 and rho > room + 1e-6:
        rho = room
    length = min(far + 0.3 * rho, HOOK_MAX)
    if length < 1.5:
        return FAILURE
    u = unit(chord)
    turn = -parent.turn if parent.type == "hook" else (1.0 if ctx.rng.random() < 0.5 else -1.0)
    n = turn * np.array([-u[1], u[0]])
    h = ctx.new_child("hook", turn=turn)
    drop = ctx.new_child("teardrop")
    # Not in §5 / Appendix A: a hook that does not fit tries shorter ones (the lengths
    # length * SHRINK**k, k = 1, 2, ..., down to the rule's 1.5) and the longest that fits
    # grows, instead of failing. The hook fills its goal circle (length = chord + 0.3 rho,
    # up to HOOK_MAX), which is the room only while the goal is the empty circle itself;
    # in a tiled world a later tile raises a goal to the circle its finished neighbour
    # grew into there (strew.ornament._engine._handed_over, issue 19.4), the raised hook
    # saturated at HOOK_MAX, collided and failed, and the circle stayed empty (tiled /
    # untiled control, border strips +-2 s: T126 0.910, T60 0.913; with the hand-over off
    # 1.001 / 1.028, benchmarks/vas19s_nohand.py). A hook is homothetic about its start, so
    # a shorter one is not inside a longer one and whether it fits is not monotone in its
    # length: a bisection (as dots.dot_to_dot does for its nested dots) could step past the
    # lengths that fit; a short descending scan takes the longest of a fixed ladder. (A
    # raised goal no longer reaches the hook, see above: the scan is left for the hooks
    # that do not fit in one run: a 120 x 120 panel, 2,846 -> 2,848 elements at vas19t.)
    while True:
        _set_hook(h, drop, start, u, n, length, rho)
        if not ctx.intersects([h, drop], ignore=[parent]) and ctx.inside([h, drop]):
            return SUCCESS
        length *= SHRINK
        if length < 1.5:
            ctx.dynamic.remove(h)
            ctx.dynamic.remove(drop)
            return FAILURE


def _set_hook(h, drop, start, u, n, length, rho):
    """Shape hook ``h`` (from ``start`` along ``u``, curling to side ``n``) and its
    teardrop ``drop`` for a hook of ``length`` in a goal of radius ``rho``."""
    end = start + length * u
    # a hook: out along the chord, curling back at its end
    h.proxy.set_points(start, start + 0.7 * length * u, end + 0.45 * length * n, end + 0.25 * length * n - 0.2 * length * u)
    tip = h.proxy.point_at(1.0)
    drop.proxy.set(tip + 0.12 * length * n, max(0.35, min(0.12 * length, 0.25 * rho)))


# -- rendering: gold on red lacquer would need a background; here red on the paper --------
def _petals(c, r, k, inner):
    t = np.linspace(0, 2 * np.pi, 12 * k + 1)
    rr = r * (inner + (1 - inner) * np.abs(np.cos(k * t / 2)))
    return c + rr[:, None] * np.c_[np.cos(t), np.sin(t)]


@pattern.render("lotus", "vase", help="red flowers, vines and hooks, gold teardrops (Fig. 9)")
def vase_lotus(el, rc):
    c, r = el.proxy.center, el.proxy.radius
    return [Mark([_petals(c, r, 8, 0.55)[:-1]], closed=True, fill=RED, stroke="none"),
            Mark([_petals(c, 0.45 * r, 8, 0.6)[:-1]], closed=True, fill=GOLD, stroke="none")]


@pattern.render("peony", "vase")
def vase_peony(el, rc):
    c, r = el.proxy.center, el.proxy.radius
    return [Mark([_petals(c, r, 5, 0.7)[:-1]], closed=True, fill=RED, stroke="none"),
            Mark.circle(c, 0.35 * r, fill=GOLD, stroke="none")]


@pattern.render("vine", "vase")
def vase_vine(el, rc):
    w = max(1.5 * rc.line_width, 3.0 * rc.line_width * 0.9**el.depth)
    return [Mark.polygon(tapered_stroke(el.proxy.polyline(20), (w, 0.7 * w)), fill=RED)]


@pattern.render("hook", "vase")
def vase_hook(el, rc):
    return [Mark.polygon(tapered_stroke(el.proxy.polyline(16), (1.4 * rc.line_width, 0.4 * rc.line_width)), fill=RED)]


@pattern.render("teardrop", "vase")
def vase_teardrop(el, rc):
    c, r = el.proxy.center, el.proxy.radius
    t = np.linspace(0, 2 * np.pi, 25)[:-1]
    # a teardrop: a circle drawn out to a point (pointing up the page)
    pts = c + r * np.c_[np.cos(t) * (1 - 0.35 * (1 - np.sin(t)) / 2), np.sin(t) + 0.6 * np.maximum(0, -np.sin(t)) ** 3]
    return [Mark.polygon(pts, fill=GOLD, stroke=RED, stroke_width=0.4 * rc.line_width)]
