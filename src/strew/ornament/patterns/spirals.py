"""``spirals``: equal-angle spiral vines (Wong et al. 1998, §5, Fig. 12 "bamboo spirals").

Each spiral is an equal-angle (logarithmic) spiral [Cook 1914] scaled to the goal
circle: it winds inwards from 0.8 of the circle's radius about the circle's centre. It is
drawn with several cubic Bézier segments, created as dynamic children, because spirals
of different sizes need different numbers of segments to stay smooth; a first segment
joins it tangentially to its parent. Each spiral turns the opposite way to its parent
(§5: "Each spiral curve is given an orientation opposite to that of its parent").
This file is a complete rule file: copy it to start your own.

Drawing (not in the paper's text): the segments of one spiral are one element of the
output, of kind ``spiral`` (``pattern.group``), and the ``vine`` and ``filigree`` styles
draw each spiral as one outline, so that no seam shows at the segments' joins.
"""

from __future__ import annotations

import math

import numpy as np

from strew.ornament import FAILURE, SUCCESS, Bezier, Mark, Pattern, Point, angle_of, tapered_stroke, unit

PITCH = 0.22  # r(theta) = R0 exp(-PITCH theta): the spiral's constant angle is atan(1 / PITCH)
PIECE = math.pi / 2  # at most a quarter turn per Bezier segment
FILL = (0.8, 0.55)  # outer radius of a spiral as a fraction of the goal radius, tried in order

pattern = Pattern(
    "spirals",
    state={"spirals": 0},
    min_radius=2.0,
    description="Fig. 12: equal-angle spiral vines of Bezier segments, alternating orientation.",
)

pattern.element("seed", Point)
# one Bezier segment of a spiral; `segment` counts from the junction, `segments` is the total
pattern.element("arm", Bezier, orientation=1, spiral=0, segment=0, segments=1, scale=1.0)
# the arms of one spiral are drawn as one element, of kind "spiral"
pattern.group("arm", "spiral", "spiral")


def spiral_controls(center, r0, phi0, turn, r_end):
    """Control points (m, 4, 2) of Bezier pieces approximating an inward equal-angle spiral."""
    total = math.log(r0 / r_end) / PITCH
    m = max(1, math.ceil(total / PIECE))
    thetas = np.linspace(0.0, total, m + 1)

    def point(t):
        r = r0 * math.exp(-PITCH * t)
        phi = phi0 + turn * t
        return center + r * np.array([math.cos(phi), math.sin(phi)])

    def deriv(t):
        r = r0 * math.exp(-PITCH * t)
        phi = phi0 + turn * t
        return r * (-PITCH * np.array([math.cos(phi), math.sin(phi)]) + turn * np.array([-math.sin(phi), math.cos(phi)]))

    pieces = []
    for a, b in zip(thetas[:-1], thetas[1:]):
        d = (b - a) / 3
        pieces.append([point(a), point(a) + d * deriv(a), point(b) - d * deriv(b), point(b)])
    return np.array(pieces)


def _turning(u, v):
    a = angle_of(v) - angle_of(u)
    return abs((a + math.pi) % (2 * math.pi) - math.pi)


def grow_spiral(ctx, parent, start, tangent, turn):
    """Try to grow one spiral from ``start`` (heading along +-``tangent``) into the goal."""
    g, rho = ctx.goal.center, ctx.goal.radius
    for frac in FILL:
        r0 = frac * rho
        r_end = max(0.15 * r0, 0.4)
        if r0 <= r_end:
            return FAILURE
        # choose where the spiral starts on its outer circle, and which way the junction
        # leaves the parent, so that the joining segment bends least
        best = None
        for phi0 in np.linspace(0, 2 * math.pi, 16, endpoint=False):
            radial = np.array([math.cos(phi0), math.sin(phi0)])
            s = g + r0 * radial
            t_s = unit(-PITCH * radial + turn * np.array([-radial[1], radial[0]]))  # spiral tangent at its start
            chord = s - start
            if np.hypot(*chord) < 1e-9:
                continue
            for sign in (1.0, -1.0):
                t_a = sign * tangent
                score = _turning(t_a, chord) + _turning(chord, t_s)
                if best is None or score < best[0]:
                    best = (score, phi0, t_a)
        if best is None:
            return FAILURE
        _, phi0, t_a = best
        pieces = spiral_controls(g, r0, phi0, turn, r_end)
        s = pieces[0, 0]
        length = float(np.hypot(*(s - start)))
        t_s = unit(pieces[0, 1] - pieces[0, 0])
        joint = np.array([start, start + 0.4 * length * t_a, s - 0.4 * length * t_s, s])
        arms = []
        for k, ctrl in enumerate([joint, *pieces]):
            arm = ctx.new_child("arm", orientation=turn, spiral=ctx.state.spirals, segment=k, segments=len(pieces) + 1, scale=r0)
            arm.proxy.set_points(*ctrl)
            arms.append(arm)
        if ctx.intersects(arms, ignore=[parent]) or not ctx.inside(arms):
            for arm in arms:
                ctx.dynamic.remove(arm)
            continue
        ctx.state.spirals += 1
        return SUCCESS
    return FAILURE


