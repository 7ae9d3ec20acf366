"""``dots``: a cluster of circular dots (Wong et al. 1998, Appendix A, Fig. 14).

The first dot is centred on the seed point; every later dot is placed adjacent to an
existing dot, in the direction of the goal circle, with radius at most 3 units. This
file is a complete rule file: copy it to start your own.

Paper (Appendix A)::

    %rule  seed --> dot  { $0.set($, 3.0); $$0.order = dot_count++; $$0.sterile = 1; }
    %rule  dot --> dot   { if ($goal.radius < 0.5) return FAILURE;
                           double r = min(3.0, $goal.radius);
                           $0.set($.center.offset($goal.center - $.center, $.radius + r), r); ... }
"""

from __future__ import annotations

import colorsys

from strew.ornament import FAILURE, SUCCESS, Circle, Mark, Pattern, Point, offset

MAX_RADIUS = 3.0  # "Dots may be at most 3 units in radius."

pattern = Pattern(
    "dots",
    state={"dot_count": 0},  # %source: int dot_count = 0;
    min_radius=1.0,
    description="Appendix A: dots of radius <= 3 grown into the largest empty circle.",
)

pattern.element("seed", Point)  # the seed element is required
pattern.element("dot", Circle, order=0)  # number each dot in order of placement


@pattern.rule("seed", children=["dot"])
def seed_to_dot(ctx, seed, dot):
    # place a maximum-sized dot on the initial seed. (Appendix A uses 3.0 as is; here the
    # dot also shrinks to fit near the boundary or near dots grown from another seed.)
    r = min(MAX_RADIUS, ctx.clearance(seed.proxy.center, ignore=[seed]))
    if r < 0.5:
        return FAILURE
    dot.proxy.set(seed.proxy.center, r)
    dot.order = ctx.state.dot_count
    ctx.state.dot_count += 1
    # prevent the seed from being used again
    seed.sterile = True
    return SUCCESS


@pattern.rule("dot", children=["dot"])
def dot_to_dot(ctx, parent, dot):
    # ignore tiny empty spaces.
    if ctx.goal.radius < 0.5:
        return FAILURE
    # determine the radius of the new dot.
    r = min(MAX_RADIUS, ctx.goal.radius)
    # place the new dot adjacent to the parent dot.
    p = parent.proxy
    dot.proxy.set(offset(p.center, ctx.goal.center - p.center, p.radius + r), r)
    # Not in Appendix A's rule: it relies on C touching the parent; with C's neighbours
    # up to delta away the dot could overlap another, so check (the paper's flower rule
    # does the same with `intersection($$1)`).
    if ctx.intersects(dot) or not ctx.inside(dot):
        return FAILURE
    dot.order = ctx.state.dot_count
    ctx.state.dot_count += 1
    return SUCCESS


@pattern.render("dot", "order", help="dots coloured by placement order, oldest red to newest purple (Fig. 14)")
def dot_by_order(dot, rc):
    hue = 0.8 * dot.order / max(1, rc.count("dot") - 1)
    r, g, b = colorsys.hsv_to_rgb(hue, 0.75, 0.92)
    color = f"#{int(r * 255):02x}{int(g * 255):02x}{int(b * 255):02x}"
    return [Mark.circle(dot.proxy.center, dot.proxy.radius, fill=color, stroke="none")]
