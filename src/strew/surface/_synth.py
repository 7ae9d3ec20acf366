"""Discrete element texture synthesis on a surface (Davison et al. §5.1, §5.4, §5.7, §5.8).

Region growing (Algorithm 1) runs on the mesh with the exemplar analysis of
:mod:`strew.synth` (neighbourhoods, k-coherence sets, free-space vectors, collision
radii: :func:`strew.synth.new_state`) and its compiled matching kernels. What changes on
a surface is the local map m_p of §5.1:

* **m_p** (exemplar offset -> surface point) is the walk of §5.7: from ``p`` in the
  orientation field's frame (exemplar +x along the field's tangent ``t``, exemplar +y
  along ``-b``, ``b = n x t``) along the surface for ``|v| * scale``. It maps the copied
  elements (``p_s + m_{p_s}(p_{e'} - p_{s_e})``) and the free-space points (Eq. 3).
  The walk is a geodesic (potpourri3d's tracer), see :mod:`._walk` for that departure.
* **its inverse** (output neighbour -> exemplar offset), needed to compare a seed's
  neighbourhood with the exemplar's: the chord ``q - p`` projected on the tangent plane
  at ``p`` in the field's frame, stretched back to the chord's length, divided by
  ``scale``. Departure from §5.7, which only states the forward walk: at neighbourhood
  distances (a few element spacings, small against the curvature radius) the chord
  and the geodesic differ by ``O(l^3 / R^2)``; a log map per seed would cost a solve.
* **overlap** is tested with bounding spheres, as in the paper: two elements intersect
  when their centres are closer than ``scale * (rc_p + rc_q)`` (the collision radii of
  :class:`strew.synth.Prepared`, which are the exemplar's bounding radii wherever it
  gives them) or than the learned closest approach of their kinds (``min_dist``), in
  3D (chord) distance.

Tools (§5.4) work with points on the surface: the generative brush (brush points with a
radius: balls about them bound the growth), the filler (a fill point; growth until no
room is left) and the eraser (elements within the radius of the brush points are
removed and their neighbours return to the horizon). View-based synthesis (§5.8): with a
:class:`~strew.surface.Camera`, seeds next to visible free-space points are served
first and only visible free-space points generate; occluded ones follow when nothing
visible is left (or never, with ``view_only``).

Departures, besides the two maps above: the horizon optimisation (§5.2-5.3) is optional
and simplified (one Jacobi step of the least squares with equal weights, moves put back
on the surface and refused where spheres would meet; ``optimize="horizon"``), off by
default: generation alone keeps the exemplar's local pattern within a few per cent
(``benchmarks/surfaces.py``) at a fifth of the cost; seeds are placed
seed by seed (the planar synth's size-class ordering, parents and yielding are
extensions for multi-size exemplars that are not carried over); when the front dies
with room left (another connected component, a gap behind the front) a new patch is
seeded at a random free spot, until none is left.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
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
from ._view import Camera

__all__ = ["SurfaceSynthState", "new_synth_state", "synthesize"]


# -- geometry of one mesh ---------------------------------------------------------------------
class _Surface:
    """Cached geometry: face centroids' k-d tree, vertex normals, the geodesic tracer."""

    def __init__(self, mesh: Any, field: OrientationField) -> None:
        pp3d = require("potpourri3d")
        self.mesh = mesh
        self.V = np.ascontiguousarray(mesh.vertices, dtype=np.float64)
        self.F = np.ascontiguousarray(mesh.faces, dtype=np.int64)
        self.VN = np.asarray(mesh.vertex_normals, dtype=np.float64)
        self.FN = np.asarray(mesh.face_normals, dtype=np.float64)
        self.tri = self.V[self.F]
        self.tree = cKDTree(self.tri.mean(axis=1))
        self.field = field
        self.tracer = pp3d.GeodesicTracer(self.V, self.F).bound_tracer
        self.area = np.asarray(mesh.area_faces, dtype=float)
        self.edge = float(np.mean(mesh.edges_unique_length))
        lo = self.V.min(axis=0)
        self.size = float(np.linalg.norm(self.V.max(axis=0) - lo))
        edges = np.sort(np.concatenate([self.F[:, [0, 1]], self.F[:, [1, 2]], self.F[:, [2, 0]]]), axis=1)
        self.has_boundary = bool(np.any(np.unique(edges, axis=0, return_counts=True)[1] == 1))

    def locate(self, pts: np.ndarray, k: int = 8) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Closest points of the mesh to ``pts`` (near the surface) among the faces of the
        ``k`` nearest centroids: faces, barycentric coordinates, points on those faces."""
        pts = np.ascontiguousarray(pts, dtype=float).reshape(-1, 3)
        m = len(pts)
        if m == 0:
            return np.zeros(0, np.int64), np.zeros((0, 3)), np.zeros((0, 3))
        k = min(k, len(self.F))
        _, cand = self.tree.query(pts, k=k)
        cand = np.ascontiguousarray(np.asarray(cand, dtype=np.int64).reshape(m, k))
        return _closest(pts, cand, self.tri)

    def frames(self, faces: np.ndarray, bary: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Unit normals and the field's unit tangents at points given by face and bary."""
        n = np.einsum("mk,mkj->mj", bary, self.VN[self.F[faces]])
        n /= np.linalg.norm(n, axis=1, keepdims=True).clip(1e-300)
        return n, self.field.at(faces, bary, n)

    def walk(self, faces: np.ndarray, bary: np.ndarray, dirs: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """m_p: from each start (face, bary) along the surface by the 3D tangent vector
        ``dirs`` (its length is the distance walked).

        Returns
        -------
        faces, bary, points
        complete : (m,) bool
            False where the walk was cut short by the mesh's boundary (the point is not
            at distance ``|v|``; callers drop it).
        """
        m = len(faces)
        ends = np.empty((m, 3))
        complete = np.ones(m, bool)
        tr = self.tracer
        big = 2**62
        for i in range(m):
            d = dirs[i]
            if d[0] == 0.0 and d[1] == 0.0 and d[2] == 0.0:
                ends[i] = bary[i] @ self.tri[faces[i]]
                continue
            path = tr.trace_geodesic_from_face(int(faces[i]), bary[i], d, big)
            ends[i] = path[-1]
            if self.has_boundary:
                walked = float(np.sum(np.linalg.norm(np.diff(path, axis=0), axis=1)))
                # the tracer walks d projected on the start face's plane (d is tangent to
                # the interpolated normal), up to 0.08% shorter on a 5k-face sphere: a
                # walk counts as cut by the boundary when it fell short by over 1%
                complete[i] = walked >= (1.0 - 1e-2) * float(np.linalg.norm(d))
        f, b, p = self.locate(ends)
        return f, b, p, complete


@numba.njit(cache=True)
def _closest(pts, cand, tri):
    """Closest point on the candidate triangles (Ericson, Real-Time Collision Detection
    5.1.5) for each point: face, barycentric coordinates, point."""
    m, k = cand.shape
    faces = np.empty(m, np.int64)
    bary = np.empty((m, 3))
    out = np.empty((m, 3))
    for i in range(m):
        best = np.inf
        px, py, pz = pts[i, 0], pts[i, 1], pts[i, 2]
        for jj in range(k):
            f = cand[i, jj]
            ax, ay, az = tri[f, 0, 0], tri[f, 0, 1], tri[f, 0, 2]
            abx, aby, abz = tri[f, 1, 0] - ax, tri[f, 1, 1] - ay, tri[f, 1, 2] - az
            acx, acy, acz = tri[f, 2, 0] - ax, tri[f, 2, 1] - ay, tri[f, 2, 2] - az
            apx, apy, apz = px - ax, py - ay, pz - az
            d1 = abx * apx + aby * apy + abz * apz
            d2 = acx * apx + acy * apy + acz * apz
            bpx, bpy, bpz = apx - abx, apy - aby, apz - abz
            d3 = abx * bpx + aby * bpy + abz * bpz
            d4 = acx * bpx + acy * bpy + acz * bpz
            cpx, cpy, cpz = apx - acx, apy - acy, apz - acz
            d5 = abx * cpx + aby * cpy + abz * cpz
            d6 = acx * cpx + acy * cpy + acz * cpz
            va = d3 * d6 - d5 * d4
            vb = d5 * d2 - d1 * d6
            vc = d1 * d4 - d3 * d2
            if d1 <= 0.0 and d2 <= 0.0:
                v, w = 0.0, 0.0
            elif d3 >= 0.0 and d4 <= d3:
                v, w = 1.0, 0.0
            elif vc <= 0.0 and d1 >= 0.0 and d3 <= 0.0:
                v, w = d1 / (d1 - d3), 0.0
            elif d6 >= 0.0 and d5 <= d6:
                v, w = 0.0, 1.0
            elif vb <= 0.0 and d2 >= 0.0 and d6 <= 0.0:
                v, w = 0.0, d2 / (d2 - d6)
            elif va <= 0.0 and (d4 - d3) >= 0.0 and (d5 - d6) >= 0.0:
                w = (d4 - d3) / ((d4 - d3) + (d5 - d6))
                v = 1.0 - w
            else:
                den = 1.0 / (va + vb + vc)
                v = vb * den
                w = vc * den
            qx = ax + v * abx + w * acx
            qy = ay + v * aby + w * acy
            qz = az + v * abz + w * acz
            dd = (qx - px) ** 2 + (qy - py) ** 2 + (qz - pz) ** 2
            if dd < best:
                best = dd
                faces[i] = f
                bary[i, 0] = 1.0 - v - w
                bary[i, 1] = v
                bary[i, 2] = w
                out[i, 0] = qx
                out[i, 1] = qy
                out[i, 2] = qz
    return faces, bary, out


# -- the 3D sphere grid ------------------------------------------------------------------------
@numba.njit(cache=True)
def _cell_of(p, origin, h, dims):
    c = np.empty(3, np.int64)
    for a in range(3):
        c[a] = min(max(int((p[a] - origin[a]) / h), 0), dims[a] - 1)
    return c


@numba.njit(cache=True)
def _hit(q, rq, skq, cover, P, R, SK, min_dist, heads, nxt, origin, h, dims):
    """Whether a sphere (q, rq) of class skq (-1: none) meets a stored one, or a stored
    centre lies closer than ``cover``."""
    c = _cell_of(q, origin, h, dims)
    for ix in range(max(c[0] - 1, 0), min(c[0] + 2, dims[0])):
        for iy in range(max(c[1] - 1, 0), min(c[1] + 2, dims[1])):
            for iz in range(max(c[2] - 1, 0), min(c[2] + 2, dims[2])):
                j = heads[(ix * dims[1] + iy) * dims[2] + iz]
                while j >= 0:
                    d0 = q[0] - P[j, 0]
                    d1 = q[1] - P[j, 1]
                    d2 = q[2] - P[j, 2]
                    lim = max(rq + R[j], cover)
                    if skq >= 0:
                        lim = max(lim, min_dist[skq, SK[j]])
                    if d0 * d0 + d1 * d1 + d2 * d2 < lim * lim:
                        return True
                    j = nxt[j]
    return False


@numba.njit(cache=True)
def _hits(Q, RQ, SKQ, COV, P, R, SK, min_dist, heads, nxt, origin, h, dims):
    out = np.zeros(Q.shape[0], np.bool_)
    for i in range(Q.shape[0]):
        out[i] = _hit(Q[i], RQ[i], SKQ[i], COV[i], P, R, SK, min_dist, heads, nxt, origin, h, dims)
    return out


@numba.njit(cache=True)
def _insert(i, p, heads, nxt, origin, h, dims):
    c = _cell_of(p, origin, h, dims)
    g = (c[0] * dims[1] + c[1]) * dims[2] + c[2]
    nxt[i] = heads[g]
    heads[g] = i


@numba.njit(cache=True)
def _unlink(i, p, heads, nxt, origin, h, dims):
    """Remove stored sphere i (at p) from its cell's list."""
    c = _cell_of(p, origin, h, dims)
    g = (c[0] * dims[1] + c[1]) * dims[2] + c[2]
    j = heads[g]
    if j == i:
        heads[g] = nxt[i]
        return
    while j >= 0:
        if nxt[j] == i:
            nxt[j] = nxt[i]
            return
        j = nxt[j]


def _chart(p0: np.ndarray, t0: np.ndarray, b0: np.ndarray, q: np.ndarray, scale: float) -> np.ndarray:
    """Inverse of m_p at p0: points ``q`` (m, 3) as exemplar offsets (m, 2) (module notes)."""
    d = q - p0
    u = d @ t0
    w = -(d @ b0)
    proj = np.hypot(u, w)
    chord = np.linalg.norm(d, axis=1)
    s = np.divide(chord, proj, out=np.ones_like(chord), where=proj > 1e-12 * max(scale, 1e-300)) / scale
    return np.column_stack([u * s, w * s])


class SurfaceSynthState:
    """The output on a surface during synthesis; the tools (§5.4) act on it.

    Made by :func:`new_synth_state`. Elements are stored in arrays of capacity that
    grows; ``n`` is the count. Free-space points (Eq. 3) are stored flat with their owner.
    """

    def __init__(self, state: Any, surf: _Surface, scale: float, camera: Camera | None, view_only: bool) -> None:
        self.synth = state  # strew.synth.SynthState (prep, params, rng)
        self.prep = state.prep
        self.params = state.params
        self.rng = state.rng
        self.surf = surf
        self.scale = float(scale)
        self.camera = camera
        self.view_only = bool(view_only)
        self.optimize = False
        self.iterations = 0
        self.n = 0
        cap = 1024
        self.P = np.zeros((cap, 3))
        self.face = np.zeros(cap, np.int64)
        self.bary = np.zeros((cap, 3))
        self.N = np.zeros((cap, 3))
        self.T = np.zeros((cap, 3))  # the field's tangent: the chart frame
        self.src = np.zeros(cap, np.int64)
        self.origin = np.zeros(cap, np.int64)
        self.horizon = np.zeros(cap, bool)
        # free-space points (flat)
        self.nf = 0
        self.FP = np.zeros((4 * cap, 3))
        self.FR = np.zeros(4 * cap)
        self.FC = np.zeros(4 * cap)
        self.FO = np.zeros(4 * cap, np.int64)
        self.FA = np.zeros(4 * cap, bool)
        self.FV = np.zeros(4 * cap, bool)  # visible from the camera
        self.FF = np.zeros(4 * cap, np.int16)
        self.brush_points = np.zeros((0, 3))
        self.brush_radii = np.zeros(0)
        prep = self.prep
        self.rc = prep.rc * self.scale
        self.min_dist = np.ascontiguousarray(prep.min_dist * self.scale)
        V = surf.V
        reach = max(2.0 * float(self.rc.max()), float(self.min_dist.max()), float(prep.free_cover.max()) * self.scale,
                    float(prep.free_r.max() + prep.rc.max()) * self.scale)
        lo = V.min(axis=0) - reach
        span = np.maximum(V.max(axis=0) + reach - lo, 1e-12)
        self._origin = lo
        self._h = max(reach * 1.0001, float(span.max()) / 128.0)
        self._dims = np.maximum(np.ceil(span / self._h).astype(np.int64), 1)
        self._heads = np.full(int(np.prod(self._dims)), -1, np.int64)
        self._nxt = np.full(cap, -1, np.int64)

    # -- storage ---------------------------------------------------------------------------
    def _reserve(self, n: int) -> None:
        cap = len(self.src)
        if n > cap:
            new = max(n, 2 * cap)
            for name in ("P", "face", "bary", "N", "T", "src", "origin", "horizon", "_nxt"):
                old = getattr(self, name)
                arr = np.full((new, *old.shape[1:]), -1 if name == "_nxt" else 0, dtype=old.dtype)
                arr[: self.n] = old[: self.n]
                setattr(self, name, arr)

    def _reserve_free(self, n: int) -> None:
        cap = len(self.FO)
        if n > cap:
            new = max(n, 2 * cap)
            for name in ("FP", "FR", "FC", "FO", "FA", "FV", "FF"):
                old = getattr(self, name)
                arr = np.zeros((new, *old.shape[1:]), dtype=old.dtype)
                arr[: self.nf] = old[: self.nf]
                setattr(self, name, arr)

    @property
    def positions(self) -> np.ndarray:
        return self.P[: self.n]

    def _add(self, ex: int, face: int, bary: np.ndarray, p: np.ndarray, n: np.ndarray, t: np.ndarray) -> int:
        i = self.n
        self._reserve(i + 1)
        self.P[i], self.face[i], self.bary[i], self.N[i], self.T[i] = p, face, bary, n, t
        self.src[i] = self.origin[i] = ex
        self.horizon[i] = True
        self._R[i] = self.rc[ex]
        self._SK[i] = self.prep.skind[ex]
        _insert(i, p, self._heads, self._nxt, self._origin, self._h, self._dims)
        self.n += 1
        return i

    @property
    def _R(self) -> np.ndarray:
        if getattr(self, "_R_arr", None) is None or len(self._R_arr) < len(self.src):
            old = getattr(self, "_R_arr", None)
            arr = np.zeros(len(self.src))
            if old is not None:
                arr[: len(old)] = old
            self._R_arr = arr
        return self._R_arr

    @property
    def _SK(self) -> np.ndarray:
        if getattr(self, "_SK_arr", None) is None or len(self._SK_arr) < len(self.src):
            old = getattr(self, "_SK_arr", None)
            arr = np.zeros(len(self.src), np.int64)
            if old is not None:
                arr[: len(old)] = old
            self._SK_arr = arr
        return self._SK_arr

    def _rebuild_grid(self) -> None:
        self._heads[:] = -1
        self._nxt[:] = -1
        R, SK = self._R, self._SK
        R[: self.n] = self.rc[self.src[: self.n]]
        SK[: self.n] = self.prep.skind[self.src[: self.n]]
        for i in range(self.n):
            _insert(i, self.P[i], self._heads, self._nxt, self._origin, self._h, self._dims)

    # -- domain ------------------------------------------------------------------------------
    def in_domain(self, pts: np.ndarray) -> np.ndarray:
        """(m,) bool: inside a brush ball while brushing (everywhere otherwise)."""
        ok = np.ones(len(pts), bool)
        if len(self.brush_radii) and len(pts):
            d, j = cKDTree(self.brush_points).query(pts, k=min(8, len(self.brush_points)))
            d = np.asarray(d).reshape(len(pts), -1)
            j = np.asarray(j).reshape(len(pts), -1)
            rr = np.where(j < len(self.brush_radii), self.brush_radii[np.minimum(j, len(self.brush_radii) - 1)], 0.0)
            ok = np.any(d <= rr, axis=1)
        return ok

    # -- free space (§5.1, Eq. 3) --------------------------------------------------------------
    def _make_free(self, elems: np.ndarray) -> None:
        """F += {m_{p_o}(v) + p_o | v in free(o_e)} for new elements ``elems``."""
        prep = self.prep
        elems = np.asarray(elems, np.int64)
        if len(elems) == 0:
            return
        src = self.src[elems]
        counts = prep.free_ptr[src + 1] - prep.free_ptr[src]
        owner = np.repeat(elems, counts)
        total = int(counts.sum())
        if total == 0:
            return
        local = np.arange(total) - np.repeat(np.cumsum(counts) - counts, counts)
        rows = np.repeat(prep.free_ptr[src], counts) + local
        off = prep.free_off[rows] * self.scale
        t = self.T[owner]
        b = np.cross(self.N[owner], t)
        dirs = off[:, :1] * t - off[:, 1:2] * b
        ff, fb, pts, done = self.surf.walk(self.face[owner], self.bary[owner], dirs)
        if not done.all():  # free space beyond the mesh's boundary
            ff, fb, pts, owner, rows = ff[done], fb[done], pts[done], owner[done], rows[done]
            total = int(done.sum())
        a, z = self.nf, self.nf + total
        self._reserve_free(z)
        self.FP[a:z] = pts
        self.FR[a:z] = prep.free_r[rows] * self.scale
        self.FC[a:z] = prep.free_cover[rows] * self.scale
        self.FO[a:z] = owner
        self.FA[a:z] = True
        self.FF[a:z] = 0
        if self.camera is not None:
            n, _ = self.surf.frames(ff, fb)
            self.FV[a:z] = self.camera.visible(self.surf.mesh, pts, n)
        else:
            self.FV[a:z] = True
        self.nf = z

    def _update_free(self) -> None:
        """Kill covered free-space points of the horizon and prune the horizon (§5.1)."""
        hz = np.flatnonzero(self.horizon[: self.n])
        if len(hz) == 0:
            return
        fid = np.flatnonzero(self.FA[: self.nf] & self.horizon[self.FO[: self.nf]])
        if len(fid):
            cov = _hits(self.FP[fid], self.FR[fid], np.full(len(fid), -1, np.int64), self.FC[fid], self.P, self._R, self._SK,
                        self.min_dist, self._heads, self._nxt, self._origin, self._h, self._dims)
            self.FA[fid[cov]] = False
            fid = fid[~cov]
            fid = fid[self.in_domain(self.FP[fid])]
        keep = np.zeros(len(hz), bool)
        if len(fid):
            rbar = self.prep.rbar[self.src[hz]] * self.scale
            keep = cKDTree(self.FP[fid]).query_ball_point(self.P[hz], r=rbar, return_length=True) > 0
        self.horizon[hz] = keep

    # -- generation ------------------------------------------------------------------------------
    def _place(self, exs: np.ndarray, faces: np.ndarray, bary: np.ndarray, pts: np.ndarray, max_elements: int | None,
               parent: np.ndarray | None = None) -> tuple[list[int], np.ndarray]:
        """Copy exemplar elements ``exs`` to surface points unless they intersect O.

        ``parent`` (m,) gives for each item the item number of the larger element it
        leans on (-1: none, below -1: never, e.g. outside the copied neighbourhood): an item is copied only
        together with its parent, or when the parent's point lies outside the domain
        (``Prepared.parent``, as in the planar synth: no orphaned small elements).
        Parents come before their children in the order given.
        """
        if len(exs) == 0:
            return [], np.zeros(0, bool)
        ok = self.in_domain(pts)
        n, t = self.surf.frames(faces, bary)
        new: list[int] = []
        placed = np.zeros(len(exs), bool)
        for i in range(len(exs)):
            if max_elements is not None and self.n >= max_elements:
                break
            if parent is not None:
                ps = int(parent[i])
                if ps < -1 or (ps >= 0 and not placed[ps] and ok[ps]):
                    continue
            if not ok[i]:
                continue
            ex = int(exs[i])
            if self.n and _hit(pts[i], float(self.rc[ex]), int(self.prep.skind[ex]), 0.0, self.P, self._R, self._SK, self.min_dist,
                               self._heads, self._nxt, self._origin, self._h, self._dims):
                continue
            placed[i] = True
            new.append(self._add(ex, int(faces[i]), bary[i], pts[i], n[i], t[i]))
        return new, placed

    def seed_patch(self, point: Any, *, random: bool = False, max_elements: int | None = None) -> np.ndarray:
        """Copy the exemplar's central neighbourhood (or a random interior one) to the
        surface point nearest ``point`` (Algorithm 1, first line; §5.4). Returns new indices."""
        prep = self.prep
        rng = self.rng
        ex_i = int(rng.choice(len(prep.names), p=prep.weights)) if len(prep.names) > 1 else 0
        if random:
            pool = prep.interior[ex_i]
            c = int(pool[rng.integers(len(pool))])
        else:
            c = int(prep.center[ex_i])
        ids = np.flatnonzero(prep.source == ex_i)
        off = prep.pos[ids] - prep.pos[c]
        near = np.hypot(off[:, 0], off[:, 1]) <= prep.rbar[c]
        ids, off = ids[near], off[near]
        order = np.argsort(np.hypot(off[:, 0], off[:, 1]), kind="stable")
        ids, off = ids[order], off[order] * self.scale
        f0, b0, p0 = self.surf.locate(np.asarray(point, dtype=float).reshape(1, 3))
        n0, t0 = self.surf.frames(f0, b0)
        b = np.cross(n0[0], t0[0])
        dirs = off[:, :1] * t0[0] - off[:, 1:2] * b
        faces, bary, pts, done = self.surf.walk(np.repeat(f0, len(ids)), np.repeat(b0, len(ids), axis=0), dirs)
        ids, faces, bary, pts = ids[done], faces[done], bary[done], pts[done]
        new = np.asarray(self._place(ids, faces, bary, pts, max_elements)[0], np.int64)
        self._make_free(new)
        return new

    def grow(self, *, max_elements: int | None = None, max_iterations: int = 100_000, rep: Reporter | None = None) -> int:
        """Region growing from the horizon until no free space is left (Algorithm 1)."""
        prep, prm = self.prep, self.params
        from strew.synth import _kernels as K

        from strew.synth._grow import anchors

        start = self.n
        self._update_free()
        sel_el = prep.selected_elements
        anchor = anchors(prep)
        for _ in range(max_iterations):
            self.iterations += 1
            hz = np.flatnonzero(self.horizon[: self.n])
            if len(hz) == 0 or (max_elements is not None and self.n >= max_elements):
                break
            if rep is not None:
                rep.tick(self.n - start, message=f"{self.n} elements")
            fid = np.flatnonzero(self.FA[: self.nf] & self.horizon[self.FO[: self.nf]])
            fid = fid[self.in_domain(self.FP[fid])]
            if self.camera is not None:
                vis = self.FV[fid]
                if vis.any():
                    fid = fid[vis]  # §5.8: the visible queue first
                elif self.view_only:
                    break
            if len(fid) == 0:
                self.horizon[hz] = False
                break
            ftree = cKDTree(self.FP[fid])
            rbar = prep.rbar[self.src[hz]] * self.scale
            near = ftree.query_ball_point(self.P[hz], r=rbar, return_length=True) > 0
            cand_seeds = hz[near]
            if len(cand_seeds) == 0:
                self.horizon[hz] = False
                continue
            # -- seeds (§5.1): 0.75 r-bar apart, in random order --------------------------------
            order = self.rng.permutation(cand_seeds)
            seeds = _separated(self.P, order, prm.seed_separation * prep.rbar[self.src] * self.scale)
            rbar_s = prep.rbar[self.src[seeds]]
            # output neighbourhoods as exemplar offsets (the inverse of m_p)
            otree = cKDTree(self.P[: self.n])
            lists = otree.query_ball_point(self.P[seeds], r=rbar_s * self.scale)
            q_ptr = np.zeros(len(seeds) + 1, np.int64)
            q_idx_l, q_off_l = [], []
            charts = []
            for a, (s, lst) in enumerate(zip(seeds.tolist(), lists)):
                lst = np.asarray([j for j in lst if j != s], np.int64)
                t0 = self.T[s]
                b0 = np.cross(self.N[s], t0)
                charts.append((t0, b0))
                off = _chart(self.P[s], t0, b0, self.P[lst], self.scale) if len(lst) else np.zeros((0, 2))
                o = np.argsort(np.einsum("ij,ij->i", off, off), kind="stable")
                q_idx_l.append(lst[o])
                q_off_l.append(off[o])
                q_ptr[a + 1] = q_ptr[a] + len(lst)
            q_idx = np.concatenate(q_idx_l) if q_idx_l else np.zeros(0, np.int64)
            q_off = np.ascontiguousarray(np.concatenate(q_off_l)) if q_off_l else np.zeros((0, 2))
            osrc = self.src[: self.n]
            q_kind = prep.kind[osrc[q_idx]].astype(np.int64)
            q_d = 2.0 * prep.r[osrc[q_idx]]
            cands = prep.co[self.origin[seeds]]
            cands = np.where((cands >= 0) & sel_el[np.maximum(cands, 0)], cands, -1).astype(np.int64)
            ckind = prep.kind[osrc[seeds]].astype(np.int64)
            cd = 2.0 * prep.r[osrc[seeds]]
            costs = K.candidate_costs(q_ptr, q_off, q_kind, q_d, rbar_s, ckind, cd, cands, prep.nb_ptr, prep.nb_off, prep.nb_kind,
                                      prep.nb_d, prep.kind, prep.kind_cost)
            kk = cands.shape[1]
            sizes = np.where(cands >= 0, np.diff(prep.nb_ptr)[np.maximum(cands, 0)], 0).ravel()
            out_ptr = np.zeros(len(sizes) + 1, np.int64)
            np.cumsum(sizes, out=out_ptr[1:])
            count, ex, ppos, pslot = K.generate_proposals(np.zeros((len(seeds), 2)), q_ptr, q_off, q_kind, q_d, rbar_s, cands,
                                                           prep.nb_ptr, prep.nb_idx, prep.nb_off, prep.nb_kind, prep.nb_d,
                                                           prep.kind_cost, out_ptr, prep.parent, *_follow(K, prep))
            slack = 2.0 * (2.0 * prep.r[osrc[seeds]]) ** 2
            reach = (rbar_s + 2.0 * float(prep.rc.max()) + float(prep.free_cover.max())) * self.scale
            flists = ftree.query_ball_point(self.P[seeds], r=reach)
            added = 0
            failed: list[int] = []
            rows_l: list[np.ndarray] = []
            owner_l: list[np.ndarray] = []
            par_rows: list[np.ndarray] = []
            for a, s in enumerate(seeds.tolist()):
                fl = np.asarray(flists[a], np.int64)
                if len(fl) == 0:
                    failed.append(a)
                    continue
                t0, b0 = charts[a]
                fq = _chart(self.P[s], t0, b0, self.FP[fid[fl]], self.scale)
                fcov = self.FC[fid[fl]] / self.scale
                o = np.argsort(costs[a], kind="stable")
                d0 = costs[a, o[0]]
                chosen = None
                if np.isfinite(d0):
                    for j in o.tolist():
                        cj = costs[a, j]
                        if not np.isfinite(cj) or cj > prm.c * d0 + slack[a]:
                            break  # bad suggestion: abandon the seed (§5.1)
                        w = out_ptr[a * kk + j]
                        rows = np.arange(w, w + count[a * kk + j])
                        rows = rows[ex[rows] >= 0]
                        if len(rows) == 0:
                            continue
                        # proposals overlapping a free-space point (in the seed's chart)
                        dd = np.linalg.norm(ppos[rows][:, None, :] - fq[None, :, :], axis=2)
                        hit = np.any(dd < (prep.rc[ex[rows]][:, None] + fcov[None, :]), axis=1)
                        if hit.any():
                            chosen = rows[hit]
                            break
                if chosen is None:
                    failed.append(a)
                    continue
                # parents as proposal rows of this copy; a parent not chosen: never (-2)
                inside = set(chosen.tolist())
                par_rows.append(np.array([q if (q < 0 or q in inside) else -2 for q in pslot[chosen].tolist()], np.int64))
                rows_l.append(chosen)
                owner_l.append(np.full(len(chosen), a, np.int64))
            if rows_l:
                rows = np.concatenate(rows_l)
                owner = np.concatenate(owner_l)
                prow = np.concatenate(par_rows)
                s_idx = seeds[owner]
                T0 = self.T[s_idx]
                B0 = np.cross(self.N[s_idx], T0)
                off = ppos[rows] * self.scale
                faces, bary, pts, done = self.surf.walk(self.face[s_idx], self.bary[s_idx], off[:, :1] * T0 - off[:, 1:2] * B0)
                # the copies of all seeds, larger size classes first and within a class
                # the anchors (a ring's hub), seed order otherwise: as the planar synth
                # places them (strew.synth._kernels.place_proposals, _grow.anchors);
                # seed by seed, a neighbouring copy's tile took the hub's place (rings:
                # 2.9 % hubs against the exemplar's 7.7 %)
                key = 2 * prep.size_class[ex[rows]] + anchor[ex[rows]]
                order = np.argsort(-key, kind="stable")
                item_of = np.full(len(ppos), -1, np.int64)
                item_of[rows[order]] = np.arange(len(order))
                par = np.where(prow[order] >= 0, item_of[np.maximum(prow[order], 0)], prow[order])
                # a copy whose walk ran into the mesh's boundary is not placed (nor its children)
                par = np.where(done[order], par, -2)
                new, placed = self._place(ex[rows[order]], faces[order], bary[order], pts[order], max_elements, par)
                if new:
                    self._make_free(np.asarray(new, np.int64))
                    added += len(new)
                got = np.bincount(owner[order][placed], minlength=len(seeds)) > 0
                failed.extend(np.flatnonzero(~got & np.isin(np.arange(len(seeds)), owner)).tolist())
            # seeds that could not generate: a failure on the free space they reach
            if failed:
                fa = np.asarray(failed, np.int64)
                hit = ftree.query_ball_point(self.P[seeds[fa]], r=rbar_s[fa] * self.scale)
                ids = np.unique(np.fromiter((j for v in hit for j in v), dtype=np.int64))
                if len(ids):
                    g = fid[ids]
                    self.FF[g] += 1
                    self.FA[g[self.FF[g] >= prm.max_failures]] = False
            if self.optimize and added:
                self._optimize(K, anchor_new=np.arange(self.n - added, self.n))
            self._update_free()
        return self.n - start

    def _optimize(self, K: Any, anchor_new: np.ndarray) -> int:
        """One relaxation step of the horizon (§5.2-5.3), on the surface.

        Each element of the expanded horizon finds its most similar exemplar
        neighbourhood (k-coherence candidates, :func:`strew.synth._kernels.best_matches`,
        in its chart); each paired neighbour gets the predicted position
        ``m_{p_h}(p_{e'} - p_e)``, walked on the surface. A horizon element moves by
        ``relaxation`` (0.8) of the way to the mean of its predictions (Ma et al.'s least
        squares with equal weights, solved by one Jacobi step: a departure from §5.3's
        Gaussian weights and sparse solve), is put back on the surface (closest point)
        and keeps the move only if its bounding sphere meets no other. Frozen elements
        (outside the horizon) do not move. Returns the number of elements moved.
        """
        prep, prm = self.prep, self.params
        hz = np.flatnonzero(self.horizon[: self.n])
        if len(hz) == 0:
            return 0
        otree = cKDTree(self.P[: self.n])
        reach = float(prep.rbar.max()) * self.scale
        near = otree.query_ball_point(self.P[hz], r=reach)
        hbar = np.unique(np.concatenate([hz, np.fromiter((j for v in near for j in v), dtype=np.int64)]))
        q_ptr, q_idx, q_off = self._charts(hbar, otree)
        osrc = self.src[: self.n]
        cands = prep.co[self.origin[hbar]]
        cands = np.where((cands >= 0) & prep.selected_elements[np.maximum(cands, 0)], cands, -1).astype(np.int64)
        best, _cost, con_q, con_o, con_off = K.best_matches(
            q_ptr, q_idx, q_off, prep.kind[osrc[q_idx]].astype(np.int64), 2.0 * prep.r[osrc[q_idx]], prep.rbar[osrc[hbar]],
            prep.kind[osrc[hbar]].astype(np.int64), 2.0 * prep.r[osrc[hbar]], cands, prep.nb_ptr, prep.nb_idx, prep.nb_off,
            prep.nb_kind, prep.nb_d, prep.kind, prep.kind_cost)
        ok = best >= 0
        self.origin[hbar[ok]] = best[ok]
        movable = np.zeros(self.n, bool)
        movable[hz] = True
        keep = movable[con_o]
        con_q, con_o, con_off = con_q[keep], con_o[keep], con_off[keep]
        if len(con_o) == 0:
            return 0
        h = hbar[con_q]
        off = con_off * self.scale
        T0 = self.T[h]
        B0 = np.cross(self.N[h], T0)
        _, _, target, done = self.surf.walk(self.face[h], self.bary[h], off[:, :1] * T0 - off[:, 1:2] * B0)
        con_o, target = con_o[done], target[done]
        cnt = np.bincount(con_o, minlength=self.n).astype(float)
        mean = np.zeros((self.n, 3))
        for a in range(3):
            mean[:, a] = np.bincount(con_o, weights=target[:, a], minlength=self.n)
        idx = np.flatnonzero(cnt > 0)
        mean = mean[idx] / cnt[idx, None]
        want = self.P[idx] + prm.relaxation * (mean - self.P[idx])
        faces, bary, pts = self.surf.locate(want)
        n, t = self.surf.frames(faces, bary)
        moved = []
        for u, i in enumerate(idx.tolist()):
            if not self.in_domain(pts[u:u + 1])[0]:
                continue
            old = self.P[i].copy()
            _unlink(i, old, self._heads, self._nxt, self._origin, self._h, self._dims)
            ex = int(self.src[i])
            if _hit(pts[u], float(self.rc[ex]), int(prep.skind[ex]), 0.0, self.P, self._R, self._SK, self.min_dist,
                    self._heads, self._nxt, self._origin, self._h, self._dims):
                _insert(i, old, self._heads, self._nxt, self._origin, self._h, self._dims)
                continue
            self.P[i], self.face[i], self.bary[i], self.N[i], self.T[i] = pts[u], faces[u], bary[u], n[u], t[u]
            _insert(i, pts[u], self._heads, self._nxt, self._origin, self._h, self._dims)
            moved.append(i)
        if moved:
            mv = np.asarray(moved, np.int64)
            mine = np.isin(self.FO[: self.nf], mv)
            self.FA[: self.nf][mine] = False  # their free space moves with them
            self._make_free(mv)
        return len(moved)

    def _charts(self, elems: np.ndarray, otree: cKDTree) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """CSR neighbourhoods of ``elems`` within their r-bar as exemplar offsets (the
        inverse of m_p), sorted by distance."""
        rbar = self.prep.rbar[self.src[elems]] * self.scale
        lists = otree.query_ball_point(self.P[elems], r=rbar)
        ptr = np.zeros(len(elems) + 1, np.int64)
        idx_l, off_l = [], []
        for a, (s, lst) in enumerate(zip(elems.tolist(), lists)):
            lst = np.asarray([j for j in lst if j != s], np.int64)
            t0 = self.T[s]
            b0 = np.cross(self.N[s], t0)
            off = _chart(self.P[s], t0, b0, self.P[lst], self.scale) if len(lst) else np.zeros((0, 2))
            o = np.argsort(np.einsum("ij,ij->i", off, off), kind="stable")
            idx_l.append(lst[o])
            off_l.append(off[o])
            ptr[a + 1] = ptr[a] + len(lst)
        idx = np.concatenate(idx_l) if idx_l else np.zeros(0, np.int64)
        off = np.ascontiguousarray(np.concatenate(off_l)) if off_l else np.zeros((0, 2))
        return ptr, idx, off

    def fill(self, point: Any = None, *, max_elements: int | None = None, rep: Reporter | None = None) -> int:
        """The filler (§5.4): from ``point`` (default: a random point of the surface) until
        no room is left; where the front dies with room left, a new patch is seeded at a
        random free spot (another component, a gap), until none is left."""
        start = self.n
        self.brush_points = np.zeros((0, 3))
        self.brush_radii = np.zeros(0)
        if point is None:
            point = self._random_points(1)[0]
        self._seed_if_free(point, max_elements)
        for _ in range(1000):
            self.grow(max_elements=max_elements, rep=rep)
            if max_elements is not None and self.n >= max_elements:
                break
            if self.camera is not None and self.view_only:
                break
            spot = self._free_spot()
            if spot is None:
                break
            if len(self.seed_patch(spot, max_elements=max_elements)) == 0:
                break
        return self.n - start

    def brush(self, points: Any, radius: Any, *, max_elements: int | None = None, rep: Reporter | None = None) -> int:
        """The generative brush (§5.4): grow within ``radius`` of the brush points (on or
        near the surface); a patch seeds the stroke where no element is near its first point."""
        pts = _points(points, "brush_points")
        rad = _radii(radius, len(pts), "brush_radius")
        _, _, on = self.surf.locate(pts)
        start = self.n
        self.brush_points, self.brush_radii = on, rad
        if self.n == 0 or np.min(np.linalg.norm(self.positions - on[0], axis=1)) > rad[0]:
            self._seed_if_free(on[0], max_elements)
        # elements inside the stroke rejoin the horizon: they may generate into it
        inside = np.flatnonzero(self.in_domain(self.positions))
        self.horizon[inside] = True
        self._revive(inside)
        self.grow(max_elements=max_elements, rep=rep)
        self.brush_points = np.zeros((0, 3))
        self.brush_radii = np.zeros(0)
        return self.n - start

    def erase(self, points: Any, radius: Any) -> int:
        """The eraser (§5.4): remove elements within ``radius`` of the brush points; their
        neighbours return to the horizon with fresh free space. Returns how many were removed."""
        pts = _points(points, "eraser points")
        rad = _radii(radius, len(pts), "eraser radius")
        if self.n == 0:
            return 0
        _, _, on = self.surf.locate(pts)
        d, j = cKDTree(on).query(self.positions, k=min(8, len(on)))
        d = np.asarray(d).reshape(self.n, -1)
        j = np.asarray(j).reshape(self.n, -1)
        rr = np.where(j < len(rad), rad[np.minimum(j, len(rad) - 1)], 0.0)
        gone = np.any(d <= rr, axis=1)
        removed = int(gone.sum())
        if removed == 0:
            return 0
        keep = ~gone
        remap = np.full(self.n, -1, np.int64)
        remap[keep] = np.arange(int(keep.sum()))
        for name in ("P", "face", "bary", "N", "T", "src", "origin", "horizon"):
            arr = getattr(self, name)
            arr[: int(keep.sum())] = arr[: self.n][keep]
        fkeep = keep[self.FO[: self.nf]]
        for name in ("FP", "FR", "FC", "FO", "FA", "FV", "FF"):
            arr = getattr(self, name)
            arr[: int(fkeep.sum())] = arr[: self.nf][fkeep]
        self.nf = int(fkeep.sum())
        self.FO[: self.nf] = remap[self.FO[: self.nf]]
        self.n = int(keep.sum())
        self._rebuild_grid()
        # neighbours of the hole get their free space back
        reach = float(self.prep.rbar.max()) * self.scale + float(rad.max())
        near = np.flatnonzero(cKDTree(on).query(self.positions, distance_upper_bound=reach)[0] <= reach) if self.n else np.zeros(0, np.int64)
        self.horizon[near] = True
        self._revive(near)
        self._update_free()
        return removed

    # -- helpers ---------------------------------------------------------------------------------
    def _revive(self, elems: np.ndarray) -> None:
        if len(elems) == 0 or self.nf == 0:
            return
        mine = np.isin(self.FO[: self.nf], elems)
        self.FA[: self.nf][mine] = True
        self.FF[: self.nf][mine] = 0

    def _random_points(self, m: int) -> np.ndarray:
        s = self.surf
        f = self.rng.choice(len(s.F), size=m, p=s.area / s.area.sum())
        u = self.rng.random((m, 2))
        flip = u.sum(axis=1) > 1.0
        u[flip] = 1.0 - u[flip]
        bary = np.column_stack([1.0 - u[:, 0] - u[:, 1], u[:, 0], u[:, 1]])
        return np.einsum("mk,mkj->mj", bary, s.tri[f])

    def _spacing(self) -> float:
        """The exemplars' mean nearest-neighbour spacing in mesh units (cover radius / 0.75)."""
        return float(np.mean(self.prep.free_cover)) / 0.75 * self.scale

    def _free_spot(self) -> np.ndarray | None:
        """A random surface point at least two exemplar spacings from every element
        (visible first with a camera), or None."""
        a = self._spacing()
        m = int(min(200_000, max(2000, 8.0 * self.surf.area.sum() / (a * a))))
        q = self._random_points(m)
        if self.n:
            d, _ = cKDTree(self.positions).query(q, distance_upper_bound=2.0 * a)
            q = q[~np.isfinite(d)]
        if len(q) == 0:
            return None
        return q[0]

    def _seed_if_free(self, point: Any, max_elements: int | None) -> None:
        p = np.asarray(point, dtype=float).reshape(3)
        if self.n:
            d = np.min(np.linalg.norm(self.positions - p, axis=1))
            if d < self._spacing():
                self.horizon[: self.n][np.linalg.norm(self.positions - p, axis=1) < float(self.prep.rbar.max()) * self.scale] = True
                return
        self.seed_patch(p, max_elements=max_elements)

    # -- output ---------------------------------------------------------------------------------
    def to_arrangement(self, *, keep_voids: bool = False, meta: dict | None = None) -> Arrangement:
        """The output as a surface arrangement (columns of :mod:`strew.surface`)."""
        prep = self.prep
        n = self.n
        src = self.src[:n]
        P, N, T = self.P[:n], self.N[:n], self.T[:n]
        B = np.cross(N, T)
        th = prep.rotation[src]
        # exemplar rotation about the normal, in the field's frame (exemplar +y is -b)
        tang = np.cos(th)[:, None] * T - np.sin(th)[:, None] * B
        cols: dict[str, Any] = {
            "z": P[:, 2], "nx": N[:, 0], "ny": N[:, 1], "nz": N[:, 2],
            "tx": tang[:, 0], "ty": tang[:, 1], "tz": tang[:, 2],
            "radius": self.rc[src], "face": self.face[:n].copy(),
            "neighborhood_radius": prep.rbar[src] * self.scale,
            "exemplar": np.asarray(prep.names, dtype=object)[prep.source[src]],
        }
        for name, col in prep.columns.items():
            if name not in cols and name not in ("z",):
                cols[name] = col[src]
        if keep_voids:
            cols["void"] = prep.void[src]
        arr = Arrangement(prep.shapes, prep.kind[src].astype(np.int64), P[:, 0], P[:, 1],
                          np.arctan2(tang[:, 1], tang[:, 0]) if n else None, prep.scale[src] * self.scale,
                          columns=cols, meta=meta or {})
        if not keep_voids:
            arr = arr.select(~prep.void[src])
        return arr


@numba.njit(cache=True)
def _separated_kernel(P, order, sep):
    m = order.shape[0]
    out = np.empty(m, np.int64)
    ns = 0
    for t in range(m):
        i = order[t]
        ok = True
        for u in range(ns):
            j = out[u]
            d0 = P[i, 0] - P[j, 0]
            d1 = P[i, 1] - P[j, 1]
            d2 = P[i, 2] - P[j, 2]
            lim = max(sep[i], sep[j])
            if d0 * d0 + d1 * d1 + d2 * d2 < lim * lim:
                ok = False
                break
        if ok:
            out[ns] = i
            ns += 1
    return out[:ns]


def _follow(K: Any, prep: Any) -> tuple:
    """The extra argument of ``generate_proposals`` where the synth kernels take one
    (``Prepared.follow``: children placed from their parent's stand-in)."""
    argc = getattr(getattr(K.generate_proposals, "py_func", None), "__code__", None)
    if argc is not None and argc.co_argcount >= 17 and hasattr(prep, "follow"):
        # and the children that lean on an anchor of their size class (a ring's tiles)
        from ..synth._grow import anchor_children

        return (prep.follow, anchor_children(prep)[0])
    if argc is not None and argc.co_argcount >= 16 and hasattr(prep, "follow"):
        return (prep.follow,)
    return ()


def _separated(P: np.ndarray, order: np.ndarray, sep: np.ndarray) -> np.ndarray:
    """Greedy subset of ``order`` at least ``sep`` apart (seeds, §5.1); order kept."""
    if len(order) == 0:
        return order.astype(np.int64)
    # a grid would scale better; the horizon's seeds are few per iteration
    return _separated_kernel(np.ascontiguousarray(P), np.asarray(order, np.int64), np.asarray(sep, float))


def _points(value: Any, where: str) -> np.ndarray:
    try:
        pts = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"{where}: must be 3D points [[x, y, z], ...]") from None
    if pts.ndim == 1 and pts.shape == (3,):
        pts = pts[None]
    if pts.ndim != 2 or pts.shape[1] != 3 or len(pts) == 0 or not np.all(np.isfinite(pts)):
        raise InputError(f"{where}: must be finite 3D points [[x, y, z], ...], got shape {pts.shape}")
    return pts


