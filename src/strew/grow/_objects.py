"""The grower's objects: seeds and elements, their ghost images on a torus, and
their connectivity (Ijiri et al. 2008, §5; edges of §4's Delaunay graph).

Split out of :mod:`strew.grow._growth` (issue 15); :class:`_Objects` is a base of
:class:`strew.grow._growth._Grower` and holds no state of its own.
"""

from __future__ import annotations

import heapq
import math
from collections.abc import Sequence

import shapely

DEAD, SEED, ELEMENT = 0, 1, 2
#: A smaller kind leans on larger ones (see ``_Grower.lean_ok``) when 90% of its elements
#: have their nearest larger element within this factor of the median distance to it.
LEAN_SPREAD = 1.15
#: Elements the growth must not overlap but does not own (a scene the spray paints over).
OBSTACLE = 3
#: bit masks of the state tuples :meth:`_Grower.near` is asked for
_STATE_MASKS: dict[tuple[int, ...], int] = {}
_ELEMENT_OR_OBSTACLE = (1 << ELEMENT) | (1 << OBSTACLE)


class _Objects:
    """Creation, movement and removal of objects, and the edges between them."""

    def _cell(self, x: float, y: float) -> tuple[int, int]:
        return self.index.cell_of(x, y)

    def new_object(self, x: float, y: float, kind: int) -> int:
        """A new seed at (x, y); on a torus, the image at (x, y) of a seed made at its wrapped place."""
        if self.tile is not None:
            x0, y0, w, h = self.tile
            ki, kj = math.floor((x - x0) / w), math.floor((y - y0) / h)
            i = self._new_object(x - ki * w, y - kj * h, kind)
            self._ensure_ghosts(i)
            return self.image(i, (ki, kj))
        return self._new_object(x, y, kind)

    def _new_object(self, x: float, y: float, kind: int) -> int:
        if self.n == len(self.state):
            self._grow_capacity()
        i = self.n
        self.n += 1
        self.pos[i] = (x, y)
        self.xy.append((float(x), float(y)))
        self.state[i] = SEED
        self.kind[i] = kind
        self.adj.append(set())
        self.target.append(None)
        self.geom.append(None)
        self.color.append(None)
        self.orig_of.append(i)
        self.off_of.append((0, 0))
        self.index.insert(i, x, y)
        heapq.heappush(self.heap, (math.hypot(x - self.origin[0], y - self.origin[1]), i))
        self.dirty.add(i)
        if self.use_prio and self.seed_priority(i) > self.none_prio:
            self.hgrid.setdefault((math.floor(x / self.hcell), math.floor(y / self.hcell)), set()).add(i)
        return i

    # -- torus (issue 18) ------------------------------------------------------------------
    def image(self, i: int, off: tuple[int, int]) -> int:
        """The ghost of original ``i`` translated by ``off`` tile periods (made on demand).

        A ghost mirrors its original's state (:meth:`_sync`), is held fixed by the
        relaxation and never grows itself: only originals are on the heap.
        """
        if off == (0, 0):
            return i
        own = self.ghosts.setdefault(i, {})
        g = own.get(off)
        if g is not None:
            return g
        assert self.tile is not None
        _, _, w, h = self.tile
        if self.n == len(self.state):
            self._grow_capacity()
        g = self.n
        self.n += 1
        x, y = self.xy[i]
        gx, gy = x + off[0] * w, y + off[1] * h
        self.pos[g] = (gx, gy)
        self.xy.append((gx, gy))
        self.fixed[g] = True
        self.adj.append(set())
        self.target.append(None)
        self.geom.append(None)
        self.color.append(None)
        self.orig_of.append(i)
        self.off_of.append(off)
        own[off] = g
        self._copy_state(i, g)
        if self.state[g] != DEAD:
            self.index.insert(g, gx, gy)
        # a seed of a higher priority holds back the seeds around its images too (§5.1)
        if self.state[g] == SEED and self.use_prio and self.seed_priority(g) > self.none_prio:
            self.hgrid.setdefault((math.floor(gx / self.hcell), math.floor(gy / self.hcell)), set()).add(g)
        return g

    def _copy_state(self, i: int, g: int) -> None:
        for a in (self.state, self.kind, self.sub, self.rot, self.scl, self.refslot, self.frame):
            a[g] = a[i]
        self.color[g] = self.color[i]
        gi = self.geom[i]
        if gi is None:
            self.geom[g] = None
        else:
            dx, dy = self.xy[g][0] - self.xy[i][0], self.xy[g][1] - self.xy[i][1]
            self.geom[g] = shapely.transform(gi, lambda q: q + (dx, dy))

    def _sync(self, i: int) -> None:
        """Ghosts of ``i`` take its state (placed, died, new outline)."""
        for g in self.ghosts.get(i, {}).values():
            was = self.state[g]
            self._copy_state(i, g)
            if self.state[g] == DEAD and was != DEAD:
                self.index.remove(g)

    def _ensure_ghosts(self, i: int) -> None:
        """Ghosts of original ``i`` wherever one lies within the margin of the tile."""
        x0, y0, w, h = self.tile  # type: ignore[misc]
        m = self.margin
        x, y = self.xy[i]
        for ki in (-1, 0, 1):
            px = x + ki * w
            if px < x0 - m or px > x0 + w + m:
                continue
            for kj in (-1, 0, 1):
                py = y + kj * h
                if (ki or kj) and y0 - m <= py <= y0 + h + m:
                    self.image(i, (ki, kj))

    def has_edge(self, a: int, b: int) -> bool:
        if self.tile is None:
            return b in self.adj[a]
        ia, ib = self.orig_of[a], self.orig_of[b]
        oa, ob = self.off_of[a], self.off_of[b]
        g = self.ghosts.get(ib, {}).get((ob[0] - oa[0], ob[1] - oa[1])) if ob != oa else ib
        return g is not None and g in self.adj[ia]

    def near(self, x: float, y: float, r: float, states: tuple[int, ...] = (SEED, ELEMENT)) -> list[int]:
        """Objects within ``r`` of (x, y) in one of ``states`` (:meth:`GrowIndex.near`)."""
        m = _STATE_MASKS.get(states)
        if m is None:
            m = _STATE_MASKS[states] = sum(1 << s for s in set(states))
        return self.index.near(x, y, r, m)

    def _unhigh(self, i: int) -> None:
        """Take seed ``i`` off the priority grid (it was placed, died or moves)."""
        if self.hgrid:
            x, y = self.xy[i]
            cell = self.hgrid.get((math.floor(x / self.hcell), math.floor(y / self.hcell)))
            if cell is not None:
                cell.discard(i)
            for g in self.ghosts.get(i, {}).values():
                self._unhigh(g)

    def _defer(self, i: int) -> None:
        """Seed ``i`` waits for a seed of a higher priority (§5.1; see ``release_deferred``)."""
        self.deferred.add(i)
        x, y = self.xy[i]
        self.dgrid.setdefault((math.floor(x / self.hcell), math.floor(y / self.hcell)), set()).add(i)

    def _undefer(self, i: int) -> None:
        if i in self.deferred:
            self.deferred.discard(i)
            x, y = self.xy[i]
            self.dgrid[(math.floor(x / self.hcell), math.floor(y / self.hcell))].discard(i)

    def _move(self, i: int, x: float, y: float) -> None:
        if (self.hgrid or self.deferred) and self.state[i] == SEED:
            h = self.hcell
            ox, oy = self.xy[i]
            a, b = (math.floor(ox / h), math.floor(oy / h)), (math.floor(x / h), math.floor(y / h))
            if a != b:
                if i in self.hgrid.get(a, ()):
                    self.hgrid[a].discard(i)
                    self.hgrid.setdefault(b, set()).add(i)
                if i in self.deferred:
                    self.dgrid[a].discard(i)
                    self.dgrid.setdefault(b, set()).add(i)
        ox, oy = self.xy[i]
        self.pos[i] = (x, y)
        self.xy[i] = (float(x), float(y))
        self.index.move(i, ox, oy, x, y)  # a new cell: its edges are listed there too
        if self.tile is not None and self.orig_of[i] == i:
            _, _, w, h = self.tile
            for (ki, kj), g in list(self.ghosts.get(i, {}).items()):
                self._move(g, x + ki * w, y + kj * h)
            self._ensure_ghosts(i)

    # -- edges --------------------------------------------------------------------------
    def add_edge(self, a: int, b: int) -> None:
        if self.tile is None:  # (the plane: straight to the index, the common case)
            oo = self.orig_of
            self.index.add_edge(a, b, oo[a], oo[b])
            return
        # on the torus an edge is kept at both ends: from each original to the image
        # of the other
        ia, ib = self.orig_of[a], self.orig_of[b]
        if ia == ib:
            return
        oa, ob = self.off_of[a], self.off_of[b]
        rel = (ob[0] - oa[0], ob[1] - oa[1])
        self._add_edge(ia, self.image(ib, rel))
        if rel != (0, 0):
            self._add_edge(self.image(ia, (-rel[0], -rel[1])), ib)

    def _add_edge(self, a: int, b: int) -> None:
        self.index.add_edge(a, b, self.orig_of[a], self.orig_of[b])

    def remove_edge(self, a: int, b: int) -> None:
        if self.tile is not None:
            ia, ib = self.orig_of[a], self.orig_of[b]
            oa, ob = self.off_of[a], self.off_of[b]
            rel = (ob[0] - oa[0], ob[1] - oa[1])
            pairs = [(ia, self.ghosts.get(ib, {}).get(rel) if rel != (0, 0) else ib)]
            if rel != (0, 0):
                pairs.append((self.ghosts.get(ia, {}).get((-rel[0], -rel[1])), ib))
            for u, v in pairs:
                if u is not None and v is not None:
                    self._remove_edge(u, v)
            return
        self._remove_edge(a, b)

    def _remove_edge(self, a: int, b: int) -> None:
        self.index.remove_edge(a, b)

    def crosses_edges(self, a: int | None, pa: tuple[float, float], b: int | None, pb: tuple[float, float]) -> bool:
        """Edge collision (§5.4, Fig. 6d): does segment pa-pb cross an existing edge?

        Edges at ``a`` or ``b`` (on the torus: at any of their images) do not count.
        """
        oo = self.orig_of
        if self.tile is None:
            return self.index.crosses_plane(-2 if a is None else oo[a], pa, -2 if b is None else oo[b], pb)
        return self.index.crosses(-2 if a is None else oo[a], pa, -2 if b is None else oo[b], pb, self.tile, self.margin)

    def crosses_boundary(self, pa: Sequence[float], pb: Sequence[float]) -> bool:
        if self.boundary is None:
            return False
        return bool(shapely.intersects(self.boundary, shapely.LineString([pa, pb])))

    def kill(self, i: int) -> None:
        self._unhigh(i)
        for j in list(self.adj[i]):
            self.remove_edge(i, j)
        self.state[i] = DEAD
        self._undefer(i)
        # the dead take no part in any query: off the grid, so that queries stay short
        self.index.remove(i)
        if self.tile is not None:
            self._sync(i)

    # -- geometry guard -----------------------------------------------------------------
