"""The local map m_p of Davison et al. §5.1 on a surface (§5.7).

``m_p`` takes an offset ``v`` in exemplar space (2D, SVG's y-down) to a point of the
surface: start at ``p`` in the frame of the orientation field (x along the field's
tangent ``t``, exemplar +y along ``-b``, ``b = n x t``, as in :mod:`._frames`) and walk
``|v|`` along the surface. The walk is a geodesic traced by potpourri3d (the exponential
map at ``p``). Departure from §5.7: Davison et al. walk along the integral curve of the
orientation field turned by the offset's angle; on a smooth field and at neighbourhood
distances the two differ by the field's turning along the path, and the geodesic needs
no step size. :mod:`._synth` walks the same way, batched with cached geometry.
"""

from __future__ import annotations

import hashlib
import weakref
from typing import Any

import numpy as np

from .._errors import InputError
from ._deps import require
from ._field import OrientationField

__all__ = ["local_map", "locate", "chart"]

# one geodesic tracer per mesh object (building it costs about as much as 1,000 walks)
_TRACERS: "weakref.WeakKeyDictionary[Any, tuple[bytes, Any]]" = weakref.WeakKeyDictionary()
_SOLVERS: "weakref.WeakKeyDictionary[Any, tuple[bytes, Any]]" = weakref.WeakKeyDictionary()


def _mesh_key(mesh: Any) -> bytes:
    """A digest of the vertices and faces: cached solvers are rebuilt when they change."""
    h = hashlib.blake2b(digest_size=16)
    h.update(np.ascontiguousarray(mesh.vertices, dtype=np.float64).tobytes())
    h.update(np.ascontiguousarray(mesh.faces, dtype=np.int64).tobytes())
    return h.digest()


def locate(mesh: Any, points: np.ndarray, k: int = 12) -> tuple[np.ndarray, np.ndarray]:
    """Face and barycentric coordinates of points lying on the mesh.

    Parameters
    ----------
    points : (m, 3) float
        Points on (or within a hair of) the surface.
    k : int
        Faces tried per point, nearest centroids first.

    Returns
    -------
    faces : (m,) int
    bary : (m, 3) float
        Clipped to the triangle and renormalised.
    """
    from scipy.spatial import cKDTree

    trimesh = require("trimesh")
    V = np.asarray(mesh.vertices)
    F = np.asarray(mesh.faces)
    cent = V[F].mean(axis=1)
    k = min(k, len(F))
    _, cand = cKDTree(cent).query(points, k=k)
    cand = np.asarray(cand).reshape(len(points), k)
    best_f = cand[:, 0].copy()
    best_b = np.zeros((len(points), 3))
    best_err = np.full(len(points), np.inf)
    for j in range(k):
        f = cand[:, j]
        tri = V[F[f]]
        b = trimesh.triangles.points_to_barycentric(tri, points)
        outside = np.clip(-b, 0.0, None).sum(axis=1)
        plane = np.abs(np.einsum("ij,ij->i", points - tri[:, 0], np.asarray(mesh.face_normals)[f]))
        err = plane + outside
        better = err < best_err
        best_err[better], best_f[better], best_b[better] = err[better], f[better], b[better]
    best_b = np.clip(best_b, 0.0, None)
    best_b /= best_b.sum(axis=1, keepdims=True)
    return best_f, best_b


