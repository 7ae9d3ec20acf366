"""``flowers``: flowers joined by stems, with a leaf on long stems (Wong et al. 1998, Appendix A, Figs. 15-16).

Element types, as in the appendix's declaration section::

    seed point            // the required seed element type
    flower circle         // flower: a circle proxy, with a user field `color`
    stem linesegment      // stem: a line segment proxy
    leaf bezier bezier    // leaf: two Bezier segment proxies

The rule ``flower --> stem flower * x leaf`` places a new flower at most 10 units from
its parent towards the goal circle, joins them with a stem, and adds a leaf at the stem's
midpoint only when the new flower is farther than 8 units. This file is a complete rule
file: copy it to start your own.

Additions to Appendix A, so that the result looks designed (issues 21 and 23):

* a stem must not cross the ornament between the two flowers it joins (the appendix
  tests only the new flower; Wong et al. test intersections before placing, §3.2);
* a second phase (§5's "state preconditions", as the hierarchy pattern) grows buds, small
  flowers of radius 1.2-2 on stems, into the gaps that no full flower fits, above all the
  band along the panel's edge that the flowers leave, about one flower wide;
* a new flower or bud stands at least ``MIN_STEM_SHOWN`` clear of its parent's rim, so
  that a stem shows between them (the appendix lets flowers touch, hiding the stem: the
  child seemed to float);
* the ``ink`` rendering draws a stem only where it shows between the flowers (it runs
  from centre to centre, under them) and a leaf beside its stem, so that no two drawn
  shapes overlap.
"""

from __future__ import annotations

import math

import numpy as np
import shapely

from strew.ornament import (
    FAILURE,
    SUCCESS,
    Bezier,
    Circle,
    Mark,
    Pattern,
    Point,
    Segment,
    angle_of,
    distance,
    offset,
    tapered_stroke,
)

FLOWER_RADIUS = 3.0
MIN_STEM_SHOWN = 0.5  # a stem shows at least this long between two flowers (not in Appendix A)
MAX_STEM = 10.0
LEAF_MIN_STEM = 8.0  # "if the new flower was placed far enough away, add a leaf as well"
LEAF_LENGTH = 3.0
BUD_RADIUS = (1.2, 2.0)  # smaller growth of the second phase (not in Appendix A)
COLORS = ("#c8413b", "#e3a72f", "#4f7cc2")

pattern = Pattern(
    "flowers",
    state={"flowers": 0},
    # a new flower needs an empty circle of about its own diameter next to its parent;
    # then buds fill the gaps down to their smallest radius
    min_radius=BUD_RADIUS[0],
    phases=[("flowers", FLOWER_RADIUS), ("buds", None)],
    description="Appendix A: flowers on stems, a leaf on every stem longer than 8 units.",
    draw_order=["stem", "leaf", "flower", "bud"],
)

pattern.element("seed", Point)
pattern.element("flower", Circle, color=0)  # this element type has a user field
pattern.element("stem", Segment)
pattern.element("leaf", [Bezier, Bezier])
pattern.element("bud", Circle, color=0)  # second phase: a small flower (not in Appendix A)


def _stem_crosses(ctx, a, ra, b, rb):
    """True when the stem from the flower at ``a`` (radius ``ra``) to the one at ``b``
    (radius ``rb``) meets the ornament between the two flowers' rims. Not in Appendix A
    (it tests the new flower only, so stems crossed stems); the part inside the flowers
    is left out, since every stem of a flower starts at its centre."""
    d = distance(a, b)
    gap = 1e-6 * max(1.0, d)
    if d <= ra + rb + 2 * gap:
        return False  # the flowers touch: no stem shows between them
    u = (b - a) / d
    exposed = Segment().set(a + (ra + gap) * u, b - (rb + gap) * u)
    return ctx.intersects(exposed)


@pattern.rule("seed", children=["flower"], phase="flowers")
def seed_to_flower(ctx, seed, flower):
    # The appendix omits this rule's code: a flower on top of the seed, used once.
    flower.proxy.set(seed.proxy.center, FLOWER_RADIUS)
    flower.color = 0
    seed.sterile = True
    if not ctx.inside(flower):
        return FAILURE
    return SUCCESS