@pattern.rule("seed")
def seed_to_spiral(ctx, seed):
    start = seed.proxy.center
    if grow_spiral(ctx, seed, start, unit(ctx.goal.center - start), 1):
        seed.sterile = True
        return SUCCESS
    return FAILURE


@pattern.rule("arm")
def arm_to_spiral(ctx, parent, *_):
    # branch from the point of the parent segment nearest the goal circle's centre
    ts = np.linspace(0.0, 1.0, 25)
    pts = parent.proxy.point_at(ts)
    k = int(np.argmin(np.hypot(*(pts - ctx.goal.center).T)))
    return grow_spiral(ctx, parent, pts[k], parent.proxy.tangent_at(ts[k]), -parent.orientation)


def _full_width(arm, rc):
    return min(6 * rc.line_width, max(1.5 * rc.line_width, 0.12 * arm.scale))


def _width_at_branch(arms, rc):
    """Width of the parent spiral where ``arms`` branch off it (None from a seed)."""
    parent = arms[0].parent
    if parent is None or parent.type != "arm":
        return None
    ts = np.linspace(0.0, 1.0, 25)  # where arm_to_spiral looks for the branch point
    k = int(np.argmin(np.hypot(*(parent.proxy.point_at(ts) - arms[0].proxy.points[0]).T)))
    return _full_width(parent, rc) * (1 - 0.85 * (parent.segment + ts[k]) / parent.segments)


def _spiral_outline(arm, rc, reverse):
    """The whole spiral of ``arm`` as one filled outline, thinning from its junction to its
    eye (or the reverse): drawn once, by the spiral's first arm, so that no seam shows
    where two segments' outlines would meet (issue 23). A spiral starts no wider than its
    parent where it branches off, with a round end."""
    arms = sorted(rc.group(arm), key=lambda a: a.segment)
    if arm is not arms[0]:
        return []
    pts, ts = [], []
    for a in arms:
        p = a.proxy.polyline(24)
        k = 0 if not pts else 1  # each segment starts where the last one ended
        pts.append(p[k:])
        # the width falls by segment, as Wong et al. split the spiral (§5), linearly in arc
        # length within each segment
        seg = np.hypot(*np.diff(p, axis=0).T)
        u = np.r_[0.0, np.cumsum(seg)] / max(seg.sum(), 1e-12)
        ts.append(((a.segment + u) / a.segments)[k:])
    pts, t = np.vstack(pts), np.concatenate(ts)
    w = _full_width(arm, rc)
    if reverse:
        t = 1 - t
    else:
        branch = _width_at_branch(arms, rc)
        if branch is not None:
            w = min(w, branch)
    width = w * (1 - 0.85 * t)
    outline = tapered_stroke(pts, width)
    # a round start: half a circle from the right side, behind the start, to the left
    left, right = outline[0], outline[-1]
    across = (left - right) / max(np.hypot(*(left - right)), 1e-12)
    back = -unit(pts[1] - pts[0])
    th = np.linspace(0.0, math.pi, 13)[1:-1]
    cap = pts[0] + (width[0] / 2) * (np.cos(th)[:, None] * -across + np.sin(th)[:, None] * back)
    return [np.vstack([outline, cap])]


@pattern.render("arm", "vine", help="each spiral one stroke thinning from its junction to its eye (Fig. 12)")
def vine_arm(arm, rc):
    return [Mark.polygon(p, fill="#2f5d3a") for p in _spiral_outline(arm, rc, False)]


@pattern.render("arm", "filigree", help="each spiral thickening towards its eye, the reversed variation of Fig. 13")
def filigree_arm(arm, rc):
    return [Mark.polygon(p, fill="#6b3d2f") for p in _spiral_outline(arm, rc, True)]
