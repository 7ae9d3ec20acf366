"""Ma et al.'s patch initialisation, the baseline of §6.4."""

from __future__ import annotations

import time
from collections.abc import Callable

import numpy as np

from .._progress import Reporter
from ._grow import _record
from ._optimize import optimize
from ._state import SynthState

__all__ = ["patch_initialize"]


def patch_initialize(
    state: SynthState,
    *,
    cell: float | None = None,
    time_budget: float = 0.0,
    rounds: int | None = None,
    max_rounds: int = 1000,
    progress: Callable | None = None,
    should_cancel: Callable | None = None,
) -> int:
    """Patch initialisation (Ma et al., as in §6.4), then global optimisation rounds.

    The region's bounding box and the selection are cut into square cells of side
    ``cell`` (default: the median neighbourhood radius); every output cell receives the
    elements of a random exemplar cell (exemplar drawn by the selection's weights),
    keeping those whose centre lies in the region. Global optimisation then runs for
    ``rounds`` rounds (deterministic), or else for ``time_budget`` seconds (at least one
    round when the budget is positive; as in §6.4, where it gets the time region growing
    took).

    Returns
    -------
    int
        Elements placed.
    """
    prep = state.prep
    rng = state.rng
    if state.region is None:
        from .._errors import InputError

        raise InputError("patch initialisation: give a region (or a size) to fill")
    if cell is None:
        cell = float(np.median(prep.rbar))
    x0, y0, x1, y1 = state.region.bounds
    nx = max(1, int(np.ceil((x1 - x0) / cell)))
    ny = max(1, int(np.ceil((y1 - y0) / cell)))
    rep = Reporter(progress, should_cancel, total=nx * ny, message="patch init")
    t0 = time.perf_counter()
    skipped = [0.0]
    srcs, pts = [], []
    spans = []
    for s in range(len(prep.names)):
        ids = np.flatnonzero(prep.source == s)
        lo, hi = prep.pos[ids].min(axis=0), prep.pos[ids].max(axis=0)
        spans.append((ids, lo, hi))
    for gy in range(ny):
        for gx in range(nx):
            rep.tick(gy * nx + gx)
            s = int(rng.choice(len(prep.names), p=prep.weights)) if len(prep.names) > 1 else 0
            ids, lo, hi = spans[s]
            room = np.maximum(hi - lo - cell, 0.0)
            o = lo + rng.random(2) * room
            p = prep.pos[ids]
            inside = np.all((p >= o) & (p < o + cell), axis=1)
            dst = np.array([x0 + gx * cell, y0 + gy * cell])
            srcs.append(ids[inside])
            pts.append(p[inside] - o + dst)
    src = np.concatenate(srcs)
    pos = np.concatenate(pts) if pts else np.zeros((0, 2))
    keep = state.region.contains(pos)
    state.add(src[keep], pos[keep], horizon=False)
    _record(state, t0, skipped)
    if rounds is not None:
        for _ in range(int(rounds)):
            optimize(state, None)
            _record(state, t0, skipped)
    else:
        done = 0
        while time_budget > 0 and done < max_rounds:
            optimize(state, None)
            done += 1
            _record(state, t0, skipped)
            if time.perf_counter() - t0 - skipped[0] >= time_budget:
                break
    rep.done(nx * ny)
    return state.n