@pattern.rule("flower", children=["stem", "flower"], phase="flowers")
def flower_to_flower(ctx, parent, stem, flower):
    to_goal = ctx.goal.center - parent.proxy.center
    # determine how far away to place the child flower.
    dist = min(distance(ctx.goal.center, parent.proxy.center), MAX_STEM)
    # Not in Appendix A: never so near that the flowers hide the stem between them (the
    # new flower would seem to float, issue 23)
    if dist < parent.proxy.radius + FLOWER_RADIUS + MIN_STEM_SHOWN - 1e-9:
        return FAILURE
    # place the flower centred `dist` units away in the direction of the goal, radius 3.
    flower.proxy.set(offset(parent.proxy.center, to_goal, dist), FLOWER_RADIUS)
    # if the new flower intersects any already-placed element, cancel this rule.
    if ctx.intersects(flower):
        return FAILURE
    # Not in Appendix A: nor may its stem cross the ornament.
    if _stem_crosses(ctx, parent.proxy.center, parent.proxy.radius, flower.proxy.center, FLOWER_RADIUS):
        return FAILURE
    flower.color = (parent.color + 1) % len(COLORS)
    # the stem extends from the centre of the parent flower to the centre of the child.
    stem.proxy.set(parent.proxy.center, flower.proxy.center)
    # if the new flower was placed far enough away, add a leaf as well.
    if dist > LEAF_MIN_STEM:
        # the base of the leaf is the stem midpoint. (Appendix A writes
        # `($1.center - $.center) / 2`, half the stem vector; its comment and Fig. 15
        # mean the midpoint, used here.)
        leaf_base = (flower.proxy.center + parent.proxy.center) / 2
        # place the leaf at a right angle to the stem, and make it 3 units long.
        leaf_dir = angle_of(to_goal) + math.pi / 2
        leaf_tip = offset(leaf_base, leaf_dir, LEAF_LENGTH)
        leaf = ctx.new_child("leaf")
        # a leaf is proxied by two Bezier segments, each placed by position, tangent
        # direction and magnitude.
        leaf.proxies[0].set(leaf_base, leaf_dir + math.pi / 4, 0.6, leaf_tip, leaf_dir, 0.4)
        leaf.proxies[1].set(leaf_base, leaf_dir - math.pi / 4, 0.6, leaf_tip, leaf_dir, 0.4)
        # Not in the appendix: a leaf that would overlap the ornament or leave the panel
        # is left out (the flower and stem still grow), so leaves never cover flowers.
        if ctx.intersects(leaf) or not ctx.inside(leaf):
            ctx.dynamic.remove(leaf)
    ctx.state.flowers += 1
    return SUCCESS


@pattern.rule("flower bud", children=["stem", "bud"], phase="buds")
def flower_to_bud(ctx, parent, stem, bud):
    # Not in Appendix A: in the second phase, a bud on a stem grows into the goal circle
    # itself (which the appendix's flowers would overfill), as large as it allows.
    g, rho, rp = ctx.goal.center, ctx.goal.radius, parent.proxy.radius
    d = distance(g, parent.proxy.center)
    # as large as the goal circle allows with a stem of at least MIN_STEM_SHOWN showing:
    # on the line from the parent through the goal's centre, at distance t = rp + r +
    # MIN_STEM_SHOWN (at least d), inside the goal circle (t + r <= d + rho)
    r = min(BUD_RADIUS[1], rho, (d + rho - rp - MIN_STEM_SHOWN) / 2)
    if r < BUD_RADIUS[0] or d > MAX_STEM + rp:
        return FAILURE
    bud.proxy.set(offset(parent.proxy.center, g - parent.proxy.center, max(d, rp + r + MIN_STEM_SHOWN)), r)
    if ctx.intersects(bud) or not ctx.inside(bud):
        return FAILURE
    if _stem_crosses(ctx, parent.proxy.center, rp, bud.proxy.center, r):
        return FAILURE
    stem.proxy.set(parent.proxy.center, bud.proxy.center)
    bud.color = (parent.color + 1) % len(COLORS)
    return SUCCESS


