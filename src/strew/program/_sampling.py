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
    world (issue 19.1, program's partitions tiled). The context near the rectangle seeds
    the dart throwing, so the set reaches the finished borders. This is
    :func:`strew.pack.poisson_disk` with ``context`` (the library's one compiled sampler,
    issue 15 point 5); phase-0 tiles, with no context, start from a random point.

    Returns
    -------
    (n, 2) float
        Points in ``[x0, x1) x [y0, y1)``, in generation order.
    """
    x0, y0, x1, y1 = (float(v) for v in rect)
    r = math.sqrt(DISK_PACKING / density)
    from ..pack import poisson_disk as bridson

    ctx = np.asarray(context, float).reshape(-1, 2)
    return bridson((x0, y0, x1, y1), r, candidates=30, rng=rng, context=ctx)


def tile_poisson(rect: tuple[float, float, float, float], density: float, rng: np.random.Generator) -> np.ndarray:
    """A Poisson set of ``density`` in the half-open tile ``rect = (x0, y0, x1, y1)``: the
    tiles' sets together are a Poisson set of the world (no context needed)."""
    x0, y0, x1, y1 = (float(v) for v in rect)
    n = int(rng.poisson(density * (x1 - x0) * (y1 - y0)))
    p = rng.uniform([x0, y0], [x1, y1], size=(n, 2))
    return p[(p[:, 0] < x1) & (p[:, 1] < y1)]
