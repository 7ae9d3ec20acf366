"""Issue 13 point 1 (s28k): ``_grow.copyable`` asks only whether a candidate can generate
(``_kernels.place_proposals``' ``prop_gen``); the chosen candidate's proposals are copied
as before, a child of a parent beyond the region's edge too. Dropping those from the copy
(s27t) left a seam against a context (``test_synth_context.py``, density 1.19)."""

from __future__ import annotations

import numpy as np

from strew.synth import _kernels as K


def _layout():
    # one seed, two candidates within the ratio bound (0 and 1 against 0 + slack 2):
    # candidate 0 offers t0 (an orphan, -2) and t1 (refused by the static checks);
    # candidate 1 offers t2, its child t3, t4 beyond the edge (refused, parent_free) and
    # t4's child t5
    costs = np.array([[0.0, 1.0]])
    slack = np.array([2.0])
    count = np.array([2, 4], np.int64)
    out_ptr = np.array([0, 2, 6], np.int64)
    pos = np.column_stack([np.arange(6) * 10.0, np.zeros(6)])
    r = np.ones(6)
    sk = np.zeros(6, np.int64)
    md = np.zeros((1, 1))
    ok = np.array([True, False, True, True, False, True])
    pslot = np.array([-2, -1, -1, 2, -1, 4], np.int64)
    free = np.array([False, False, False, False, True, False])
    cls = np.array([0, 0, 1, 0, 1, 0], np.int64)
    return costs, slack, out_ptr, count, pos, r, sk, md, ok, pslot, free, cls


def _place(gen):
    costs, slack, out_ptr, count, pos, r, sk, md, ok, pslot, free, cls = _layout()
    return K.place_proposals(costs, slack, out_ptr, count, pos, r, sk, md, ok, 1.0, 1.0, 3.0, pslot, free, cls, gen)


def test_generation_is_asked_of_prop_gen_and_the_copy_of_prop_ok():
    """With ``prop_gen = prop_ok`` (the paper's rule) the seed takes candidate 0, whose
    only passing proposal is an orphan, and gives up; with the orphan not counted it
    takes candidate 1 and copies all its passing proposals, t5 (not counted: its parent
    lies beyond the edge) with them."""
    ok = _layout()[8]
    placed, seed_ok = _place(ok.copy())
    assert not placed.any() and not seed_ok[0]
    gen = np.array([False, False, True, True, False, False])
    placed, seed_ok = _place(gen)
    assert placed.tolist() == [False, False, True, True, False, True]
    assert seed_ok[0]
