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
SHRINK_STEPS = 12  # bisection steps of a dot that does not fit (dot_to_dot)

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
        # Not in Appendix A either: the dot shrinks to the largest that fits (as the seed
        # rule's dot does above) instead of failing. Appendix A's dot fills its goal
        # circle (r = min(3, $goal.radius), tangent to the parent), which is the room only
        # while the goal is the empty circle itself. In a tiled world a later tile raises
        # a goal to the circle its finished neighbour grew into there
        # (strew.ornament._engine._handed_over, issue 19.4), and a dot that large failed
        # in 175 of 184 raised tries (radius 1.34 -> 2.83): the circles were left empty
        # and the border strips thinned (+-1 s / +-2 s density 0.823 / 0.871 on 3 worlds;
        # benchmarks/dot19r_handover.py, orn19m_willow.py). The dots tangent to the parent
        # at one point along one direction are nested as r grows, so whether one fits is
        # monotone in r and the bisection finds the largest (to r / 2**12).
        lo, hi = 0.0, r
        for _ in range(SHRINK_STEPS):
            m = 0.5 * (lo + hi)
            dot.proxy.set(offset(p.center, ctx.goal.center - p.center, p.radius + m), m)
            if ctx.intersects(dot) or not ctx.inside(dot):
                hi = m
            else:
                lo = m
        if lo < 0.5:  # as small as the tiny empty spaces ignored above
            return FAILURE
        dot.proxy.set(offset(p.center, ctx.goal.center - p.center, p.radius + lo), lo)
    dot.order = ctx.state.dot_count
    ctx.state.dot_count += 1
    return SUCCESS


@pattern.render("dot", "order", help="dots coloured by placement order, oldest red to newest purple (Fig. 14)")
def dot_by_order(dot, rc):
    hue = 0.8 * dot.order / max(1, rc.count("dot") - 1)
    r, g, b = colorsys.hsv_to_rgb(hue, 0.75, 0.92)
    color = f"#{int(r * 255):02x}{int(g * 255):02x}{int(b * 255):02x}"
    return [Mark.circle(dot.proxy.center, dot.proxy.radius, fill=color, stroke="none")]
