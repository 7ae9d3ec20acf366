"""Energy (Eq. 2) and average neighbourhood distance (Eq. 5, §6.4)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from . import _kernels as K

if TYPE_CHECKING:
    from ._state import SynthState

__all__ = ["neighborhood_distances", "energy", "average_neighborhood_distance", "sample_distance"]


def neighborhood_distances(state: SynthState, which: np.ndarray | None = None) -> np.ndarray:
    """min over the selection S of |n(o) - n(e)| (Eq. 1) for output elements ``which``.

    A brute-force search over every exemplar element of the selection (no k-coherence),
    so that outputs made by different methods are measured alike.

    Returns
    -------
    (m,) float
    """
    prep = state.prep
    n = state.n
    if which is None:
        which = np.arange(n)
    which = np.asarray(which, np.int64)
    if len(which) == 0 or n == 0:
        return np.zeros(0)
    pos = state.pos
    src = state.src
    out = np.empty(len(which))
    sel = np.flatnonzero(prep.selected_elements).astype(np.int64)
    ne = len(sel)
    block = max(1, 400_000 // max(ne, 1))
    for a in range(0, len(which), block):
        q = which[a : a + block]
        ptr, idx, off = K.grid_neighborhoods(pos, q, prep.rbar[src[q]])
        cands = np.tile(sel, (len(q), 1))
        costs = K.candidate_costs(ptr, off, prep.kind[src[idx]], 2.0 * prep.r[src[idx]], prep.rbar[src[q]], prep.kind[src[q]], 2.0 * prep.r[src[q]], cands, prep.nb_ptr, prep.nb_off, prep.nb_kind, prep.nb_d, prep.kind, prep.kind_cost)
        out[a : a + len(q)] = costs.min(axis=1)
    return out


def energy(state: SynthState, which: np.ndarray | None = None) -> float:
    """E(O, S) of Eq. 2: the sum of neighbourhood distances to the most similar exemplar
    neighbourhoods."""
    return float(neighborhood_distances(state, which).sum())


def average_neighborhood_distance(state: SynthState, sample: int | None = None, rng: int = 0) -> float:
    """Eq. 5: the average neighbourhood distance of the output against the selection.

    Parameters
    ----------
    sample : int, optional
        Measure a random sample of this many elements (a fixed seed) instead of all.
    """
    n = state.n
    if n == 0:
        return float("nan")
    which = None
    if sample is not None and sample < n:
        which = np.sort(np.random.default_rng(rng).choice(n, sample, replace=False))
    return float(neighborhood_distances(state, which).mean())


def sample_distance(state: SynthState, sample: int) -> float:
    """Eq. 5 on a fixed-seed sample, for traces while synthesis runs."""
    return average_neighborhood_distance(state, sample)
