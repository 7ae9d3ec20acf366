"""Example-based growth on a surface (Ijiri et al. 2008 §5 on a mesh; issue 20 point 3).

The planar growth of :mod:`strew.grow` carried to a mesh the way
:mod:`strew.surface._synth` carries synthesis (Davison et al. §5.7):

* **frame**: every seed and element has the orientation field's tangent ``t`` and
  ``b = n x t``; exemplar +x is ``t`` and exemplar +y is ``-b``. Matching (§5.2) runs in
  that frame, so growth is the flow-field mode of §5.3 with the orientation field as the
  flow (the reference is turned to the field's direction at the seed).
* **target neighbourhood** w(e_tar): the placed elements joined to the seed, as exemplar
  offsets through the chart of :func:`strew.surface._synth._chart` (the tangent-plane
  projection stretched to the chord's length; see that module's notes).
* **local growth** (§5.4): the unpaired members of the matched reference ring are put
  out as new seeds by the geodesic walk of §5.7 from the seed in the field's frame
  (:meth:`_Surface.walk`); a new seed within ``l_short`` (half the reference's shortest
  edge) of an existing element or seed is not made, and the edge goes to that one
  (Fig. 6b); consecutive ring members are joined by edges (Fig. 2g).
* **seeding order** (§5.1): the seed nearest the initial seed first, by geodesic
  distance (potpourri3d's heat method).
* **overlap** is tested with bounding spheres in 3D, as Davison et al. do on surfaces: a
  seed whose sphere meets a placed element's is not placed (dies).

Departures from Ijiri et al.: no windowed relaxation (§5.5) on the surface; instead the
seed is moved before its ring is put out, by the mean offset between its placed
neighbours and the paired reference neighbours (at most ``l_short``), the least-squares
translation of the ring fit (§5.5's Eq. 5 for the seed alone), so that the error does
not accumulate from ring to ring. No angle (Fig. 6c), edge-crossing (6d) or long-edge
(6e) heuristics: the merge within ``l_short`` and the sphere test keep elements apart.
Collision radii are the elements' bounding radii, capped at just under half the
distance to their nearest neighbour in the exemplar (an exemplar whose outlines nearly
touch, such as a lattice of scales, would otherwise have overlapping spheres already).
"""

from __future__ import annotations

import heapq
from collections.abc import Callable
from typing import Any

import numba
import numpy as np
from scipy.spatial import cKDTree

from .._errors import InputError
from .._progress import Reporter
from .._version import __version__
from ..arrangement import Arrangement
from ._deps import require
from ._field import OrientationField, orientation_field
from ._mesh import load_mesh
from ._synth import _chart, _insert, _Surface, _unlink

__all__ = ["grow"]

SEED, ELEMENT, DEAD = 0, 1, 2
#: rotation-mode fit (as strew.grow's flow mode): the error per radian of turning away
#: from the neighbours' frame, in mean edge lengths, and the largest turn from it
_FRAME_WEIGHT = 3.0
_MAX_TURN = np.pi / 18


@numba.njit(cache=True)
def _probe(q, rq, md, seeds, cover, skip, P, R, K, ST, heads, nxt, origin, h, dims):
    """Around point ``q``: whether a sphere (q, rq) meets a placed element's (other than
    ``skip``) or a centre lies closer than ``md[kind]`` (elements; with ``seeds`` also
    seeds), and the nearest live element or seed closer than ``cover`` (-1: none)."""
    c0 = min(max(int((q[0] - origin[0]) / h), 0), dims[0] - 1)
    c1 = min(max(int((q[1] - origin[1]) / h), 0), dims[1] - 1)
    c2 = min(max(int((q[2] - origin[2]) / h), 0), dims[2] - 1)
    hit = False
    best = -1
    bd = cover * cover
    for ix in range(max(c0 - 1, 0), min(c0 + 2, dims[0])):
        for iy in range(max(c1 - 1, 0), min(c1 + 2, dims[1])):
            for iz in range(max(c2 - 1, 0), min(c2 + 2, dims[2])):
                j = heads[(ix * dims[1] + iy) * dims[2] + iz]
                while j >= 0:
                    if j != skip and ST[j] != 2:
                        d0 = q[0] - P[j, 0]
                        d1 = q[1] - P[j, 1]
                        d2 = q[2] - P[j, 2]
                        dd = d0 * d0 + d1 * d1 + d2 * d2
                        if ST[j] == 1 or seeds:
                            lim = md[K[j]]
                            if ST[j] == 1:
                                lim = max(lim, rq + R[j])
                            if dd < lim * lim:
                                hit = True
                        if dd < bd:
                            bd = dd
                            best = j
                    j = nxt[j]
    return hit, best


