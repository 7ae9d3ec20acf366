"""An example rule file for ``strew ornament``: berries on curling stalks.

Run it with::

    strew ornament examples/ornament/berries.py --region examples/ornament/shield.svg \\
        --style tapered --seed-point 60,20 -o berries.svg

A rule file is plain Python: it assigns ``pattern = Pattern(...)``, declares element
types with their proxies (``seed`` is required and has a Point proxy), and decorates
growth rules. A rule receives ``ctx`` (``ctx.goal`` is the empty circle C to grow into),
its parent element and fresh static children, sets the children's proxies, and returns
SUCCESS or FAILURE. Rules are tried in the order they are written.
"""

from __future__ import annotations

import numpy as np

from strew.ornament import FAILURE, SUCCESS, Bezier, Circle, Mark, Pattern, Point, angle_of, offset, unit

pattern = Pattern("berries", min_radius=2.0, description="Berries on curling stalks.", draw_order=["stalk", "berry"])

pattern.element("seed", Point)
pattern.element("stalk", Bezier, turn=1)  # a user field: which way the stalk curls
pattern.element("berry", Circle)


def attachment(parent, goal_center):
    """The point of the parent nearest the goal centre."""
    if parent.type == "berry":
        c, r = parent.proxy.center, parent.proxy.radius
        return offset(c, goal_center - c, r)
    if parent.type == "seed":
        return parent.proxy.center
    pts = parent.proxy.polyline(24)
    return pts[np.argmin(np.hypot(*(pts - goal_center).T))]


@pattern.rule("seed stalk berry", children=["stalk", "berry"])
def stalk_and_berry(ctx, parent, stalk, berry):
    goal = ctx.goal
    start = attachment(parent, goal.center)
    # a berry scaled to the empty circle, at its centre
    radius = min(2.5, 0.6 * goal.radius)
    berry.proxy.set(goal.center, radius)
    rim = offset(goal.center, start - goal.center, radius)
    # the stalk curls to alternate sides along a branch
    stalk.turn = -getattr(parent, "turn", 1)
    stalk.proxy.set(start, angle_of(rim - start) + 0.6 * stalk.turn, 0.4, rim, angle_of(goal.center - rim), 0.3)
    # the new elements may touch their parent, nothing else
    if ctx.intersects([stalk, berry], ignore=[parent]) or not ctx.inside([stalk, berry]):
        return FAILURE
    if parent.type == "seed":
        parent.sterile = True
    return SUCCESS


@pattern.render("berry", "tapered", help="filled berries with a highlight, tapered stalks")
def shiny_berry(berry, rc):
    c, r = berry.proxy.center, berry.proxy.radius
    return [
        Mark.circle(c, r, fill="#7b2d4f", stroke="none"),
        Mark.circle(c + 0.35 * r * unit((-1.0, -1.0)), 0.25 * r, fill="#f3d9e4", stroke="none"),
    ]
