"""Exemplars of our own for tests, the benchmark and the demo (after §6.3, Table 1).

Rings of tiles, a grid, stripes, sparse apples with voids (§5.6), and large and small
stones for a two-scale palette. Each function is deterministic for a given ``rng``.
"""

from __future__ import annotations

import numpy as np

from .._rng import as_rng
from ..arrangement import Arrangement
from ..shape import Shape

__all__ = ["grid", "stripes", "rings", "apples", "stones", "EXEMPLARS"]


def _poisson(rng: np.random.Generator, w: float, h: float, dmin: float, avoid: np.ndarray | None = None, avoid_d: float = 0.0, passes: int = 16) -> np.ndarray:
    """Poisson-disk points in ``[0, w) x [0, h)``, none closer than ``dmin``, and none
    within ``avoid_d`` of a point of ``avoid``.

    The library's one sampler (:func:`strew.pack.poisson_disk`, Bridson's, issue 15
    point 5) rather than a dart thrower of its own. Its sets are maximal but a little
    sparser than the 2,500-4,000 darts thrown before (apples of seeds 0-2: 26-30 in the
    160-unit square against 30-32). With ``avoid`` (the voids between apples), the
    square is sampled again in up to ``passes`` passes, each pass's points kept where
    they keep their distances from ``avoid`` and from the points kept so far (a pass's
    own points are ``dmin`` apart already), until a pass adds none: the gaps around
    ``avoid`` fill up as the dart thrower filled them.
    """
    from ..pack import poisson_disk  # deferred: importing strew.synth stays light

    pts = poisson_disk((float(w), float(h)), dmin, rng=rng)
    if avoid is None or not len(avoid):
        return np.asarray(pts, dtype=float).reshape(-1, 2)
    avoid = np.asarray(avoid, dtype=float).reshape(-1, 2)
    kept = np.zeros((0, 2))
    for i in range(passes):
        if i:
            pts = poisson_disk((float(w), float(h)), dmin, rng=rng)
        ok = ((pts[:, None, :] - avoid[None, :, :]) ** 2).sum(axis=2).min(axis=1) >= avoid_d * avoid_d
        if len(kept):
            ok &= ((pts[:, None, :] - kept[None, :, :]) ** 2).sum(axis=2).min(axis=1) >= dmin * dmin
        if not ok.any():
            break
        kept = np.concatenate([kept, pts[ok]])
    return kept


def grid(n: int = 12, spacing: float = 10.0, side: float = 6.0, jitter: float = 0.3, rng=0) -> Arrangement:
    """An n x n grid of squares with a little positional jitter."""
    g = np.mgrid[0:n, 0:n].reshape(2, -1).T * spacing
    g = g + as_rng(rng).normal(0.0, jitter, g.shape)
    shapes = {"square": Shape.rectangle(side, side, style={"fill": "#5a7d9a"})}
    return Arrangement(shapes, np.zeros(len(g), int), g[:, 0], g[:, 1], meta={"exemplar": "grid"})


def stripes(n: int = 14, spacing: float = 8.0, rng=0) -> Arrangement:
    """Vertical stripes: columns of dots alternating with columns of bars."""
    g = np.mgrid[0:n, 0:n].reshape(2, -1).T * spacing
    g = g + as_rng(rng).normal(0.0, 0.2, g.shape)
    kind = (np.arange(n * n) // n) % 2
    shapes = {"dot": Shape.circle(2.5, style={"fill": "#c0504d"}), "bar": Shape.rectangle(5.0, 2.5, style={"fill": "#4f81bd"})}
    return Arrangement(shapes, kind, g[:, 0], g[:, 1], meta={"exemplar": "stripes"})


def rings(nx: int = 4, ny: int = 4, radius: float = 16.0, tiles: int = 12, rng=0) -> Arrangement:
    """Rings of glass tiles on a hexagonal lattice, each with a hub (after Fig. 15a)."""
    pts, kinds, rots = [], [], []
    step = 2 * radius + 8.0
    for j in range(ny):
        for i in range(nx):
            c = np.array([i * step + (step / 2 if j % 2 else 0.0), j * step * np.sqrt(3) / 2])
            pts.append(c)
            kinds.append(1)
            rots.append(0.0)
            t = np.linspace(0, 2 * np.pi, tiles, endpoint=False)
            pts.extend(c + radius * np.c_[np.cos(t), np.sin(t)])
            kinds += [0] * tiles
            rots += list(t + np.pi / 2)
    p = np.asarray(pts)
    shapes = {"tile": Shape.rectangle(7.0, 3.0, style={"fill": "#2e8b87"}), "hub": Shape.circle(4.0, style={"fill": "#e0a030"})}
    return Arrangement(shapes, kinds, p[:, 0], p[:, 1], rots, meta={"exemplar": "rings"})


def apples(size: float = 160.0, rng=0, voids: bool = True) -> Arrangement:
    """Sparse apples with void elements in the gaps between them (§5.6, Fig. 12)."""
    rng = as_rng(rng)
    a = _poisson(rng, size, size, 26.0)
    apple = Shape.circle(5.0, style={"fill": "#b22222"})
    if not voids:
        return Arrangement({"apple": apple}, np.zeros(len(a), int), a[:, 0], a[:, 1], meta={"exemplar": "apples"})
    v = _poisson(rng, size, size, 12.0, avoid=a, avoid_d=14.0)
    p = np.r_[a, v]
    kind = np.r_[np.zeros(len(a), int), np.ones(len(v), int)]
    void = np.r_[np.zeros(len(a), bool), np.ones(len(v), bool)]
    shapes = {"apple": apple, "void": Shape.circle(4.0, style={"fill": "#dddddd"})}
    return Arrangement(shapes, kind, p[:, 0], p[:, 1], columns={"void": void}, meta={"exemplar": "apples"})


def stones(scale: float = 1.0, size: float = 120.0, rng=0) -> Arrangement:
    """Roughly round stones: ``scale`` 1 for large ones, about 0.25 for pebbles."""
    rng = as_rng(rng)
    p = _poisson(rng, size, size, 22.0 * scale)
    t = np.linspace(0, 2 * np.pi, 9, endpoint=False)
    blob = np.c_[np.cos(t), 0.8 * np.sin(t)] * 8.0 * scale
    name = "stone" if scale >= 0.5 else "pebble"
    color = "#8a8f98" if scale >= 0.5 else "#c2b280"
    rot = rng.uniform(0, np.pi, len(p))
    return Arrangement({name: Shape.polygon(blob, style={"fill": color})}, np.zeros(len(p), int), p[:, 0], p[:, 1], rot, meta={"exemplar": name})


EXEMPLARS = {"rings": rings, "grid": grid, "stripes": stripes, "apples": apples}