def _collision_radii(ex: Arrangement) -> np.ndarray:
    r = np.asarray(ex.radii, dtype=float)
    if len(ex) >= 2:
        d, _ = cKDTree(ex.xy).query(ex.xy, k=2)
        r = np.minimum(r, 0.45 * d[:, 1])
    return r


def _closest_approach(ex: Arrangement) -> np.ndarray:
    """(kinds, kinds) the closest distance between elements of two kinds in the exemplar
    (0 where a pair never occurs within its neighbourhoods)."""
    nk = len(ex.kinds)
    out = np.full((nk, nk), np.inf)
    xy, kind = ex.xy, np.asarray(ex.kind)
    if len(xy) >= 2:
        tree = cKDTree(xy)
        d, j = tree.query(xy, k=min(len(xy), 13))
        for c in range(1, d.shape[1]):
            np.minimum.at(out, (kind, kind[j[:, c]]), d[:, c])
    out = np.minimum(out, out.T)
    return np.where(np.isfinite(out), out, 0.0)


class _SurfaceGrower:
    def __init__(self, ref: Any, surf: _Surface, scale: float, rng: np.random.Generator, jitter_scale: float,
                 jitter_rotation: float) -> None:
        self.ref = ref
        self.surf = surf
        self.scale = float(scale)
        self.rng = rng
        self.jitter_scale = float(jitter_scale)
        self.jitter_rotation = float(jitter_rotation)
        ex = ref.exemplar
        self.ex = ex
        self.rings = ref.ring_arrays()
        self.ex_kind = np.asarray(ex.kind, dtype=np.int64)
        self.ex_rc = _collision_radii(ex) * self.scale
        self.l_short = 0.5 * float(ref.shortest_edge) * self.scale
        self.l_mean = float(ref.mean_edge)  # exemplar units (the charts' unit)
        # as the planar growth's too_close_in_kind: no two centres closer than the
        # exemplar ever has their kinds (x 0.95)
        self.min_dist = np.ascontiguousarray(_closest_approach(ex) * 0.95 * self.scale)
        ids = self.rings["ids"]
        nk = len(ex.kinds)
        self.kind_cand = [self.ex_kind[ids] == k for k in range(nk)]
        self.all_cand = np.ones(len(ids), bool)
        self.n = 0
        cap = 1024
        self.P = np.zeros((cap, 3))
        self.face = np.zeros(cap, np.int64)
        self.bary = np.zeros((cap, 3))
        self.N = np.zeros((cap, 3))
        self.T = np.zeros((cap, 3))
        self.kind = np.zeros(cap, np.int64)
        self.sub = np.zeros(cap, np.int64)
        self.R = np.zeros(cap)
        self.ST = np.zeros(cap, np.int8)
        self.scl = np.ones(cap)
        self.rot = np.zeros(cap)
        self.theta = np.zeros(cap)  # the ring fit's turn from the field's frame (§5.3)
        self.adj: list[set[int]] = []
        self.order: list[int] = []  # elements in the order placed
        reach = max(2.0 * float(self.ex_rc.max(initial=0.0)), self.l_short, 1e-12)
        V = surf.V
        lo = V.min(axis=0) - reach
        span = np.maximum(V.max(axis=0) + reach - lo, 1e-12)
        self.g_origin = lo
        self.g_h = max(reach * 1.0001, float(span.max()) / 128.0)
        self.g_dims = np.maximum(np.ceil(span / self.g_h).astype(np.int64), 1)
        self.heads = np.full(int(np.prod(self.g_dims)), -1, np.int64)
        self.nxt = np.full(cap, -1, np.int64)
        self.heap: list[tuple[float, int, int]] = []
        self.dist: np.ndarray | None = None

    def _reserve(self, n: int) -> None:
        cap = len(self.kind)
        if n <= cap:
            return
        new = max(n, 2 * cap)
        for name in ("P", "face", "bary", "N", "T", "kind", "sub", "R", "ST", "scl", "rot", "theta", "nxt"):
            old = getattr(self, name)
            arr = np.full((new, *old.shape[1:]), -1 if name == "nxt" else 0, dtype=old.dtype)
            arr[: self.n] = old[: self.n]
            setattr(self, name, arr)

    def _frame_at(self, i: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        t = self.T[i]
        return self.P[i], t, np.cross(self.N[i], t)

    def _add_seed(self, face: int, bary: np.ndarray, p: np.ndarray, kind: int, sub: int) -> int:
        i = self.n
        self._reserve(i + 1)
        n, t = self.surf.frames(np.array([face]), bary[None])
        self.P[i], self.face[i], self.bary[i], self.N[i], self.T[i] = p, face, bary, n[0], t[0]
        self.kind[i], self.sub[i], self.ST[i] = kind, sub, SEED
        self.R[i] = self.ex_rc[sub] if sub >= 0 else 0.0
        self.adj.append(set())
        _insert(i, p, self.heads, self.nxt, self.g_origin, self.g_h, self.g_dims)
        self.n += 1
        d = 0.0
        if self.dist is not None:
            d = float(bary @ self.dist[self.surf.F[face]])
        heapq.heappush(self.heap, (d, i, i))
        return i

    def _move(self, i: int, face: int, bary: np.ndarray, p: np.ndarray) -> None:
        _unlink(i, self.P[i], self.heads, self.nxt, self.g_origin, self.g_h, self.g_dims)
        n, t = self.surf.frames(np.array([face]), bary[None])
        self.P[i], self.face[i], self.bary[i], self.N[i], self.T[i] = p, face, bary, n[0], t[0]
        _insert(i, p, self.heads, self.nxt, self.g_origin, self.g_h, self.g_dims)

    def _link(self, a: int, b: int) -> None:
        if a != b:
            self.adj[a].add(b)
            self.adj[b].add(a)

    def _probe(self, q: np.ndarray, kind: int, rq: float, cover: float, skip: int, seeds: bool) -> tuple[bool, int]:
        return _probe(q, rq, self.min_dist[kind], seeds, cover, skip, self.P, self.R, self.kind, self.ST, self.heads, self.nxt,
                      self.g_origin, self.g_h, self.g_dims)

    def _walk(self, i: int, off: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """m_p from element ``i``: exemplar offsets ``off`` (m, 2) to surface points."""
        _, t, b = self._frame_at(i)
        off = np.asarray(off, dtype=float).reshape(-1, 2) * self.scale
        dirs = off[:, :1] * t - off[:, 1:2] * b
        m = len(off)
        return self.surf.walk(np.full(m, self.face[i]), np.repeat(self.bary[i][None], m, axis=0), dirs)

    def start(self, point: np.ndarray, start_kind: int | None) -> None:
        f0, b0, p0 = self.surf.locate(point.reshape(1, 3))
        # the heat method's geodesic distance from the initial seed orders the seeds (§5.1)
        pp3d = require("potpourri3d")
        v0 = int(self.surf.F[f0[0]][int(np.argmax(b0[0]))])
        self.dist = np.asarray(pp3d.MeshHeatMethodDistanceSolver(self.surf.V, self.surf.F).compute_distance(v0))
        ids = self.rings["ids"]
        cand = np.arange(len(ids))
        if start_kind is not None:
            cand = cand[self.ex_kind[ids] == start_kind]
        # the reference nearest the exemplar's centre (as the planar growth's first seed)
        xy = self.ex.xy[ids[cand]]
        c = cand[int(np.argmin(np.hypot(*(xy - self.ex.xy.mean(axis=0)).T)))]
        r = int(ids[c])
        self._add_seed(int(f0[0]), b0[0], p0[0], int(self.ex_kind[r]), r)

    def step(self, s: int) -> None:
        """§5.2 and §5.4 for seed ``s``."""
        from ..grow import match_references, order_target

        if self.ST[s] != SEED:
            return
        p0, t0, b0 = self._frame_at(s)
        nb = np.fromiter((j for j in self.adj[s] if self.ST[j] == ELEMENT), dtype=np.int64)
        rings = self.rings
        kind = int(self.kind[s])
        cand = self.kind_cand[kind] if kind >= 0 and self.kind_cand[kind].any() else self.all_cand
        if len(nb):
            rel = _chart(p0, t0, b0, self.P[nb], self.scale)
            o = order_target(rel)
            nb, rel = nb[o], rel[o]
            n_max = int(rings["n"][cand].max())
            if len(nb) > n_max:  # as the planar growth: the nearest n_max neighbours
                near = np.sort(np.argsort(np.hypot(rel[:, 0], rel[:, 1]), kind="stable")[:n_max])
                nb, rel = nb[near], rel[near]
                o = order_target(rel)
                nb, rel = nb[o], rel[o]
        else:
            rel = np.zeros((0, 2))
        if len(nb) == 0 and self.sub[s] >= 0 and np.any(rings["ids"] == self.sub[s]):
            # the first seed: its own reference
            a = int(np.flatnonzero(rings["ids"] == self.sub[s])[0])
            k = 0
            th = 0.0
        else:
            # the neighbours' frames carried on (circular mean of their turns from the field)
            # Not in the paper: each neighbour's lattice direction (its turn from the field
            # at its own place) is carried to the seed by projection on the seed's tangent
            # plane (parallel transport over one edge, to first order); the field's own turn
            # between the two is taken out, so that the lattice does not follow the field
            # where it turns against parallel transport (curvature, singularities).
            tj = self.T[nb] - np.outer(self.T[nb] @ self.N[s], self.N[s])
            f = self.theta[nb] + np.arctan2(-(tj @ b0), tj @ t0)  # exemplar +y is -b
            frame = float(np.arctan2(np.sin(f).sum(), np.cos(f).sum())) if len(nb) else 0.0
            err, shift, theta = match_references(rings, rel, self.kind[nb], self.sub[nb], mode="rotate", candidates=cand,
                                                 frame_theta=frame, frame_weight=_FRAME_WEIGHT * self.l_mean,
                                                 max_turn=_MAX_TURN, keep_frame=3)
            best = float(err.min()) if len(err) else np.inf
            if not np.isfinite(best):
                self.ST[s] = DEAD
                return
            ties = np.flatnonzero(err <= best + 1e-9 * max(1.0, abs(best)))
            a = int(ties[self.rng.integers(len(ties))]) if len(ties) > 1 else int(ties[0])
            k = int(shift[a])
            th = float(theta[a])
        r = int(rings["ids"][a])
        n_ring = int(rings["n"][a])
        ring = rings["sub"][a, :n_ring]
        c_, s_ = np.cos(th), np.sin(th)
        ref_rel = rings["rel"][a, :n_ring] @ np.array([[c_, s_], [-s_, c_]])
        paired = {(k + i) % n_ring: int(nb[i]) for i in range(len(nb))}
        if len(nb) >= 2:
            # the ring fit's translation (see module notes), at most l_short
            c = np.mean(rel - ref_rel[[(k + i) % n_ring for i in range(len(nb))]], axis=0)
            lim = self.l_short / self.scale
            norm = float(np.hypot(*c))
            if norm > lim:
                c *= lim / norm
            if norm > 0:
                f, bb, q, done = self._walk(s, c[None])
                if done[0]:
                    self._move(s, int(f[0]), bb[0], q[0])
        rc = float(self.ex_rc[r])
        hit, _ = self._probe(self.P[s], int(self.ex_kind[r]), rc, 0.0, s, False)
        if hit and not self._nudge(s, int(self.ex_kind[r]), rc):
            self.ST[s] = DEAD
            return
        self.ST[s] = ELEMENT
        self.kind[s], self.sub[s], self.R[s] = self.ex_kind[r], r, rc
        scl = 1.0
        rot = 0.0
        if self.jitter_scale > 0:
            scl = float(1.0 + self.rng.uniform(-self.jitter_scale, self.jitter_scale))
        if self.jitter_rotation > 0:
            rot = float(self.rng.uniform(-self.jitter_rotation, self.jitter_rotation))
        self.scl[s], self.rot[s], self.theta[s] = scl, rot + th, th
        self.order.append(s)
        # §5.4: the unpaired ring members become seeds
        free = [j for j in range(n_ring) if j not in paired]
        slot = dict(paired)
        if free:
            f, bb, q, done = self._walk(s, ref_rel[free])
            for m, j in enumerate(free):
                if not done[m]:
                    continue  # beyond the mesh's boundary
                e = int(ring[j])
                hit, near = self._probe(q[m], int(self.ex_kind[e]), float(self.ex_rc[e]), self.l_short, -1, False)
                if near >= 0:
                    slot[j] = near  # Fig. 6b: join the existing element or seed
                    continue
                if hit:
                    continue
                slot[j] = self._add_seed(int(f[m]), bb[m], q[m], int(self.ex_kind[e]), e)
        for j, o in slot.items():
            self._link(s, o)
            nxt = slot.get((j + 1) % n_ring)
            if nxt is not None and (n_ring > 2):
                self._link(o, nxt)

    def _nudge(self, s: int, kind: int, rc: float) -> bool:
        """As the planar growth's nudge: a seed that would overlap or crowd may move up to
        ``l_short / 4`` (12 directions)."""
        _, t, b = self._frame_at(s)
        ang = np.arange(12) * (np.pi / 6)
        for rad in (0.25 * self.l_short,):
            pts = self.P[s] + rad * (np.cos(ang)[:, None] * t + np.sin(ang)[:, None] * b)
            f, bb, q = self.surf.locate(pts)
            for m in range(len(q)):
                hit, _ = self._probe(q[m], kind, rc, 0.0, s, False)
                if not hit:
                    self._move(s, int(f[m]), bb[m], q[m])
                    return True
        return False

    def run(self, count: int | None, rep: Reporter) -> None:
        while self.heap:
            if count is not None and len(self.order) >= count:
                break
            _, _, s = heapq.heappop(self.heap)
            self.step(s)
            rep.tick(len(self.order))

    def to_arrangement(self, meta: dict) -> Arrangement:
        idx = np.asarray(self.order, dtype=np.int64)
        ex = self.ex
        sub = self.sub[idx]
        P, N, T = self.P[idx], self.N[idx], self.T[idx]
        B = np.cross(N, T)
        th = np.asarray(ex.rotation, dtype=float)[sub] + self.rot[idx]
        tang = np.cos(th)[:, None] * T - np.sin(th)[:, None] * B
        cols: dict[str, Any] = {
            "z": P[:, 2], "nx": N[:, 0], "ny": N[:, 1], "nz": N[:, 2],
            "tx": tang[:, 0], "ty": tang[:, 1], "tz": tang[:, 2],
            "radius": self.R[idx] * self.scl[idx], "face": self.face[idx].copy(),
            "reference": sub.copy(),
        }
        for name, col in ex.columns.items():
            if name not in cols:
                cols[name] = np.asarray(col)[sub]
        scale = np.asarray(ex.scale, dtype=float)[sub] * self.scale * self.scl[idx]
        rot = np.arctan2(tang[:, 1], tang[:, 0]) if len(idx) else None
        return Arrangement(ex.shapes, self.ex_kind[sub], P[:, 0], P[:, 1], rot, scale, columns=cols, meta=meta)


def _auto_scale(ref: Any, surf: _Surface, target: int) -> float:
    a = float(ref.mean_edge)
    return float(np.sqrt(surf.area.sum() / (target * a * a * np.sqrt(3.0) / 2.0)))


def grow(
    exemplar: Any,
    mesh: Any,
    *,
    field: OrientationField | str = "smoothest",
    scale: float | None = None,
    count: int | None = None,
    start: Any = None,
    start_kind: str | None = None,
    jitter_scale: float = 0.0,
    jitter_rotation: float = 0.0,
    flips: Any = (),
    rng: int | np.random.Generator | None = None,
    progress: Callable[[int, int | None, str], None] | None = None,
    should_cancel: Callable[[], bool] | None = None,
) -> Arrangement:
    """Grow an arrangement on a surface from one seed (Ijiri et al. §5; module notes).

    Parameters
    ----------
    exemplar : Arrangement or strew.grow.Reference
        The reference arrangement (analysed with :func:`strew.grow.analyze`).
    mesh : path, trimesh.Trimesh or (vertices, faces)
    field : OrientationField or "smoothest"
        The orientation field of Davison et al. §5.7: the exemplar's +x on the surface.
    scale : float, optional
        Mesh units per exemplar unit; default: about 2,000 elements cover the mesh.
    count : int, optional
        Stop at this many elements (default: until no seed is left).
    start : (3,) float, optional
        The initial seed (the nearest surface point); default: a random vertex.
    start_kind : str, optional
        The kind of the initial seed.
    jitter_scale, jitter_rotation : float
        Per-element scale noise (relative) and rotation noise (radians) (§3).
    flips : sequence of (i, j)
        Exemplar edges to flip first (Fig. 3).
    rng, progress, should_cancel
        As :func:`strew.grow.grow`.

    Returns
    -------
    Arrangement
        A surface arrangement (columns ``z nx ny nz tx ty tz``, ``radius`` the bounding
        sphere, ``face``, ``reference`` the exemplar element copied).

    Raises
    ------
    InputError
        A bad mesh, field, scale, count or start kind.

    Examples
    --------
    >>> import trimesh
    >>> from strew.grow._exemplars import hex_exemplar
    >>> m = trimesh.creation.icosphere(subdivisions=3)
    >>> a = grow(hex_exemplar(), m, scale=0.02, rng=1)
    >>> len(a) > 200
    True
    """
    from .._method import seed_record
    from ..grow import Reference, analyze

    gen, seed = seed_record(rng)
    mesh = load_mesh(mesh)
    if isinstance(field, str):
        if field != "smoothest":
            raise InputError(f"field: expected an OrientationField or 'smoothest', got {field!r}")
        field = orientation_field(mesh)
    elif not isinstance(field, OrientationField):
        raise InputError(f"field: expected an OrientationField or 'smoothest', got {type(field).__name__}")
    if field.directions.shape != (len(mesh.vertices), 3):
        raise InputError(f"field: has {len(field.directions)} directions, the mesh {len(mesh.vertices)} vertices")
    if isinstance(exemplar, Reference):
        ref = exemplar
    elif isinstance(exemplar, Arrangement):
        ref = analyze(exemplar)
    else:
        raise InputError(f"exemplar: expected an Arrangement or a grow Reference, got {type(exemplar).__name__}")
    for f in flips or ():
        ref = ref.flip(*f)
    if count is not None and (isinstance(count, bool) or not isinstance(count, (int, np.integer)) or count < 1):
        raise InputError(f"count: must be a positive integer, got {count!r}")
    for name, v, hi in (("jitter_scale", jitter_scale, 1.0), ("jitter_rotation", jitter_rotation, np.inf)):
        if not np.isfinite(float(v)) or float(v) < 0 or float(v) >= hi:
            raise InputError(f"{name}: must be in [0, {hi}), got {v!r}")
    kind_id = None
    if start_kind is not None:
        kinds = ref.exemplar.kinds
        if start_kind not in kinds:
            raise InputError(f"start_kind: {start_kind!r} is not a kind of the exemplar ({', '.join(kinds)})")
        kind_id = kinds.index(start_kind)
        if not np.any(np.asarray(ref.exemplar.kind)[ref.ring_arrays()["ids"]] == kind_id):
            raise InputError(f"start_kind: {start_kind!r} has no interior element in the exemplar to start from")
    surf = _Surface(mesh, field)
    if scale is None:
        scale = _auto_scale(ref, surf, 2000)
    else:
        try:
            scale = float(scale)
        except (TypeError, ValueError):
            raise InputError(f"scale: must be a positive number, got {scale!r}") from None
        if not np.isfinite(scale) or scale <= 0:
            raise InputError(f"scale: must be a positive number, got {scale!r}")
    from .._limits import check_elements

    a = float(ref.mean_edge) * scale
    check_elements(int(surf.area.sum() / max(a * a * np.sqrt(3) / 2, 1e-300)), "surface grow")
    if start is None:
        point = surf.V[int(gen.integers(len(surf.V)))]
    else:
        try:
            point = np.asarray(start, dtype=float).reshape(3)
        except (TypeError, ValueError):
            raise InputError(f"start: must be a 3D point (x, y, z), got {start!r}") from None
        if not np.all(np.isfinite(point)):
            raise InputError("start: NaN or inf coordinate")
    g = _SurfaceGrower(ref, surf, scale, gen, jitter_scale, jitter_rotation)
    rep = Reporter(progress, should_cancel, message="surface grow")
    g.start(point, kind_id)
    g.run(count, rep)
    rep.done(len(g.order))
    meta = {
        "generator": f"strew {__version__}",
        "method": "surface.grow",
        **seed,
        "params": {
            "scale": float(scale), "count": count, "start": None if start is None else point.tolist(), "start_kind": start_kind,
            "jitter_scale": float(jitter_scale), "jitter_rotation": float(jitter_rotation),
            "flips": [list(map(int, f)) for f in (flips or ())], "field": field.design,
        },
        "surface": {"vertices": int(len(surf.V)), "faces": int(len(surf.F)), "area": float(surf.area.sum()),
                    "bounds": np.asarray(mesh.bounds, dtype=float).tolist()},
    }
    return g.to_arrangement(meta)