# -- an "ink" rendering (Fig. 15e-g): petals, tapered stems, filled leaves ----------------
# Each stem runs from a flower's centre to its child's, as in Appendix A, under the
# flowers; it is drawn as what shows of it between them (the petals cut away), and a leaf
# as what shows beside its stem, so that no two drawn shapes overlap (issue 23).
def _petals(el):
    """Petal outline of a flower or bud, (n, 2)."""
    c, r = el.proxy.center, el.proxy.radius
    if el.type == "flower":
        t = np.linspace(0, 2 * np.pi, 121)[:-1]
        k, inner = 2.5, 0.72
    else:
        t = np.linspace(0, 2 * np.pi, 73)[:-1]
        k, inner = 1.5, 0.75
    return c + (r * (inner + (1 - inner) * np.abs(np.cos(k * t))))[:, None] * np.c_[np.cos(t), np.sin(t)]


GAP = 1e-6


def _stem_outline(stem, rc):
    pts = np.linspace(stem.proxy.start, stem.proxy.end, 12)
    return tapered_stroke(pts, (2.5 * rc.line_width, 1.2 * rc.line_width))


def _index(rc, types, outline):
    """Polygons that elements of ``types`` draw, and an STRtree over them (once per rendering)."""
    key = f"flowers:{types}"
    if key not in rc.cache:
        polys = [shapely.Polygon(outline(e, rc)) for e in rc.ornament.elements if e.type in types]
        rc.cache[key] = (polys, shapely.STRtree(polys))
    return rc.cache[key]


def _visible(poly, rc, types, outline):
    """``poly`` less what elements of ``types`` draw over it: closed (n, 2) rings."""
    polys, tree = _index(rc, types, outline)
    hits = [polys[i] for i in tree.query(poly, predicate="intersects") if not polys[i].equals(poly)]
    if hits:
        # a hair's gap (1e-6 units), so that the shapes still do not overlap once their
        # coordinates are rounded (SVG keeps 10 significant digits)
        poly = poly.difference(shapely.union_all(hits).buffer(GAP, quad_segs=2))
    return [np.asarray(g.exterior.coords)[:-1] for g in shapely.get_parts(poly) if isinstance(g, shapely.Polygon) and g.area > 0]


@pattern.render("flower", "ink", help="petalled flowers, tapered stems and filled leaves (Fig. 15e-g)")
def ink_flower(flower, rc):
    c, r = flower.proxy.center, flower.proxy.radius
    return [
        Mark([_petals(flower)], closed=True, fill=COLORS[flower.color % len(COLORS)], stroke="#2b2f36", stroke_width=rc.line_width),
        Mark.circle(c, 0.3 * r, fill="#2b2f36", stroke="none"),
    ]


@pattern.render("bud", "ink")
def ink_bud(bud, rc):
    return [Mark([_petals(bud)], closed=True, fill=COLORS[bud.color % len(COLORS)], stroke="#2b2f36", stroke_width=rc.line_width)]


@pattern.render("stem", "ink")
def ink_stem(stem, rc):
    shown = _visible(shapely.Polygon(_stem_outline(stem, rc)), rc, ("flower", "bud"), lambda e, rc: _petals(e))
    return [Mark(shown, closed=True, fill="#3d6b35", stroke="none")] if shown else []


@pattern.render("leaf", "ink")
def ink_leaf(leaf, rc):
    a = leaf.proxies[0].polyline()
    b = leaf.proxies[1].polyline()
    outline = np.vstack([a, b[::-1][1:-1]])
    shown = _visible(shapely.Polygon(outline), rc, ("stem",), _stem_outline)
    return [Mark(shown, closed=True, fill="#5d9b4a", stroke="#2b4d24", stroke_width=0.5 * rc.line_width)] if shown else []
