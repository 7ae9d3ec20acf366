"""Placement with exact collision tests (Sakurai & Miyata §3.2, steps 1-3).

A :class:`Placer` holds the exclusive regions placed so far and tries candidate
positions in order. Each candidate gets a kind (cyclic, as in §3.2, or drawn by
weight), a rotation and a scale; it is accepted when its exclusive region and element
lie wholly inside the domain and its exclusive region intersects no placed one; else the
placement is cancelled. Tests are exact on the polygons: a prepared domain, and bulk
``STRtree`` queries of a whole batch of candidates against the placed regions, with the
few regions accepted within the batch checked directly.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import shapely

from ..region import Region
from ._exclusive import ExclusiveRegion, transform_many

__all__ = ["Placer"]

# Regions accepted within one batch are checked one by one; past this many, the
# STRtree is rebuilt and the rest of the batch re-queried in bulk.
_PENDING_LIMIT = 48


class Placer:
    """Placed exclusive regions and the exact tests for new ones.

    Parameters
    ----------
    kinds : sequence of ExclusiveRegion
    region : Region
    weights : (K,) float, optional
        Kind probabilities; None picks kinds cyclically (§3.2).
    max_failures : int
        Stop once this many consecutive placements have been cancelled.
    periodic : (x0, y0, W, H), optional
        Place on the torus of this repeat tile (issue 18; ``region`` is its rectangle):
        no containment test, and each placed region also blocks with its wrapped
        images, so that candidates (whose reference points lie in the tile) are tested
        across the wrap.
    """

    def __init__(self, kinds: Sequence[ExclusiveRegion], region: Region, weights: np.ndarray | None, max_failures: int,
                 periodic: Sequence[float] | None = None) -> None:
        self.kinds = list(kinds)
        self.region = region
        self.weights = weights
        self.max_failures = max_failures
        self.next_kind = 0  # cyclic selection: the kind to place next
        self.consecutive = 0  # consecutive cancellations
        self.trials = 0
        # exclusive regions placed by this placer's own tests (naive, fill-gap Step 1);
        # fill-gap Step 2 adds kinds and poses only (its compiled store holds the rings)
        self.geoms: list[shapely.Geometry] = []
        self.kind: list[int] = []
        self.xy: list[tuple[float, float]] = []
        self.rotation: list[float] = []
        self.scale: list[float] = []
        self._tree: shapely.STRtree | None = None
        self._tree_n = 0
        self.periodic = None if periodic is None else tuple(float(v) for v in periodic)
        # wrapped images of the placed regions that reach within the largest circumscribed
        # radius of the tile (periodic only)
        self._images: list[shapely.Geometry] = []
        self._reach = max(k.radius * k.scale[1] for k in self.kinds) if self.kinds else 0.0

    @property
    def done(self) -> bool:
        """True once the consecutive-cancellation limit is reached."""
        return self.consecutive >= self.max_failures

    def __len__(self) -> int:
        return len(self.kind)

    def _tree_now(self) -> shapely.STRtree | None:
        if self._tree_n != len(self.geoms):
            obstacles = self.geoms + self._images
            self._tree = shapely.STRtree(np.array(obstacles, dtype=object)) if obstacles else None
            self._tree_n = len(self.geoms)
        return self._tree

    def wrapped_images(self, geom: shapely.Geometry) -> list[shapely.Geometry]:
        """Copies of ``geom`` by the tile's lattice translations (3 x 3 less the centre)
        whose boxes reach within the largest circumscribed radius of the tile."""
        if self.periodic is None:
            return []
        x0, y0, w, h = self.periodic
        reach = self._reach
        b = shapely.bounds(geom)
        out = []
        for i in (-1, 0, 1):
            for j in (-1, 0, 1):
                if i == 0 and j == 0:
                    continue
                dx, dy = i * w, j * h
                if (b[0] + dx > x0 + w + reach or b[2] + dx < x0 - reach
                        or b[1] + dy > y0 + h + reach or b[3] + dy < y0 - reach):
                    continue
                out.append(shapely.transform(geom, lambda p, dx=dx, dy=dy: p + (dx, dy)))
        return out

    def draw_kinds(self, rng: np.random.Generator, m: int) -> np.ndarray | None:
        """(m,) kinds drawn by weight, or None in cyclic mode."""
        if self.weights is None:
            return None
        return rng.choice(len(self.kinds), size=m, p=self.weights)

    def try_batch(
        self,
        xy: np.ndarray,
        u_rot: np.ndarray,
        u_scale: np.ndarray,
        kinds: np.ndarray | None = None,
        *,
        collide: bool = True,
    ) -> list[int]:
        """Try candidates in order; return the indices of the placed elements.

        Parameters
        ----------
        xy : (m, 2) float
            Where the bounding-box centres of the exclusive regions go (T of Eq. 1).
        u_rot, u_scale : (m,) float in [0, 1)
            Uniform numbers mapped into each kind's rotation and scale range, so that
            random draws do not depend on which kind a candidate ends up with.
        kinds : (m,) int, optional
            Kinds drawn by weight; None: cyclic.
        collide : bool
            False skips the collision test (Step 1 of fill-gap, where the Poisson-disk
            circles already guarantee no overlap, §4.1).

        Returns
        -------
        list of int
            Indices (into the placed elements) of the new ones.
        """
        m = len(xy)
        placed: list[int] = []
        if m == 0:
            return placed
        tree = self._tree_now() if collide else None
        pending: list[shapely.Geometry] = []
        # per kind, lazily: geometry, ok-so-far, rotation, scale (for candidates j..m-1)
        cache: dict[int, tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]] = {}

        def evaluate(k: int, start: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
            ex = self.kinds[k]
            idx = np.arange(start, m) if kinds is None else start + np.flatnonzero(kinds[start:] == k)
            rot = np.zeros(m)
            sc = np.zeros(m)
            rot[idx] = ex.rotation[0] + u_rot[idx] * (ex.rotation[1] - ex.rotation[0])
            sc[idx] = ex.scale[0] + u_scale[idx] * (ex.scale[1] - ex.scale[0])
            pos = xy
            geoms = np.empty(m, dtype=object)
            ok = np.zeros(m, dtype=bool)
            body = transform_many(ex.body, pos[idx], rot[idx], sc[idx])
            hull = body if ex.hull is ex.body else transform_many(ex.hull, pos[idx], rot[idx], sc[idx])
            geoms[idx] = body
            if self.periodic is None:
                inside = np.asarray(shapely.covers(self.region.prepared, hull), dtype=bool)
            else:  # the torus has no boundary
                inside = np.ones(len(idx), dtype=bool)
            ok[idx] = inside
            if tree is not None and inside.any():
                sub = idx[inside]
                hit = tree.query(geoms[sub], predicate="intersects")[0]
                ok[sub[np.unique(hit)]] = False
            return geoms, ok, rot, sc, pos

        for j in range(m):
            k = self.next_kind if kinds is None else int(kinds[j])
            if k not in cache:
                cache[k] = evaluate(k, j)
            geoms, ok, rot, sc, pos = cache[k]
            good = bool(ok[j])
            self.trials += 1
            if good and pending:
                good = not bool(shapely.intersects(geoms[j], np.array(pending, dtype=object)).any())
            if not good:
                self.consecutive += 1
                if self.consecutive >= self.max_failures:
                    break
                continue
            self.consecutive = 0
            placed.append(len(self.geoms))
            self.geoms.append(geoms[j])
            images = self.wrapped_images(geoms[j])
            self._images.extend(images)
            self.kind.append(k)
            self.xy.append((float(pos[j, 0]), float(pos[j, 1])))
            self.rotation.append(float(rot[j]))
            self.scale.append(float(sc[j]))
            if collide:
                pending.append(geoms[j])
                pending.extend(images)
            if kinds is None and len(self.kinds) > 1:
                self.next_kind = (self.next_kind + 1) % len(self.kinds)
            if len(pending) > _PENDING_LIMIT:
                tree = self._tree_now()
                pending = []
                cache = {}
        return placed
