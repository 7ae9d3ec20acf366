"""Flow mode: an element put where the bent lattice is stretched, so that the stretch
becomes a dislocation (issue 14 point 2).

Not in the paper. Where growth runs away from the centre of curvature of the field's
rows (§5.3) the rows fan out, and where the growth front was not a straight row
(:meth:`strew.grow._growth._Grower.flow_respace` finds no run of seeds to respace:
from the 90 degree field's corner, 115 of 163 long front gaps had no seed beyond
either end) the lattice stays whole but stretched: chains of bonds of 1.15-1.3 mean
edges (``benchmarks/grow.py --structure --flow-only``: ``ns_stretch``), where no
element fits into any one gap. After the growth and its last relaxation, at the middle
of each bond longer than ``flow_stretch_min`` mean edges (longest first; not within
``flow_stretch_edge`` edges of the region's edge, where no lattice beyond takes the
stretch; not within ``flow_stretch_gap`` edges of an element put before), an element
is put as :func:`strew.grow._flow_holes.close_holes` puts one into a hole: a free object
there pushes the elements within ``flow_stretch_ring`` edges out to one mean edge (those
already farther keep their distance), and the window of ``flow_stretch_window`` edges
is relaxed (Eq. 5, §5.5), except that each stretched pair of it (over
``flow_stretch_taut`` edges) wants one mean edge in its present direction instead of
its present offset: the stretch around gives the room, and the window's stretched
bonds come back to about one edge (a window of 4 edges: quarter circles from the
corner 0.834 of the interior with six neighbours; 8 edges: 0.880; 550ea99: 0.806).
Where the fit leaves the centre
less than ``flow_stretch_room`` edges free, nothing is moved or tested. As there, it is
all or nothing: the moved outlines stay inside the region and off each other, and the
element is matched (§5.2) and placed (§5.4) as any seed, or all of it is undone.

Departs from §5.2-5.5 as ``close_holes`` does (a pass after the growth; elements moved
by it may turn by up to ``flow_hole_turn``); and from Eq. 5, whose terms keep the
matched ring offsets, here the present offsets, shortened where stretched.
"""

from __future__ import annotations

import math

import numpy as np

from ._flow_gaps import _bonds
from ._flow_holes import _fill
from ._flow_kernels import boundary_distance
from ._objects import ELEMENT

__all__ = ["insert_stretched"]


def insert_stretched(g, limit: int | None = None) -> int:
    """Elements put at the middles of bonds longer than ``flow_stretch_min`` mean edges
    (longest first, none within ``flow_stretch_gap`` mean edges of one put before);
    how many."""
    p = g.p
    L = g.l
    bonds = _bonds(g)
    if bonds is None:
        return 0
    els, pts, e = bonds
    ln = np.hypot(*(pts[e[:, 0]] - pts[e[:, 1]]).T)
    sel = np.flatnonzero((ln > p.flow_stretch_min * L) & (ln < 1.6 * L))
    if g.region is not None and len(sel):
        # (a bond along the region's edge has no lattice beyond it to take the stretch)
        mid = 0.5 * (pts[e[sel, 0]] + pts[e[sel, 1]])
        sel = sel[boundary_distance(g.region, mid) > p.flow_stretch_edge * L]
    sel = sel[np.argsort(-ln[sel], kind="stable")]
    made = failed = 0
    done: list[tuple[float, float]] = []
    for q in sel.tolist():
        if limit is not None and len(g.order) >= limit:
            break
        a, b = int(els[e[q, 0]]), int(els[e[q, 1]])
        if g.state[a] != ELEMENT or g.state[b] != ELEMENT:
            continue
        (ax, ay), (bx, by) = g.xy[a], g.xy[b]
        if math.hypot(bx - ax, by - ay) <= p.flow_stretch_min * L:
            continue  # an earlier insertion moved them
        cx, cy = 0.5 * (ax + bx), 0.5 * (ay + by)
        if any((cx - x) ** 2 + (cy - y) ** 2 < (p.flow_stretch_gap * L) ** 2 for x, y in done):
            continue
        if not g.in_domain(cx, cy) or g.near(cx, cy, 0.5 * L, (ELEMENT,)):
            continue
        ring = sorted(o for o in g.near(cx, cy, p.flow_stretch_ring * L, (ELEMENT,)) if g.orig_of[o] == o)
        if len(ring) < 4:
            continue
        if g.boundary is not None and any(g.crosses_boundary((cx, cy), g.xy[o]) for o in ring):
            continue
        if _fill(g, cx, cy, ring, taut=p.flow_stretch_taut, win=p.flow_stretch_window, room=p.flow_stretch_room,
                 turn=p.flow_stretch_turn, max_hits=p.flow_stretch_hits):
            made += 1
            done.append((cx, cy))
            failed = 0
        else:
            # (the longest bonds come first, and an element that goes in mostly goes in
            # among them: after this many tries in a row without one, the pass stops)
            failed += 1
            if failed >= p.flow_stretch_tries:
                break
    return made
