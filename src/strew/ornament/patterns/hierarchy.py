"""``hierarchy``: phased growth of vines, then flowers, then leaves, then fillers (Wong et al. 1998, §5, Fig. 10).

"The pattern starts from the seed points by growing the vines. It then adds the red
flowers and the yellow and blue shapes, connecting them to the main vine structure with
shorter subsidiary vines. Next, leaves are added, either attached to a vine or floating
on their own, and finally the small double-quote-shaped structure is used to fill in
small gaps. This ordering of rule phases is imposed on the system by adding 'state'
preconditions to each rule." Here each rule names its phase; a phase ends when no empty
circle as large as its threshold remains, and the next begins. This file is a complete
rule file: copy it to start your own.

Additions to the paper (issue 23): where two fronts of the vine structure meet head on
(the two ends of a ring of vines around a panel's hole), a vine joins their tips, so that
the main vine closes; and a vine is drawn as wide as its depth along the structure says
(each vine starts at its parent's depth where it branches off), so that the width runs
on without a step at the joints.
"""

from __future__ import annotations

import math

import numpy as np

from strew.ornament import (
    FAILURE,
    SUCCESS,
    Bezier,
    Circle,
    Mark,
    Pattern,
    Point,
    Polygon,
    angle_of,
    distance,
    offset,
    tapered_stroke,
    unit,
)

COLORS = ("#c0392b", "#e0b030", "#3e6fb0")
TIP = 0.75  # a vine's last quarter is its tip, where two fronts may be joined
HEAD_ON = math.cos(math.pi / 4)  # red flowers, yellow and blue shapes

pattern = Pattern(
    "hierarchy",
    state={"vines": 0},
    # (phase, the empty-circle radius at which it hands over to the next)
    phases=[("vines", 8.0), ("flowers", 5.0), ("leaves", 2.5), ("fillers", None)],
    min_radius=1.5,
    description="Fig. 10: vines, then flowers on subsidiary vines, then leaves, then small fillers.",
    draw_order=["vine", "twig", "leaf", "flower", "quote"],
)

# a tiled world (strew.tiles) keeps each tile's vines (the first phase) up to half a halo
# past its border, with the halo's edges towards later tiles open, so that the vine
# structure near a border is one run's, grown before any flower (strew.tiles
# ._first_phase_rows; not in the paper, which grows one panel in one run)
pattern.tile_keeps_first_phase = True

pattern.element("seed", Point)
# s0, s1: the vine's depth along the vine structure at its two ends (a child starts at its
# parent's depth where it branches off), which sets its width when drawn, so that the
# width runs on without a step at every joint
# joined, target: see vine_joins_vine
pattern.element("vine", Bezier, orientation=1, s0=0.0, s1=1.0, joined=False, target=-1)
pattern.element("twig", Bezier)  # a shorter subsidiary vine carrying a flower
pattern.element("flower", Circle, color=0)
# two Bezier edges, and their outline as a polygon so that the inside counts as filled
# (with the edges alone, fillers would grow inside leaves)
pattern.element("leaf", [Bezier, Bezier, Polygon])
pattern.element("quote", [Circle, Bezier, Circle, Bezier])  # a double-quote-shaped filler


def nearest_on(curve, point, n=25):
    """Parameter of the point of a curve nearest ``point`` (sampled at n values)."""
    ts = np.linspace(0.0, 1.0, n)
    pts = curve.point_at(ts)
    return float(ts[int(np.argmin(np.hypot(*(pts - point).T)))])


def attachment(ctx, parent, with_t=False):
    """Point of a curve parent nearest the goal centre, and the tangent there (and its
    parameter, with ``with_t``)."""
    u = nearest_on(parent.proxy, ctx.goal.center)
    p = parent.proxy.point_at(u)
    t = parent.proxy.tangent_at(u)
    if np.dot(t, ctx.goal.center - p) < 0:
        t = -t
    return (p, t, u) if with_t else (p, t)


def depth_at(vine, u):
    """Depth along the vine structure at parameter u of a vine."""
    return vine.s0 + u * (vine.s1 - vine.s0)


def fits(ctx, children, parent=None):
    return not ctx.intersects(children, ignore=[parent] if parent is not None else []) and ctx.inside(children)


