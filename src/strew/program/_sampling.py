"""Point sets behind the irregular partitions (Loi et al. §5.1).

``UniformPartition`` is the Voronoi diagram of a Poisson-disk set and ``RandomPartition``
the Voronoi diagram of a Poisson set. The Poisson-disk set comes from
:func:`strew.pack.poisson_disk` (Bridson's dart throwing, 30 candidates per active point),
driven by the caller's numpy Generator.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["poisson_disk", "poisson", "periodic_poisson_disk", "periodic_poisson", "tile_poisson_disk", "tile_poisson", "DISK_PACKING"]

#: Points per r^2 of a (near-maximal) Bridson set in the plane (measured: 0.62 on large
#: domains), used to turn a density (points per unit area) into a disk radius.
DISK_PACKING = 0.62


def poisson_disk(bounds: tuple[float, float, float, float], density: float, rng: np.random.Generator) -> np.ndarray:
    """A Poisson-disk set with about ``density`` points per unit area in ``bounds``.

    Returns
    -------
    (n, 2) float
    """
    x0, y0, x1, y1 = bounds
    r = math.sqrt(DISK_PACKING / density)
    from ..pack import poisson_disk as bridson

    pts = bridson((float(x1 - x0), float(y1 - y0)), r, candidates=30, rng=rng)
    return pts + np.array([x0, y0])


def poisson(bounds: tuple[float, float, float, float], density: float, rng: np.random.Generator) -> np.ndarray:
    """A Poisson set (uniform points, Poisson count) of ``density`` in ``bounds``."""
    x0, y0, x1, y1 = bounds
    n = int(rng.poisson(density * (x1 - x0) * (y1 - y0)))
    return rng.uniform([x0, y0], [x1, y1], size=(n, 2))


def periodic_poisson_disk(tile: tuple[float, float, float, float], density: float, rng: np.random.Generator) -> np.ndarray:
    """A Poisson-disk set on the torus ``tile = (x0, y0, W, H)`` (issue 18).

    Bridson's dart throwing (30 candidates per active point) with distances measured
    around the torus, so that the set and its translates by ``W`` and ``H`` keep the disk
    radius across the tile's edges: :func:`strew.pack.poisson_disk` with
    ``periodic=True`` (the library's one sampler, issue 15 point 5). The radius is capped
    at half the tile's shorter side, where a disk would meet its own translate.

    Returns
    -------
    (n, 2) float
        Points in ``[x0, x0 + W) x [y0, y0 + H)``.
    """
    x0, y0, w, h = tile
    r = math.sqrt(DISK_PACKING / density)
    r = min(r, 0.5 * min(w, h))  # a disk wider than half the tile meets its own translate
    from ..pack import poisson_disk as bridson

    pts = bridson((float(w), float(h)), r, candidates=30, rng=rng, periodic=True)
    return pts + np.array([x0, y0])


def periodic_poisson(tile: tuple[float, float, float, float], density: float, rng: np.random.Generator) -> np.ndarray:
    """A Poisson set on the torus ``tile = (x0, y0, W, H)``: uniform points, Poisson count."""
    x0, y0, w, h = tile
    n = int(rng.poisson(density * w * h))
    return rng.uniform([x0, y0], [x0 + w, y0 + h], size=(n, 2))


def tile_poisson_disk(rect: tuple[float, float, float, float], density: float, context: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """A Poisson-disk set in one tile of a world, around its finished neighbours' points.

    Bridson's dart throwing (30 candidates per active point) in the half-open rectangle
    ``rect = (x0, y0, x1, y1)``, at the radius of :func:`poisson_disk` for ``density``,
    with the points of ``context`` ((m, 2): the sites of the tile's lower-phase
    neighbours, Wei 2008's phase groups) as obstacles: no point comes within the radius
    of a context point, so the tiles' sets together are one Poisson-disk set of the
    world (issue 19.1, program's partitions tiled). Every active point also seeds from the
    context near the rectangle, so the set reaches the finished borders.

    Returns
    -------
    (n, 2) float
        Points in ``[x0, x1) x [y0, y1)``, in generation order.
    """
    x0, y0, x1, y1 = (float(v) for v in rect)
    w, h = x1 - x0, y1 - y0
    r = math.sqrt(DISK_PACKING / density)
    r2 = r * r
    cell = r / math.sqrt(2.0)  # at most one point per background cell
    pad = 2  # cells around the rectangle, for the context points within r of it
    gx, gy = max(1, int(math.ceil(w / cell))) + 2 * pad, max(1, int(math.ceil(h / cell))) + 2 * pad
    grid = [-1] * (gx * gy)
    xs: list[float] = []
    ys: list[float] = []
    offs = [(di, dj) for dj in range(-2, 3) for di in range(-2, 3) if abs(di) + abs(dj) < 4]

    def far_enough(px: float, py: float) -> bool:
        ci, cj = int((px - x0) / cell + pad), int((py - y0) / cell + pad)
        for di, dj in offs:
            i, j = ci + di, cj + dj
            if 0 <= i < gx and 0 <= j < gy:
                k = grid[j * gx + i]
                if k >= 0:
                    dx, dy = px - xs[k], py - ys[k]
                    if dx * dx + dy * dy < r2:
                        return False
        return True

    def add(px: float, py: float) -> int:
        ci, cj = int((px - x0) / cell + pad), int((py - y0) / cell + pad)
        if 0 <= ci < gx and 0 <= cj < gy:
            grid[cj * gx + ci] = len(xs)
        xs.append(px)
        ys.append(py)
        return len(xs) - 1

    ctx = np.asarray(context, float).reshape(-1, 2)
    reach = pad * cell
    near = (ctx[:, 0] >= x0 - reach) & (ctx[:, 0] < x1 + reach) & (ctx[:, 1] >= y0 - reach) & (ctx[:, 1] < y1 + reach)
    n_ctx = 0
    for px, py in ctx[near].tolist():
        add(px, py)
        n_ctx += 1
    active: list[int] = []
    # a first point: a few random darts into the rectangle (it may be covered already)
    for _ in range(30):
        px, py = x0 + float(rng.uniform(0, w)), y0 + float(rng.uniform(0, h))
        if px < x1 and py < y1 and far_enough(px, py):
            active.append(add(px, py))
            break
    # context points next to the rectangle grow into it too (no gap along a finished border)
    active += list(range(n_ctx))
    while active:
        a = int(rng.integers(len(active)))
        bx, by = xs[active[a]], ys[active[a]]
        rad = np.sqrt(rng.uniform(r2, 4 * r2, 30))
        ang = rng.uniform(0, 2 * math.pi, 30)
        found = False
        for rr, aa in zip(rad.tolist(), ang.tolist()):
            px, py = bx + rr * math.cos(aa), by + rr * math.sin(aa)
            if x0 <= px < x1 and y0 <= py < y1 and far_enough(px, py):
                active.append(add(px, py))
                found = True
                break
        if not found:
            active[a] = active[-1]
            active.pop()
    return np.c_[xs[n_ctx:], ys[n_ctx:]].reshape(-1, 2).astype(float)


def tile_poisson(rect: tuple[float, float, float, float], density: float, rng: np.random.Generator) -> np.ndarray:
    """A Poisson set of ``density`` in the half-open tile ``rect = (x0, y0, x1, y1)``: the
    tiles' sets together are a Poisson set of the world (no context needed)."""
    x0, y0, x1, y1 = (float(v) for v in rect)
    n = int(rng.poisson(density * (x1 - x0) * (y1 - y0)))
    p = rng.uniform([x0, y0], [x1, y1], size=(n, 2))
    return p[(p[:, 0] < x1) & (p[:, 1] < y1)]
