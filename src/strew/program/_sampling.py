"""Point sets behind the irregular partitions (Loi et al. §5.1).

``UniformPartition`` is the Voronoi diagram of a Poisson-disk set and ``RandomPartition``
the Voronoi diagram of a Poisson set. The Poisson-disk set comes from Bridson's
dart throwing (grid of cell r/sqrt(2), 30 candidates in the annulus [r, 2r] around an
active point); it is written here, with its own small splitmix64 generator seeded from
the caller's numpy Generator, so that no global random state is touched.
(strew.pack has its own sampler; this one is kept local to the program package.)
"""

from __future__ import annotations

import math

import numba
import numpy as np

__all__ = ["poisson_disk", "poisson", "DISK_PACKING"]

#: Points per r^2 of a (near-maximal) Bridson set in the plane (measured: 0.62 on large
#: domains), used to turn a density (points per unit area) into a disk radius.
DISK_PACKING = 0.62


@numba.njit(cache=True)
def _next(state: np.ndarray) -> float:
    # splitmix64 on a uint64 state; returns a float in [0, 1)
    state[0] += np.uint64(0x9E3779B97F4A7C15)
    z = state[0]
    z = (z ^ (z >> np.uint64(30))) * np.uint64(0xBF58476D1CE4E5B9)
    z = (z ^ (z >> np.uint64(27))) * np.uint64(0x94D049BB133111EB)
    z = z ^ (z >> np.uint64(31))
    return float(z >> np.uint64(11)) / 9007199254740992.0


@numba.njit(cache=True)
def _bridson(w: float, h: float, r: float, k: int, seed: np.uint64) -> np.ndarray:
    state = np.empty(1, dtype=np.uint64)
    state[0] = seed
    cell = r / math.sqrt(2.0)
    gw = int(math.ceil(w / cell)) + 1
    gh = int(math.ceil(h / cell)) + 1
    grid = -np.ones((gw, gh), dtype=np.int64)
    cap = gw * gh + 1
    pts = np.empty((cap, 2))
    active = np.empty(cap, dtype=np.int64)
    pts[0, 0] = _next(state) * w
    pts[0, 1] = _next(state) * h
    grid[int(pts[0, 0] / cell), int(pts[0, 1] / cell)] = 0
    n = 1
    active[0] = 0
    na = 1
    r2 = r * r
    while na > 0:
        ai = int(_next(state) * na)
        if ai >= na:
            ai = na - 1
        p = active[ai]
        found = False
        for _ in range(k):
            # uniform in the annulus [r, 2r] by area
            rad = math.sqrt(r2 + _next(state) * 3.0 * r2)
            ang = 2.0 * math.pi * _next(state)
            x = pts[p, 0] + rad * math.cos(ang)
            y = pts[p, 1] + rad * math.sin(ang)
            if x < 0.0 or y < 0.0 or x >= w or y >= h:
                continue
            gx = int(x / cell)
            gy = int(y / cell)
            ok = True
            for ix in range(max(gx - 2, 0), min(gx + 3, gw)):
                for iy in range(max(gy - 2, 0), min(gy + 3, gh)):
                    q = grid[ix, iy]
                    if q >= 0:
                        dx = pts[q, 0] - x
                        dy = pts[q, 1] - y
                        if dx * dx + dy * dy < r2:
                            ok = False
                            break
                if not ok:
                    break
            if ok:
                pts[n, 0] = x
                pts[n, 1] = y
                grid[gx, gy] = n
                active[na] = n
                na += 1
                n += 1
                found = True
                break
        if not found:
            active[ai] = active[na - 1]
            na -= 1
    return pts[:n].copy()


def poisson_disk(bounds: tuple[float, float, float, float], density: float, rng: np.random.Generator) -> np.ndarray:
    """A Poisson-disk set with about ``density`` points per unit area in ``bounds``.

    Returns
    -------
    (n, 2) float
    """
    x0, y0, x1, y1 = bounds
    r = math.sqrt(DISK_PACKING / density)
    seed = np.uint64(int(rng.integers(0, 2**63)))
    pts = _bridson(float(x1 - x0), float(y1 - y0), r, 30, seed)
    return pts + np.array([x0, y0])


def poisson(bounds: tuple[float, float, float, float], density: float, rng: np.random.Generator) -> np.ndarray:
    """A Poisson set (uniform points, Poisson count) of ``density`` in ``bounds``."""
    x0, y0, x1, y1 = bounds
    n = int(rng.poisson(density * (x1 - x0) * (y1 - y0)))
    return rng.uniform([x0, y0], [x1, y1], size=(n, 2))