def local_map(
    mesh: Any,
    field: OrientationField,
    face: int,
    bary: Any,
    offsets: Any,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Map exemplar offsets to surface points around ``p`` (Davison et al. §5.1, §5.7).

    Parameters
    ----------
    mesh : trimesh.Trimesh
    field : OrientationField
        Gives the frame at ``p``.
    face : int
    bary : (3,) float
        ``p`` as a face and barycentric coordinates.
    offsets : (k, 2) float
        Offsets ``v`` in exemplar units (SVG's y-down).

    Returns
    -------
    points : (k, 3) float
        ``m_p(v)``, on the surface, at geodesic distance ``|v|`` from ``p``.
    faces : (k,) int
    bary : (k, 3) float
    """
    pp3d = require("potpourri3d")
    F = np.asarray(mesh.faces)
    if not 0 <= int(face) < len(F):
        raise InputError(f"face: index {face} outside 0..{len(F) - 1}")
    b0 = np.asarray(bary, dtype=float).reshape(3)
    off = np.asarray(offsets, dtype=float).reshape(-1, 2)
    if not np.all(np.isfinite(off)):
        raise InputError("offsets: NaN or inf")
    V = np.asarray(mesh.vertices)
    vn = np.asarray(mesh.vertex_normals)
    n = b0 @ vn[F[face]]
    n /= np.linalg.norm(n)
    t = field.at(np.array([face]), b0[None], n[None])[0]
    b = np.cross(n, t)
    key = _mesh_key(mesh)
    cached = _TRACERS.get(mesh)
    if cached is None or cached[0] != key:
        cached = (key, pp3d.GeodesicTracer(np.ascontiguousarray(V, dtype=np.float64), np.ascontiguousarray(F, dtype=np.int64)))
        _TRACERS[mesh] = cached
    tracer = cached[1]
    start = b0 @ V[F[face]]
    out = np.empty((len(off), 3))
    for i, (u, w) in enumerate(off):
        d = u * t - w * b
        if u == 0.0 and w == 0.0:
            out[i] = start
            continue
        out[i] = tracer.trace_geodesic_from_face(int(face), b0, d)[-1]
    faces, bc = locate(mesh, out)
    return out, faces, bc


def chart(arr: Any, mesh: Any, center: Any, radius: float) -> Any:
    """The elements within geodesic distance ``radius`` of ``center`` in a flat chart.

    The chart is the logarithmic map at the mesh vertex nearest ``center`` (potpourri3d's
    vector heat method): each element's position becomes its geodesic polar coordinates,
    as ``(u, -v)`` in the vertex's tangent basis so that shapes keep their handedness
    (see :mod:`._frames`), and its rotation is its tangent's direction in the chart. With
    it, 2D measures (``strew.metrics.fidelity``) apply in the tangent plane (issue 20
    point 8).

    Parameters
    ----------
    arr : Arrangement
        A surface arrangement on ``mesh`` (with its ``face`` column).
    mesh : trimesh.Trimesh
    center : (3,) float
    radius : float
        Geodesic radius of the chart; keep it well inside the cut locus of ``center``.

    Returns
    -------
    Arrangement
        2D, with the disc of ``radius`` about the origin as its region.
    """
    import shapely

    from ..arrangement import Arrangement
    from ..region import Region

    pp3d = require("potpourri3d")
    if "face" not in arr.columns:
        raise InputError("elements.face: missing column (a surface arrangement made by strew.surface.pack)")
    try:
        radius = float(radius)
    except (TypeError, ValueError):
        raise InputError(f"radius: must be a number, got {radius!r}") from None
    if not np.isfinite(radius) or radius <= 0:
        raise InputError(f"radius: must be positive, got {radius!r}")
    c = np.asarray(center, dtype=float).reshape(-1)
    if c.shape != (3,) or not np.all(np.isfinite(c)):
        raise InputError("center: must be a finite 3D point")
    V = np.asarray(mesh.vertices, dtype=np.float64)
    F = np.asarray(mesh.faces, dtype=np.int64)
    v0 = int(np.argmin(np.linalg.norm(V - c, axis=1)))
    key = _mesh_key(mesh)
    cached = _SOLVERS.get(mesh)
    if cached is None or cached[0] != key:
        cached = (key, pp3d.MeshVectorHeatSolver(np.ascontiguousarray(V), np.ascontiguousarray(F)))
        _SOLVERS[mesh] = cached
    log = np.asarray(cached[1].compute_log_map(v0))
    log[:, 1] *= -1.0  # (u, -v): y-down like the exemplar space
    f = np.asarray(arr.columns["face"], dtype=np.int64)
    p = np.column_stack([arr.x, arr.y, arr.columns["z"]])
    tri = V[F[f]]
    trimesh = require("trimesh")
    bary = trimesh.triangles.points_to_barycentric(tri, p)
    uv = np.einsum("ik,ikj->ij", bary, log[F[f]])
    # the tangent through each face's affine chart map: t = E a, chart vector = L a
    E = np.stack([tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]], axis=2)  # (m, 3, 2)
    Lm = np.stack([log[F[f, 1]] - log[F[f, 0]], log[F[f, 2]] - log[F[f, 0]]], axis=2)  # (m, 2, 2)
    t = np.column_stack([arr.columns["tx"], arr.columns["ty"], arr.columns["tz"]])
    a = np.linalg.solve(np.einsum("mji,mjk->mik", E, E), np.einsum("mji,mj->mi", E, t)[..., None])[..., 0]
    tv = np.einsum("mij,mj->mi", Lm, a)
    keep = np.hypot(uv[:, 0], uv[:, 1]) < radius
    return Arrangement(
        arr.shapes, np.asarray(arr.kind)[keep], uv[keep, 0], uv[keep, 1], np.arctan2(tv[keep, 1], tv[keep, 0]),
        np.asarray(arr.scale)[keep], region=Region(shapely.Point(0.0, 0.0).buffer(radius, quad_segs=32)),
        meta={"chart": {"vertex": v0, "radius": radius}},
    )
