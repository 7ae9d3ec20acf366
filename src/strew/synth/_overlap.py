"""Synth's overlap rule applied as elements arrive (Davison et al. 2018, §4, §5.4).

The bounding discs of §4 do not rule overlapping shapes out. When no exemplar of the
selection has overlapping shapes (``Prepared.overlap_free``), the later of two overlapping
elements leaves the output (:meth:`strew.synth.SynthState.to_arrangement`); an interactive
caller (the studio's brush, filler and eraser) applies the same rule to each change as it
arrives, so that what is shown is what is saved. It lives here, not in the studio (issue
15 point 6: the overlap rule belongs in the library).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..arrangement import Arrangement, concat
from ..editing import overlap_drops

__all__ = ["drop_new_overlaps"]


def drop_new_overlaps(
    state: Any,
    n0: int,
    fixed: Arrangement | None = None,
    *,
    around: np.ndarray | None = None,
    reach: float = 0.0,
    tile: Any = None,
) -> int:
    """Remove the synthesis elements that overlap others, near the latest change.

    A new element (index ``>= n0``) goes when it overlaps an element of ``fixed``. When no
    exemplar of the state's selection has overlapping shapes (``state.prep.overlap_free``),
    the later of any two overlapping synthesis elements goes too (the rule of
    :meth:`strew.synth.SynthState.to_arrangement`, :func:`strew.editing.overlap_drops`).
    Older elements are checked near the new ones and, when ``around`` is given, within
    ``reach`` of those points (optimisation moves them).

    Parameters
    ----------
    state : SynthState
        Changed in place (:meth:`~strew.synth.SynthState.remove`).
    n0 : int
        Elements ``n0 ..`` are the new ones.
    fixed : Arrangement, optional
        Elements that never go (a scene around the synthesis).
    around : (m, 2) float, optional
        Points whose neighbourhood (radius ``reach``) the change touched, e.g. brush points.
    reach : float
    tile : (4,) float, optional
        ``x0, y0, w, h`` of a repeat tile: distances and overlaps on its torus.

    Returns
    -------
    int
        How many elements went.
    """
    from scipy.spatial import cKDTree

    from ..metrics import overlaps

    st = state
    fixed = fixed if fixed is not None else Arrangement({}, [], [], [])
    if st is None or st.n <= n0:
        return 0
    prep = st.prep
    overlap_free = bool(getattr(prep, "overlap_free", False))
    if not overlap_free and len(fixed) == 0:
        return 0
    pos = st.pos
    state_part = st.elements

    if tile is not None:  # distances and overlaps on the torus of the tile
        from .._periodic import canonical

        x0, y0, w, h = tile

        def rel(xy: np.ndarray) -> np.ndarray:
            xy = np.asarray(xy, float).reshape(-1, 2)
            return np.asarray(np.c_[canonical(xy[:, 0], xy[:, 1], tile)]) - (x0, y0)

        def tree_of(xy: np.ndarray) -> Any:
            return cKDTree(rel(xy), boxsize=(w, h))
    else:
        def tree_of(xy: np.ndarray) -> Any:
            return cKDTree(xy)

        def rel(xy: np.ndarray) -> np.ndarray:
            return np.asarray(xy, float)
    new_idx = np.arange(n0, st.n)
    rmax = float(np.max(state_part(new_idx).radii))
    cand = new_idx
    if overlap_free and n0:
        old_xy = rel(pos[:n0])
        r_old = state_part(np.arange(n0)).radii
        hits = tree_of(pos[new_idx]).query_ball_point(old_xy, r=r_old + rmax, return_length=True) > 0
        if around is not None and len(around):
            hits |= tree_of(np.asarray(around, float)).query_ball_point(old_xy, r=reach, return_length=True) > 0
        cand = np.concatenate([np.flatnonzero(hits), new_idx])
    local = state_part(cand)
    fixed = fixed.replace(columns={}, meta={}, extra={}, region=None)
    if len(fixed):
        tree = tree_of(local.xy)
        near = tree.query_ball_point(rel(fixed.xy), r=fixed.radii + float(np.max(local.radii)), return_length=True) > 0
        fixed = fixed.select(near)
    combined = concat([fixed, local]) if len(fixed) else local
    nf = len(fixed)
    if tile is not None:
        from ..metrics import wrap_overlaps

        pairs = wrap_overlaps(combined, tile=tile)["pairs"][:, :2]
        pairs = pairs[pairs[:, 0] != pairs[:, 1]]
    else:
        pairs, _ = overlaps(combined)
    dropped = overlap_drops(pairs, nf, cand >= n0, later=overlap_free)
    if not dropped.any():
        return 0
    mask = np.zeros(st.n, bool)
    mask[cand[dropped]] = True
    return int(st.remove(mask))
