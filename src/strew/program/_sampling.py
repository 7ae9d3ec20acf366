"""Point sets behind the irregular partitions (Loi et al. §5.1).

``UniformPartition`` is the Voronoi diagram of a Poisson-disk set and ``RandomPartition``
the Voronoi diagram of a Poisson set. The Poisson-disk set comes from
:func:`strew.pack.poisson_disk` (Bridson's dart throwing, 30 candidates per active point),
driven by the caller's numpy Generator.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["poisson_disk", "poisson", "DISK_PACKING"]

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
