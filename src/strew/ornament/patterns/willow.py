"""``willow``: curved stems with alternating willow leaves (Wong et al. 1998, §5, Fig. 11).

"There is only one rule, which grows through the empty circle by adding a curved stem
with alternating leaves while preventing the leaves from overlapping too much" (§5,
after a William Morris wallpaper). Here the rule branches from the point of a stem
nearest the empty circle C, bends a cubic Bézier stem through C, and hangs long narrow
leaves on alternating sides of it; a leaf that would overlap the ornament or leave the
panel is left out (the stem itself must not cross anything but its parent). The seed
starts the first stem; a leaf's tip may start one too (not in the paper). This file is a complete rule file: copy it to start your own.
"""

from __future__ import annotations

import math

import numpy as np

from strew.ornament import FAILURE, SUCCESS, Bezier, Mark, Pattern, Point, angle_of, tapered_stroke, unit

MAX_STEM = 28.0  # longest stem
LEAF_LENGTH = (4.0, 7.0)  # willow leaves: long and narrow, shorter on short stems
LEAF_ANGLE = math.radians(35)  # between a leaf and its stem
LEAF_AT = (0.3, 0.5, 0.7, 0.9)  # where leaves hang along the stem, alternating sides

pattern = Pattern(
    "willow",
    state={"stems": 0},
    min_radius=2.5,
    description="Fig. 11: curved stems through the empty circle with alternating willow leaves.",
    draw_order=["stem", "leaf"],
)

pattern.element("seed", Point)
pattern.element("stem", Bezier, depth=0)
pattern.element("leaf", [Bezier, Bezier])


def _turn(a, b):
    d = angle_of(b) - angle_of(a)
    return (d + math.pi) % (2 * math.pi) - math.pi


def grow_stem(ctx, parent, start, tangent, depth):
    """A stem from ``start`` through the goal circle, with its leaves; SUCCESS or FAILURE."""
    g, rho = ctx.goal.center, ctx.goal.radius
    chord = g - start
    d = float(np.hypot(*chord))
    if d < 1e-9:
        return FAILURE
    # the stem ends past C's centre, inside C, and is at most MAX_STEM long
    length = min(d + 0.6 * rho, MAX_STEM)
    end = start + length * unit(chord)
    # leave the parent along its tangent (whichever way bends less), arrive bent
    t_a = tangent if abs(_turn(tangent, chord)) <= abs(_turn(-tangent, chord)) else -tangent
    bend = 1.0 if ctx.rng.random() < 0.5 else -1.0
    c = math.cos(0.35 * bend)
    s = math.sin(0.35 * bend)
    u = unit(chord)
    t_b = np.array([c * u[0] - s * u[1], s * u[0] + c * u[1]])
    stem = ctx.new_child("stem", depth=depth)
    stem.proxy.set_points(start, start + 0.35 * length * t_a, end - 0.35 * length * t_b, end)
    if ctx.intersects(stem, ignore=[parent]) or not ctx.inside(stem):
        ctx.dynamic.remove(stem)
        return FAILURE
    # alternating leaves, each dropped if it would overlap the ornament or leave the panel
    leaf_len = LEAF_LENGTH[0] + (LEAF_LENGTH[1] - LEAF_LENGTH[0]) * min(1.0, length / MAX_STEM)
    side = bend
    for t in LEAF_AT:
        base = stem.proxy.point_at(t)
        along = angle_of(stem.proxy.tangent_at(t))
        a = along + side * LEAF_ANGLE
        side = -side
        tip = base + leaf_len * np.array([math.cos(a), math.sin(a)])
        leaf = ctx.new_child("leaf")
        leaf.proxies[0].set(base, a + math.pi / 9, 0.45 * leaf_len, tip, a - math.pi / 12, 0.3 * leaf_len)
        leaf.proxies[1].set(base, a - math.pi / 9, 0.45 * leaf_len, tip, a + math.pi / 12, 0.3 * leaf_len)
        if ctx.intersects(leaf) or not ctx.inside(leaf):
            ctx.dynamic.remove(leaf)
    ctx.state.stems += 1
    return SUCCESS


@pattern.rule("seed")
def seed_to_stem(ctx, seed):
    start = seed.proxy.center
    if grow_stem(ctx, seed, start, unit(ctx.goal.center - start), 0):
        seed.sterile = True
        return SUCCESS
    return FAILURE


@pattern.rule("stem")
def stem_to_stem(ctx, parent, *_):
    # branch from the point of the parent stem nearest C's centre, beyond its first tenth
    ts = np.linspace(0.1, 1.0, 19)
    pts = parent.proxy.point_at(ts)
    k = int(np.argmin(np.hypot(*(pts - ctx.goal.center).T)))
    return grow_stem(ctx, parent, pts[k], parent.proxy.tangent_at(float(ts[k])), parent.depth + 1)


@pattern.rule("leaf")
def leaf_to_stem(ctx, parent, *_):
    # Not in the paper's one rule: the ornament's rim is mostly leaves, and C's nearest
    # elements are tried first, so a stem also sprouts from a leaf's tip (else growth
    # stops at the first ring of leaves)
    tip = parent.proxies[0].point_at(1.0)
    return grow_stem(ctx, parent, tip, parent.proxies[0].tangent_at(1.0), 1)


@pattern.render("stem", "morris", help="olive stems and filled willow leaves, after the Morris wallpaper (Fig. 11)")
def morris_stem(stem, rc):
    w = max(1.2 * rc.line_width, 2.2 * rc.line_width * 0.85**stem.depth)
    return [Mark.polygon(tapered_stroke(stem.proxy.polyline(20), (w, 0.5 * w)), fill="#4a5a2a")]


@pattern.render("leaf", "morris")
def morris_leaf(leaf, rc):
    a = leaf.proxies[0].polyline()
    b = leaf.proxies[1].polyline()
    outline = np.vstack([a, b[::-1][1:-1]])
    return [Mark.polygon(outline, fill="#7f9a52", stroke="#3d4d22", stroke_width=0.5 * rc.line_width)]
