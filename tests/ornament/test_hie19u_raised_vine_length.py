"""A vine grown into a raised goal is as long as the raised circle's vine (issue 19 point
4; strew.ornament.patterns.hierarchy.grow_vine, strew.ornament._engine._handed_over).

A tiled world's later tile raises a goal to the circle its finished neighbour grew into
there. hierarchy's vine ended short of the goal's centre by a quarter of its radius,
measured back from the centre: with the raised radius the vine came out shorter than in
the narrow circle itself (and pointed backwards past four times the room), so a raised
border grew more, shorter vines (60 x 60 panel, every vines-phase goal raised to 20:
vines 21 -> 27, mean chord 8.96 -> 6.89 at a2b29a1).
"""

from __future__ import annotations

import numpy as np

import strew
from strew.ornament._engine import grow_elements

R = 16.0


def _vines(orn):
    """(chord, radius of the circle grown into) of the vines the vines-phase rules grew
    (not the joins, which span two tips)."""
    out = []
    for e in orn.elements:
        if e.type == "vine" and e.phase == "vines" and e.target < 0 and hasattr(e, "goal_circle"):
            p = e.proxy.point_at(np.array([0.0, 1.0]))
            out.append((float(np.hypot(*(p[1] - p[0]))), e.goal_circle[2]))
    return np.array(out, float).reshape(-1, 2)


def test_a_raised_vine_is_as_long_as_the_raised_circles():
    reg = strew.Region.rectangle(48.0, 48.0)
    seeds = [[24.0, 24.0]]
    grid = np.arange(0.0, 49.0, 4.0)
    # every vines-phase goal raised to R where its own circle is narrower
    raised = _vines(grow_elements("hierarchy", reg, seeds=seeds, rng=1, _holes=[[x, y, R, "vines"] for x in grid for y in grid]))
    narrow = raised[raised[:, 1] < R]
    assert len(narrow) >= 3
    # grown at the raised scale: (1 - 0.6) R at the shortest try (a2b29a1: chords down
    # to d - 0.6 R, under the narrow circle's own vine)
    assert narrow[:, 0].min() >= 0.4 * R - 1e-6
    plain = _vines(grow_elements("hierarchy", reg, seeds=seeds, rng=1))
    # fewer, longer vines than with nothing raised, as the one run grows at that scale
    assert len(raised) <= len(plain)
    assert raised[:, 0].mean() > plain[:, 0].mean()