# -- phase 1: vines ------------------------------------------------------------------------
def grow_vine(ctx, parent, vine, start, heading, turn):
    g, rho = ctx.goal.center, ctx.goal.radius
    d = distance(g, start)
    # towards the goal centre, bending to the side `turn`; shorter and then bending the
    # other way if that does not fit
    for short, bend in ((0.25, turn), (0.25, -turn), (0.6, turn), (0.6, -turn)):
        # the vine ends short of the goal's centre by `short` of its radius: (1 - short)
        # rho from its start, the start lying on the circle's rim. Not so where a tiled
        # world's later tile raised the goal to the circle its finished neighbour grew
        # into there (strew.ornament._engine._handed_over; the start then lies inside
        # the raised circle, d < rho): measured back from the centre by the raised
        # radius, the vine came out shorter than in the narrow circle itself (and with
        # rho > 4 d pointed backwards), not longer as the hand-over means (issue 19.4;
        # 60 x 60 panel, every vines-phase goal raised to 20: vines 21 -> 27, mean
        # chord 8.96 -> 6.89). It is measured from its start instead, as long as the
        # raised circle's vine would be.
        end = offset(start, g - start, (1.0 - short) * rho) if rho > d else offset(g, g - start, -short * rho)
        vine.proxy.set(start, angle_of(heading), 0.45, end, angle_of(end - start) + bend * 0.7, 0.35)
        vine.orientation = bend
        if fits(ctx, vine, parent):
            return True
    return False


# the seed starts a vine in whatever phase its turn comes (a seed whose first vine did
# not fit early on may still start one later)
@pattern.rule("seed", children=["vine"])
def seed_to_vine(ctx, seed, vine):
    start = seed.proxy.center
    if not grow_vine(ctx, seed, vine, start, ctx.goal.center - start, 1):
        return FAILURE
    seed.sterile = True
    return SUCCESS


def _tree_distance(a, b, limit=6):
    """Number of parent links between two elements, or ``limit`` when more."""
    up = {}
    e, k = a, 0
    while e is not None and k < limit:
        up[e.index] = k
        e, k = e.parent, k + 1
    e, k = b, 0
    while e is not None and k < limit:
        if e.index in up:
            return min(limit, up[e.index] + k)
        e, k = e.parent, k + 1
    return limit


# Not in the paper: where two fronts of the vine structure meet across a gap (the two ends
# of a ring of vines growing around a panel's hole), a vine joins their tips, so that the
# main vine closes instead of stopping short (issue 23). It is tried before a vine grows
# on, and in the flowers phase too: the gap the fronts leave is often narrower than the
# vines phase's threshold.
@pattern.rule("vine", children=["vine"], when=lambda state: state.phase in ("vines", "flowers"))
def vine_joins_vine(ctx, parent, vine):
    g, rho = ctx.goal.center, ctx.goal.radius
    start, heading, u = attachment(ctx, parent, with_t=True)
    if u < TIP or parent.joined:
        return FAILURE
    for other in ctx.elements:
        if other.type != "vine" or other is parent or other.joined or _tree_distance(parent, other) < 4:
            continue
        w = nearest_on(other.proxy, g)
        if w < TIP or any(c.type == "vine" and c.s0 >= depth_at(other, TIP) for c in other.children):
            continue  # not a free tip: a vine grows on from there
        end = other.proxy.point_at(w)
        if distance(end, g) > 1.5 * rho or distance(end, start) > 4 * rho:
            continue
        # only tips that grow towards each other, head on (within 45 degrees): fronts
        # meeting, not a vine running into the side of the structure
        chord = unit(end - start)
        if np.dot(parent.proxy.tangent_at(u), chord) < HEAD_ON or np.dot(other.proxy.tangent_at(w), -chord) < HEAD_ON:
            continue
        arrive = -other.proxy.tangent_at(w)
        vine.proxy.set(start, angle_of(heading), 0.4, end, angle_of(arrive), 0.4)
        if not ctx.intersects(vine, ignore=[parent, other]) and ctx.inside(vine):
            vine.s0, vine.s1 = depth_at(parent, u), depth_at(other, w)
            vine.orientation = -parent.orientation
            parent.joined = other.joined = vine.joined = True  # these tips are taken
            vine.target = other.index
            ctx.state.vines += 1
            return SUCCESS
    return FAILURE


@pattern.rule("vine", children=["vine"], phase="vines")
def vine_to_vine(ctx, parent, vine):
    start, heading, u = attachment(ctx, parent, with_t=True)
    if not grow_vine(ctx, parent, vine, start, heading, -parent.orientation):
        return FAILURE
    vine.s0 = depth_at(parent, u)
    vine.s1 = vine.s0 + 1.0
    ctx.state.vines += 1
    return SUCCESS


# -- phase 2: flowers on subsidiary vines ---------------------------------------------------
@pattern.rule("vine twig", children=["twig", "flower"], phase="flowers")
def flower_on_twig(ctx, parent, twig, flower):
    g, rho = ctx.goal.center, ctx.goal.radius
    start, heading = attachment(ctx, parent)
    radius = min(6.0, 0.6 * rho)
    flower.proxy.set(g, radius)
    flower.color = int(ctx.rng.integers(len(COLORS)))
    rim = offset(g, start - g, radius)
    twig.proxy.set(start, angle_of(heading), 0.4, rim, angle_of(g - rim), 0.3)
    return SUCCESS if fits(ctx, [twig, flower], parent) else FAILURE