def _radii(value: Any, m: int, where: str) -> np.ndarray:
    try:
        r = np.broadcast_to(np.asarray(value, dtype=float), (m,)).copy()
    except (TypeError, ValueError):
        raise InputError(f"{where}: a positive number or one per point, got {value!r}") from None
    if not np.all(np.isfinite(r)) or np.any(r <= 0):
        raise InputError(f"{where}: must be positive, got {value!r}")
    return r


def _auto_scale(prep: Any, surf: _Surface, target: int) -> float:
    """Exemplar units -> mesh units so that about ``target`` elements cover the mesh at
    the selected exemplars' spacing."""
    sel = prep.selected_elements & ~prep.void
    p = prep.pos[sel]
    if len(p) < 2:
        return 1.0
    d, _ = cKDTree(p).query(p, k=2)
    a = float(np.mean(d[:, 1]))
    return float(np.sqrt(surf.area.sum() / (target * a * a * np.sqrt(3.0) / 2.0)))


def new_synth_state(
    exemplars: Any,
    mesh: Any,
    *,
    field: OrientationField | str | None = "smoothest",
    selection: Any = None,
    scale: float | None = None,
    camera: Camera | None = None,
    view_only: bool = False,
    optimize: str = "none",
    k: int = 5,
    c: float = 2.0,
    kind_cost: float = 1.0,
    rng: int | np.random.Generator | None = None,
    **params: Any,
) -> SurfaceSynthState:
    """An empty output on ``mesh`` for the tools (fill, brush, erase; §5.4).

    Parameters
    ----------
    exemplars : Palette, Selection, Arrangement, list or dict of Arrangement
        As :func:`strew.synth.synthesize`.
    mesh : path, trimesh.Trimesh or (vertices, faces)
    field : OrientationField or "smoothest"
        The orientation field of §5.7 (its frame is the exemplar's frame on the surface).
    selection : optional
        Exemplars of the palette to use.
    scale : float, optional
        Mesh units per exemplar unit; default: the exemplar's spacing scaled so that
        about 2,000 elements cover the mesh (recorded in the output's meta).
    camera : Camera, optional
        View-based priority (§5.8).
    view_only : bool
        With a camera, stop when no visible free space is left.
    optimize : {"none", "horizon"}
        ``"horizon"``: one relaxation step of the horizon per iteration (§5.2, see
        ``SurfaceSynthState._optimize``). On a 5k-face sphere it brings the grid's
        nearest-neighbour 10th percentile from 0.90 to 0.98 of the exemplar's but
        costs 5-12x the CPU and does not help stripes or rings (rings' median spacing
        0.95x), so it is off by default.
    k, c, kind_cost, params
        As :class:`strew.synth.SynthParams` (``seed_separation``, ``max_failures``).
    """
    from ..synth import new_state

    mesh = load_mesh(mesh)
    if isinstance(field, str):
        if field != "smoothest":
            raise InputError(f"field: expected an OrientationField or 'smoothest', got {field!r}")
        field = orientation_field(mesh)
    elif not isinstance(field, OrientationField):
        raise InputError(f"field: expected an OrientationField or 'smoothest', got {type(field).__name__}")
    if field.directions.shape != (len(mesh.vertices), 3):
        raise InputError(f"field: has {len(field.directions)} directions, the mesh {len(mesh.vertices)} vertices")
    if optimize not in ("none", "horizon"):
        raise InputError(f"optimize: on a surface expected none or horizon, got {optimize!r}")
    if camera is not None and not isinstance(camera, Camera):
        raise InputError(f"camera: expected a strew.surface.Camera, got {type(camera).__name__}")
    state = new_state(exemplars, None, selection=selection, k=k, c=c, optimize="none", kind_cost=kind_cost, rng=rng, **params)
    surf = _Surface(mesh, field)
    if scale is None:
        scale = _auto_scale(state.prep, surf, 2000)
    else:
        try:
            scale = float(scale)
        except (TypeError, ValueError):
            raise InputError(f"scale: must be a positive number, got {scale!r}") from None
        if not np.isfinite(scale) or scale <= 0:
            raise InputError(f"scale: must be a positive number, got {scale!r}")
    rc_max = float(state.prep.rc.max()) * scale
    if rc_max < 0.02 * surf.edge:
        # elements far smaller than the triangles are fine; warn only through the cap below
        pass
    from .._limits import check_elements

    a = float(np.mean(state.prep.free_cover)) / 0.75 * scale
    check_elements(int(surf.area.sum() / max(a * a * np.sqrt(3) / 2, 1e-300)), "surface synth")
    st = SurfaceSynthState(state, surf, scale, camera, view_only)
    st.optimize = optimize == "horizon"
    st.field_design = field.design
    return st


