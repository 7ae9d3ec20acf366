"""Flow mode: the pushed hole fills are kept one hole at a time (issue 14 point 2).

Where filling all the holes left at once by pushing (``_flow_holes._push_fill``) and
the band's pass lowers the six-neighbour share, ``_Grower.run`` undoes it and tries the
holes one at a time, each kept only where the share does not fall
(``close_holes(..., each=...)``). The held-out scales over 24 spacings from (22, 2)
kept both of their holes at 4882d93 (both filled: 0.8197 -> 0.8158); one at a time the
second is kept (holes 2 -> 1), and the 90 degree field over 30 spacings rises
0.9563 -> 0.9667 (``benchmarks/grow.py --structure --flow-only``). No case small
enough for this file's time budget reaches the one-at-a-time path (20 cases over 10
and 12 spacings, flow14v), so this checks ``close_holes``' contract with ``each``.
"""

from __future__ import annotations

import numpy as np

from strew.grow import _flow_holes as fh


class _G:
    l = 1.0

    class p:
        flow_hole_min = 0.7

    order = ()

    def near(self, *a):
        return []

    def in_domain(self, *a):
        return True


def test_close_holes_each_undoes_and_does_not_count_a_refused_fill(monkeypatch):
    # three holes far apart; the guard refuses the second fill
    ux, uy = np.array([0.0, 10.0, 20.0]), np.zeros(3)
    monkeypatch.setattr(fh, "reference_gap", lambda g: 0.5)
    monkeypatch.setattr(fh, "_wide_circles", lambda g, lo: (ux, uy, np.arange(3)))
    filled = []
    monkeypatch.setattr(fh, "_close_one", lambda g, cx, cy, push=False: filled.append((cx, push)) or True)
    calls = []

    def each(mark=None):
        if mark is None:
            calls.append(("mark", len(filled)))
            return len(filled)
        calls.append(("after", mark))
        return mark != 1

    made = fh.close_holes(_G(), push=True, each=each)
    assert filled == [(0.0, True), (10.0, True), (20.0, True)]
    # a mark before each try, the verdict after each fill with that try's mark
    assert calls == [("mark", 0), ("after", 0), ("mark", 1), ("after", 1), ("mark", 2), ("after", 2)]
    assert made == 2
    # without ``each`` every fill counts, as before
    filled.clear()
    assert fh.close_holes(_G(), push=True) == 3