# -- phase 3: leaves, attached or floating ----------------------------------------------------
def set_leaf(leaf, base, tip, spread=math.pi / 5):
    d = angle_of(tip - base)
    leaf.proxies[0].set(base, d + spread, 0.6, tip, d, 0.4)
    leaf.proxies[1].set(base, d - spread, 0.6, tip, d, 0.4)
    a, b = leaf.proxies[0].polyline(12), leaf.proxies[1].polyline(12)
    leaf.proxies[2].set(np.vstack([a, b[::-1][1:-1]]))


@pattern.rule("vine twig", children=["leaf"], phase="leaves")
def attached_leaf(ctx, parent, leaf):
    start, _ = attachment(ctx, parent)
    tip = offset(start, ctx.goal.center - start, min(1.6 * ctx.goal.radius, 9.0))
    set_leaf(leaf, start, tip)
    return SUCCESS if fits(ctx, leaf, parent) else FAILURE


@pattern.rule("flower leaf", children=["leaf"], phase="leaves")
def floating_leaf(ctx, parent, leaf):
    g, rho = ctx.goal.center, ctx.goal.radius
    across = unit(g - parent.proxy.bounding_circle()[:2])
    axis = np.array([-across[1], across[0]])
    set_leaf(leaf, g - 0.8 * rho * axis, g + 0.8 * rho * axis)
    return SUCCESS if fits(ctx, leaf) else FAILURE


# -- phase 4: small double-quote fillers ---------------------------------------------------------
@pattern.rule("vine twig flower leaf quote", children=["quote"], phase="fillers")
def quote_filler(ctx, parent, quote):
    g, rho = ctx.goal.center, ctx.goal.radius
    size = 0.9 * min(rho, 2.5)
    down = unit(g - parent.proxy.bounding_circle()[:2])
    side = np.array([-down[1], down[0]])
    head = 0.28 * size
    for k, s in enumerate((-1.0, 1.0)):
        c = g + s * 0.38 * size * side - 0.3 * size * down
        quote.proxies[2 * k].set(c, head)
        p0 = c + head * down
        quote.proxies[2 * k + 1].set(p0, angle_of(down), 0.5, p0 + 0.55 * size * down - 0.2 * size * side, angle_of(down) + 0.9, 0.4)
    return SUCCESS if fits(ctx, quote) else FAILURE


# -- a coloured rendering ---------------------------------------------------------------------------
def vine_width(s, rc):
    """Width of a vine at depth s along the vine structure: thinning slowly from the seed."""
    return rc.line_width * np.maximum(1.5, 4.0 * 0.92 ** np.asarray(s, dtype=float))


@pattern.render("vine", "color", help="tapered green vines, coloured flowers, filled leaves and fillers (Fig. 10)")
def color_vine(vine, rc):
    # the width follows the depth along the structure, so that a vine starts as wide as
    # its parent where it branches off (no step at the joints); each end is drawn round,
    # so that the joints overlap smoothly
    u = np.linspace(0.0, 1.0, 25)  # the curve's own parameter, as depth_at uses it
    pts = vine.proxy.point_at(u)
    w = vine_width(depth_at(vine, u), rc)
    body = tapered_stroke(pts, w)
    caps = [Mark.circle(pts[k], w[k] / 2, segments=24, fill="#2f5d3a", stroke="none") for k in (0, -1)]
    return [Mark.polygon(body, fill="#2f5d3a"), *caps]


@pattern.render("twig", "color")
def color_twig(twig, rc):
    return [Mark.polygon(tapered_stroke(twig.proxy.polyline(16), (1.8 * rc.line_width, 1.0 * rc.line_width)), fill="#3f7a4a")]


@pattern.render("flower", "color")
def color_flower(flower, rc):
    c, r = flower.proxy.center, flower.proxy.radius
    t = np.linspace(0, 2 * np.pi, 97)[:-1]
    n = (6, 3, 4)[flower.color % 3]
    outline = c + (r * (0.7 + 0.3 * np.abs(np.cos(n / 2 * t))))[:, None] * np.c_[np.cos(t), np.sin(t)]
    return [
        Mark([outline], closed=True, fill=COLORS[flower.color % 3], stroke="#2b2f36", stroke_width=rc.line_width),
        Mark.circle(c, 0.25 * r, fill="#2b2f36", stroke="none"),
    ]


@pattern.render("leaf", "color")
def color_leaf(leaf, rc):
    a, b = leaf.proxies[0].polyline(), leaf.proxies[1].polyline()
    return [Mark.polygon(np.vstack([a, b[::-1][1:-1]]), fill="#6aa84f", stroke="#2b4d24", stroke_width=0.5 * rc.line_width)]


@pattern.render("quote", "color")
def color_quote(quote, rc):
    marks = []
    for k in (0, 2):
        head, tail = quote.proxies[k], quote.proxies[k + 1]
        marks.append(Mark.circle(head.center, head.radius, fill="#7a4b2a", stroke="none"))
        marks.append(Mark.polygon(tapered_stroke(tail.polyline(12), (1.4 * head.radius, 0.1 * head.radius)), fill="#7a4b2a"))
    return marks
