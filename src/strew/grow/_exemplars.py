"""Small reference arrangements built in Python, one per class of the paper's Fig. 8.

- :func:`hex_exemplar`: regular (a hexagonal lattice of scales);
- :func:`tile_exemplar`: near-regular (a jittered square grid of tiles in two colours);
- :func:`stone_exemplar`: irregular uniform (white and gray stones, Poisson-disk spaced).

They are used by the tests, the benchmark and the demo, and written to
``examples/grow/*.json`` so that the CLI can read them.
"""

from __future__ import annotations

import numpy as np

from .._rng import as_rng
from ..arrangement import Arrangement
from ..shape import Shape

__all__ = ["hex_exemplar", "tile_exemplar", "stone_exemplar", "hex_lattice"]


def hex_lattice(rows: int, cols: int, spacing: float = 10.0) -> np.ndarray:
    """(rows * cols, 2) centres of a hexagonal lattice (odd rows shifted by half a step)."""
    r, c = np.mgrid[0:rows, 0:cols]
    x = (c + 0.5 * (r % 2)) * spacing
    y = r * spacing * np.sqrt(3) / 2
    return np.c_[x.ravel(), y.ravel()].astype(float)


def _scale_shape(spacing: float) -> Shape:
    # A rounded "scale": a circle-like polygon, radius 0.42 * spacing, pointed towards +x.
    t = np.linspace(0, 2 * np.pi, 24, endpoint=False)
    r = 0.42 * spacing * (1 + 0.08 * np.cos(t))
    return Shape.polygon(np.c_[r * np.cos(t), 0.85 * r * np.sin(t)], style={"fill": "#3f8f7f", "stroke": "#1d4a41", "stroke_width": 0.6})


def hex_exemplar(rows: int = 6, cols: int = 6, spacing: float = 10.0) -> Arrangement:
    """A regular reference: one kind of scale on a hexagonal lattice.

    Parameters
    ----------
    rows, cols : int
    spacing : float
        Distance between neighbouring centres.

    Returns
    -------
    Arrangement
        ``rows * cols`` elements of kind ``"scale"``.
    """
    xy = hex_lattice(rows, cols, spacing)
    return Arrangement({"scale": _scale_shape(spacing)}, np.zeros(len(xy), dtype=int), xy[:, 0], xy[:, 1])


def tile_exemplar(rows: int = 6, cols: int = 6, spacing: float = 10.0, rng: int | np.random.Generator | None = 7) -> Arrangement:
    """A near-regular reference: a jittered square grid of tiles, two colours in a checker.

    The jitter (5% of ``spacing`` in position, 3° in rotation, 4% in scale) keeps the
    lattice recognisable.
    """
    g = as_rng(rng)
    r, c = np.mgrid[0:rows, 0:cols]
    x = c.ravel() * spacing + g.normal(0, 0.05 * spacing, rows * cols)
    y = r.ravel() * spacing + g.normal(0, 0.05 * spacing, rows * cols)
    kind = ((r + c) % 2).ravel()
    side = 0.72 * spacing
    shapes = {
        "tile_light": Shape.rectangle(side, side, style={"fill": "#e8d9b5", "stroke": "#7a6a48", "stroke_width": 0.5}),
        "tile_dark": Shape.rectangle(side, side, style={"fill": "#b5653c", "stroke": "#5a2f18", "stroke_width": 0.5}),
    }
    rot = np.deg2rad(g.uniform(-3, 3, rows * cols))
    scale = g.uniform(0.96, 1.04, rows * cols)
    return Arrangement(shapes, kind, x, y, rot, scale)


def _stone(radius: float, g: np.random.Generator, fill: str) -> Shape:
    t = np.sort(g.uniform(0, 2 * np.pi, 11))
    r = radius * g.uniform(0.8, 1.0, len(t))
    return Shape.polygon(np.c_[r * np.cos(t), r * np.sin(t)], style={"fill": fill, "stroke": "#333", "stroke_width": 0.5})


def stone_exemplar(width: float = 70.0, height: float = 70.0, spacing: float = 10.0, rng: int | np.random.Generator | None = 11) -> Arrangement:
    """An irregular uniform reference: stones of three kinds at Poisson-disk spacing.

    Centres are at least ``spacing`` apart (dart throwing); white stones are the most
    common, gray stones fewer, small stones fill in. Stones never overlap.
    """
    g = as_rng(rng)
    pts: list[tuple[float, float]] = []
    for _ in range(4000):
        p = g.uniform((0, 0), (width, height))
        if all((p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2 >= spacing**2 for q in pts):
            pts.append((float(p[0]), float(p[1])))
    xy = np.asarray(pts)
    u = g.uniform(0, 1, len(xy))
    kind = np.where(u < 0.6, 0, np.where(u < 0.85, 1, 2))
    shapes = {
        "white_stone": _stone(0.45 * spacing, g, "#eeeae0"),
        "gray_stone": _stone(0.45 * spacing, g, "#8a8d90"),
        "small_stone": _stone(0.28 * spacing, g, "#c9b99a"),
    }
    rot = g.uniform(-np.pi, np.pi, len(xy))
    return Arrangement(shapes, kind, xy[:, 0], xy[:, 1], rot)
