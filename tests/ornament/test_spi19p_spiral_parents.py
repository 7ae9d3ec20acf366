"""A tile keeps a spiral only with the spiral it grew from (issue 19 point 4;
strew.ornament._context.PARENT_COLUMN, strew.tiles._keep_groups, _at_parent).

A spiral is one row (Pattern.group: its arms), named by its first arm, and it branches
from any arm of its parent spiral, so the public ``parent`` named a row for few spirals.
A tile then placed a spiral by its own centre instead of at its parent, and kept spirals
whose parent spiral it dropped past the border.
"""

from __future__ import annotations

import numpy as np
import pytest

import strew
import strew.tiles as T
from strew.ornament import grow_ornament


@pytest.fixture(scope="module")
def rows():
    # tile 0 (30 x 30) of a 60 x 60 world in tiles of 30: every neighbour runs later
    return grow_ornament("spirals", strew.Region.rectangle(40, 40), rng=0, _tiled=True)


def _parent_row(arr) -> np.ndarray:
    """Each row's parent row (-1 none), from the arms each row draws: a spiral's arms are
    placed together (one rule success), so its row covers the placement indices from its
    element on, one per record."""
    el = np.asarray(arr["element"], np.int64)
    n = np.array([len(r) for r in arr["ornament_proxies"]])
    par = np.asarray(arr["parent"], np.int64)
    hit = (par[:, None] >= el[None, :]) & (par[:, None] < (el + n)[None, :])
    return np.where(hit.any(axis=1), hit.argmax(axis=1), -1)


def test_spirals_are_placed_at_and_kept_with_their_parent_spiral(rows):
    pr = _parent_row(rows)
    assert (pr >= 0).sum() >= 0.9 * len(rows)  # all but the seeds' spirals
    _, inv = np.unique(np.asarray(rows["ornament_group"]), return_inverse=True)
    tips = np.ones(len(rows), bool)  # every spiral's arm parents a rule
    at = T._at_parent(rows, inv, tips)[inv]
    # each spiral with a drawn parent is placed at its parent spiral's row
    assert np.array_equal(at[pr >= 0], pr[pr >= 0])
    tiles, nx, ny = T.plan((60.0, 60.0), 30.0)
    job = T._Job("ornament", "spirals", {}, (60.0, 60.0), 7.5, 1, (30.0, 30.0), (nx, ny))
    kept = T._keep_groups(rows, np.ones(len(rows), bool), tiles[0], job, {})
    assert kept.any() and not kept.all()
    # no kept spiral hangs from a dropped one (they were kept: 9dffc62)
    orphans = kept & (pr >= 0) & ~kept[np.maximum(pr, 0)]
    assert not orphans.any(), f"{int(orphans.sum())} kept spirals grow from a dropped spiral"
