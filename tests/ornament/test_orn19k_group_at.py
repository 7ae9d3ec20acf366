"""A finished ornament tile places each rule success by its growing tip (issue 19 point 4;
strew.tiles._keep_groups, _GROUP_AT "parents").

By the mean of a success's rows, a flower's success growing into a later tile was kept
with its flower past the border, the farther the longer its stem and the more with a
leaf (at the stem's midpoint, a third of the mean's weight): the finished side kept
the leaves and gave the later side their flowers.
"""

from __future__ import annotations

import numpy as np
import pytest

from strew.ornament._context import element_record, parent_rows
from strew.ornament._pattern import Element, load_pattern

from test_orn19g_cut_touching import _tile0 as _tile0_cut  # noqa: E402


def _row(pat, type_name):
    el = Element(pat.types[type_name])
    el.phase = "flowers"
    for pr in el.proxies:
        if type_name in ("flower", "bud"):
            pr.set(np.array([1.0, 2.0]), 2.0)
        elif type_name == "stem":
            pr.set(np.array([0.0, 0.0]), np.array([9.0, 0.0]))
        else:
            pr.set(np.array([0.0, 0.0]), 0.5, 0.6, np.array([0.0, 3.0]), 1.5, 0.4)
    return (element_record(el, pat),)


def test_rows_of_parents():
    pat = load_pattern("flowers")
    names = ["stem", "flower", "leaf", "bud"]
    col = np.empty(len(names) + 1, dtype=object)
    for i, n in enumerate(names):
        col[i] = _row(pat, n)
    col[-1] = ()  # a row without records (not drawn by a rule)
    # flower --> stem flower (* leaf, added at will); flower bud --> stem bud
    assert parent_rows("flowers", col).tolist() == [False, True, False, True, False]


def _tile0(monkeypatch, group_at):
    """Tile 0 of a 160 x 160 flowers world in tiles of 80 (halo 20): its grown rows, the
    rows it keeps and its rectangle (test_orn19g_cut_touching's world, its cut unchanged)."""
    import strew.tiles as T
    from strew.ornament import _context as C

    monkeypatch.setattr(T, "_GROUP_AT", group_at)
    arr, kept, _, _ = _tile0_cut(monkeypatch, C.CUT_TOUCH)
    return arr, kept, T.plan((160.0, 160.0), 80.0)[0][0].rect


@pytest.mark.slow
def test_finished_tile_keeps_a_success_by_its_flower(monkeypatch):
    arr, kept, (x0, y0, x1, y1) = _tile0(monkeypatch, "parents")
    tips = parent_rows("flowers", arr["ornament_proxies"])
    x, y = np.asarray(arr.x, float), np.asarray(arr.y, float)
    inside = (x >= x0) & (x < x1) & (y >= y0) & (y < y1)
    # tile 0 runs first and grows past its border into its halo (by the mean of a
    # success's rows it kept flowers there: _GROUP_AT "mean", 3e74fcd)...
    assert (tips & ~inside).sum() > 20 and (kept & tips).sum() > 50
    # ...but keeps no flower or bud past it
    assert not (kept & tips & ~inside).any()
    # a success's rows go together
    group = np.asarray(arr["ornament_group"])
    for g in np.unique(group):
        assert len(set(kept[group == g].tolist())) == 1