def synthesize(
    exemplars: Any,
    mesh: Any,
    *,
    field: OrientationField | str | None = "smoothest",
    selection: Any = None,
    scale: float | None = None,
    fill_point: Any = None,
    brush_points: Any = None,
    brush_radius: Any = None,
    camera: Camera | None = None,
    view_only: bool = False,
    optimize: str = "none",
    k: int = 5,
    c: float = 2.0,
    kind_cost: float = 1.0,
    keep_voids: bool = False,
    max_elements: int | None = None,
    rng: int | np.random.Generator | None = None,
    progress: Callable[[int, int | None, str], None] | None = None,
    should_cancel: Callable[[], bool] | None = None,
    **params: Any,
) -> Arrangement:
    """Synthesize a discrete element texture on a surface (Davison et al. §5.7).

    Fills the whole mesh (from ``fill_point`` or a random point), or paints along a
    brush stroke (``brush_points`` on the surface with ``brush_radius``).

    Parameters
    ----------
    exemplars, mesh, field, selection, scale, camera, view_only, optimize, k, c, kind_cost, params
        See :func:`new_synth_state`.
    fill_point : (3,) float, optional
    brush_points : (m, 3) float, optional
    brush_radius : float or (m,) float, optional
        In mesh units.
    keep_voids : bool
        Keep void elements (§5.6), flagged in the ``void`` column.
    max_elements : int, optional
    rng : int, Generator or None
    progress, should_cancel : callables, optional

    Returns
    -------
    Arrangement
        A surface arrangement: ``x y`` and ``z``, normals, tangents (the exemplar's
        rotation turned into the field's frame), ``scale`` (exemplar scale times
        ``scale``), ``radius`` (bounding sphere), ``neighborhood_radius``, ``face``,
        ``exemplar``; ``meta`` records method, seed, parameters and the scale used.

    Examples
    --------
    >>> import trimesh
    >>> from strew.synth._exemplars import grid
    >>> m = trimesh.creation.icosphere(subdivisions=3)
    >>> a = synthesize(grid(), m, scale=0.02, rng=1)
    >>> len(a) > 300
    True
    """
    from .._method import seed_record

    gen, seed = seed_record(rng)
    if brush_points is not None and fill_point is not None:
        raise InputError("fill_point: give a fill point or a brush stroke, not both")
    if brush_points is not None and brush_radius is None:
        raise InputError("brush_radius: needed with brush_points")
    if max_elements is not None and (isinstance(max_elements, bool) or not isinstance(max_elements, (int, np.integer)) or max_elements < 1):
        raise InputError(f"max_elements: must be a positive integer, got {max_elements!r}")
    st = new_synth_state(exemplars, mesh, field=field, selection=selection, scale=scale, camera=camera, view_only=view_only,
                         optimize=optimize, k=k, c=c, kind_cost=kind_cost, rng=gen, **params)
    rep = Reporter(progress, should_cancel, message="surface synth")
    if brush_points is not None:
        st.brush(brush_points, brush_radius, max_elements=max_elements, rep=rep)
    else:
        fp = None if fill_point is None else _points(fill_point, "fill_point")[0]
        st.fill(fp, max_elements=max_elements, rep=rep)
    rep.done(st.n)
    surf = st.surf
    meta = {
        "generator": f"strew {__version__}",
        "method": "surface.synth",
        **seed,
        "params": {
            "scale": st.scale, "k": int(k), "c": float(c), "kind_cost": float(kind_cost),
            "selection": list(st.prep.selection.names) if st.prep.selection is not None else None,
            "camera": None if camera is None else {"eye": camera.eye.tolist(), "target": camera.target.tolist(), "fov": float(camera.fov)},
            "view_only": bool(view_only), "optimize": optimize, "field": st.field_design, "max_elements": max_elements,
            "brush_radius": None if brush_radius is None else np.asarray(brush_radius, dtype=float).tolist(),
        },
        "synth": {"iterations": st.iterations},
        "surface": {"vertices": int(len(surf.V)), "faces": int(len(surf.F)), "area": float(surf.area.sum()),
                    "bounds": np.asarray(surf.mesh.bounds, dtype=float).tolist()},
    }
    return st.to_arrangement(keep_voids=keep_voids, meta=meta)
