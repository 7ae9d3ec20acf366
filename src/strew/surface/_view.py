"""Visibility from a camera for view-based synthesis (Davison et al. §5.8).

Davison et al. test whether a free-space point is occluded with the GPU's depth buffer.
:class:`Camera` does the same on the CPU: the mesh is rasterised once into a depth
buffer (a compiled scan over each triangle's pixel bounding box, perspective
projection), and a point is visible when it lies in the view frustum, faces the camera
and is no further than the buffer's depth at its pixel (plus a small tolerance).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numba
import numpy as np

from .._errors import InputError

__all__ = ["Camera"]


@numba.njit(cache=True)
def _rasterise(sx: np.ndarray, sy: np.ndarray, sz: np.ndarray, faces: np.ndarray, size: int) -> np.ndarray:
    """Depth buffer (size, size) of triangles given in pixel coordinates and view depth."""
    buf = np.full((size, size), np.inf)
    for f in range(faces.shape[0]):
        a, b, c = faces[f, 0], faces[f, 1], faces[f, 2]
        za, zb, zc = sz[a], sz[b], sz[c]
        if za <= 0.0 or zb <= 0.0 or zc <= 0.0:
            continue  # behind the eye (triangles crossing the near plane are skipped)
        xa, ya, xb, yb, xc, yc = sx[a], sy[a], sx[b], sy[b], sx[c], sy[c]
        den = (yb - yc) * (xa - xc) + (xc - xb) * (ya - yc)
        if abs(den) < 1e-14:
            continue
        x0 = max(int(np.floor(min(xa, min(xb, xc)))), 0)
        x1 = min(int(np.ceil(max(xa, max(xb, xc)))), size - 1)
        y0 = max(int(np.floor(min(ya, min(yb, yc)))), 0)
        y1 = min(int(np.ceil(max(ya, max(yb, yc)))), size - 1)
        for py in range(y0, y1 + 1):
            for px in range(x0, x1 + 1):
                x = px + 0.5
                y = py + 0.5
                l0 = ((yb - yc) * (x - xc) + (xc - xb) * (y - yc)) / den
                l1 = ((yc - ya) * (x - xc) + (xa - xc) * (y - yc)) / den
                l2 = 1.0 - l0 - l1
                if l0 < -1e-9 or l1 < -1e-9 or l2 < -1e-9:
                    continue
                # perspective-correct depth: 1/z is affine in screen space
                z = 1.0 / (l0 / za + l1 / zb + l2 / zc)
                if z < buf[py, px]:
                    buf[py, px] = z
    return buf


@dataclass(eq=False)
class Camera:
    """A pinhole camera looking at a mesh.

    Parameters
    ----------
    eye : (3,) float
        Camera position.
    target : (3,) float
        Point looked at.
    up : (3,) float, optional
        Up direction (not along the view direction); default +z, or +y when looking
        along z.
    fov : float
        Vertical field of view in degrees.
    size : int
        Side of the depth buffer in pixels.
    """

    eye: Any
    target: Any = (0.0, 0.0, 0.0)
    up: Any = None
    fov: float = 45.0
    size: int = 256
    _buf: np.ndarray | None = field(default=None, repr=False)
    _mesh: Any = field(default=None, repr=False)

    def __post_init__(self) -> None:
        if self.up is None:
            d = np.asarray(self.target, dtype=float).reshape(-1) - np.asarray(self.eye, dtype=float).reshape(-1)
            self.up = (0.0, 1.0, 0.0) if d.shape == (3,) and abs(d[2]) > 0.99 * np.linalg.norm(d) else (0.0, 0.0, 1.0)
        for name in ("eye", "target", "up"):
            v = np.asarray(getattr(self, name), dtype=float).reshape(-1)
            if v.shape != (3,) or not np.all(np.isfinite(v)):
                raise InputError(f"camera.{name}: must be a finite 3D point, got {getattr(self, name)!r}")
            setattr(self, name, v)
        fwd = self.target - self.eye
        if np.linalg.norm(fwd) < 1e-12:
            raise InputError("camera: eye and target coincide")
        self._fwd = fwd / np.linalg.norm(fwd)
        right = np.cross(self._fwd, self.up)
        if np.linalg.norm(right) < 1e-9:
            raise InputError("camera.up: must not be along the view direction")
        self._right = right / np.linalg.norm(right)
        self._upv = np.cross(self._right, self._fwd)
        if not (0.0 < float(self.fov) < 179.0):
            raise InputError(f"camera.fov: expected degrees in (0, 179), got {self.fov!r}")
        if isinstance(self.size, bool) or not isinstance(self.size, (int, np.integer)) or not 16 <= self.size <= 4096:
            raise InputError(f"camera.size: expected an integer in 16..4096, got {self.size!r}")
        self._f = 0.5 * self.size / np.tan(np.radians(float(self.fov)) / 2.0)

    def project(self, points: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Pixel coordinates ``(sx, sy)`` and view depth ``z`` (along the view direction)."""
        d = np.asarray(points, dtype=float) - self.eye
        z = d @ self._fwd
        zs = np.where(z > 1e-12, z, 1e-12)
        sx = 0.5 * self.size + self._f * (d @ self._right) / zs
        sy = 0.5 * self.size - self._f * (d @ self._upv) / zs
        return sx, sy, z

    def depth(self, mesh: Any) -> np.ndarray:
        """(size, size) float: the depth buffer of ``mesh`` (computed once per mesh)."""
        if self._buf is None or self._mesh is not mesh:
            sx, sy, z = self.project(np.asarray(mesh.vertices))
            self._buf = _rasterise(sx, sy, z, np.ascontiguousarray(mesh.faces, dtype=np.int64), int(self.size))
            self._mesh = mesh
        return self._buf

    def visible(self, mesh: Any, points: np.ndarray, normals: np.ndarray | None = None) -> np.ndarray:
        """(m,) bool: points of the surface the camera sees (§5.8).

        A point is visible when it projects inside the image, is in front of the eye,
        faces the camera (with ``normals``) and is not behind the depth buffer by more
        than 1 % of its depth plus two pixels' footprint.
        """
        pts = np.asarray(points, dtype=float).reshape(-1, 3)
        buf = self.depth(mesh)
        sx, sy, z = self.project(pts)
        px = np.floor(sx).astype(np.int64)
        py = np.floor(sy).astype(np.int64)
        ok = (z > 0) & (px >= 0) & (px < self.size) & (py >= 0) & (py < self.size)
        if normals is not None:
            ok &= np.einsum("ij,ij->i", np.asarray(normals, dtype=float).reshape(-1, 3), self.eye - pts) > 0
        tol = 0.01 * z + 2.0 * z / self._f
        zb = buf[np.clip(py, 0, self.size - 1), np.clip(px, 0, self.size - 1)]
        ok &= z <= zb + tol
        return ok
