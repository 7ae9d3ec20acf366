"""Flow mode: the band's network passes know the outlines' contacts, each bond kept no
shorter than its two outlines' contact along it and the pairs its moves leave
overlapping pushed apart by the overlap's depth before any steps back (issue 14 point
2; :func:`strew.grow._flow_net._contact_lengths`, :func:`strew.grow._flow_net._push_apart`).

A hexagon of the suite's lattice is 0.86 spacings across its flats and touches its
neighbour at 0.99 spacings corner to corner, so the band's 0.9 mean edges pressed
pairs into each other where the lattice's bonds had turned from the elements' frame,
and stepping the pairs back undid the fit around every contact. The hexagonal lattice
grown from (2, 2) spacings of a square of 16 spacings along the quarter-circle field
(``benchmarks/flow14p_heldout.py``, ``qc16_2,2``, a case nobody tuned on): 0.849 of
the interior elements kept six neighbours at the spacing at 313948f, 0.892 now, with no
hole, nothing across the edge and no overlap: that case is grown and its bound (0.875)
asserted once, in ``test_grow_flow14p_one_side.py``. Here the contacts' unit test: two
hexagons touch at their flats' distance side by side and at twice their circumradius
turned 30 degrees.
"""

from __future__ import annotations

import math

import numpy as np
import shapely
from test_grow_flow_gaps import SP


def test_contact_lengths_follow_the_outlines_not_a_disc():
    from strew.grow._flow_net import _contact_lengths

    # two regular hexagons 0.86 spacings across their flats (as the suite's lattice),
    # side by side along x: flat to flat when turned 0, corner to corner turned 30 deg
    r = 0.43 * SP / math.cos(math.pi / 6)  # circumradius
    ring = np.c_[np.cos(np.arange(6) * math.pi / 3 + math.pi / 6), np.sin(np.arange(6) * math.pi / 3 + math.pi / 6)] * r

    class G:
        l = SP

    g = G()
    for turn, want in ((0.0, 0.86 * SP), (math.pi / 6, 2 * r)):
        c, s = math.cos(turn), math.sin(turn)
        rot = ring @ np.array([[c, s], [-s, c]])
        pts = np.array([[0.0, 0.0], [0.8 * SP, 0.0]])
        g.geom = [shapely.Polygon(rot + p) for p in pts]
        got = _contact_lengths(g, np.arange(2), np.array([[0, 1]]), pts, np.zeros(2, dtype=bool), 0.5 * SP)
        assert abs(got[0] - want) < 2e-3 * SP, (turn, got[0], want)
        # (and no shorter than the shortest asked)
        assert _contact_lengths(g, np.arange(2), np.array([[0, 1]]), pts, np.zeros(2, dtype=bool), 1.2 * SP)[0] == 1.2 * SP
