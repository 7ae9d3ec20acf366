"""A PNG preview of a surface arrangement without a GPU (issue 20, point 5).

A small painter's-algorithm renderer on matplotlib's Agg backend: the surface's
triangles and the elements' outlines (their 2D shapes laid in the tangent plane and
lifted a little along the normal) are projected orthographically, shaded with one
directional light, sorted back to front and drawn as one polygon collection. Faces
turned away from the viewer are culled.
"""

from __future__ import annotations

import io
import os
from pathlib import Path
from typing import Any

import numpy as np

from .._errors import InputError
from ..arrangement import Arrangement
from ..io._atomic import atomic_write
from ._frames import element_frames
from ._mesh import _as_trimesh

__all__ = ["render_preview", "save_preview"]


def _camera(elevation: float, azimuth: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    el, az = np.radians(elevation), np.radians(azimuth)
    view = np.array([np.cos(el) * np.cos(az), np.cos(el) * np.sin(az), np.sin(el)])  # towards the viewer
    right = np.cross([0.0, 0.0, 1.0], view)
    right = right / np.linalg.norm(right) if np.linalg.norm(right) > 1e-9 else np.array([1.0, 0.0, 0.0])
    up = np.cross(view, right)
    return view, right, up


def render_preview(
    arr: Arrangement,
    mesh: Any = None,
    *,
    size: int = 800,
    elevation: float = 25.0,
    azimuth: float = -60.0,
    max_faces: int = 200_000,
) -> bytes:
    """PNG bytes of the surface and its elements seen from (elevation, azimuth) degrees.

    Parameters
    ----------
    arr : Arrangement
        A surface arrangement.
    mesh : path or trimesh.Trimesh, optional
        The surface to draw under the elements.
    size : int
        Width and height in pixels.
    """
    import matplotlib

    matplotlib.use("Agg", force=False)
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.collections import PolyCollection
    from matplotlib.figure import Figure

    if isinstance(size, bool) or not isinstance(size, (int, np.integer)) or not 16 <= size <= 8192:
        raise InputError(f"size: expected an integer in 16..8192, got {size!r}")
    view, right, up = _camera(float(elevation), float(azimuth))
    light = view + 0.6 * up + 0.3 * right
    light /= np.linalg.norm(light)
    bias = 0.0
    polys: list[np.ndarray] = []
    depth: list[np.ndarray] = []
    colors: list[np.ndarray] = []
    if mesh is not None:
        m = _as_trimesh(mesh, "mesh")
        if len(m.faces) > max_faces:
            raise InputError(f"mesh: {len(m.faces)} faces is over the preview's {max_faces}")
        tri = np.asarray(m.vertices)[np.asarray(m.faces)]
        bias = float(np.mean(m.edges_unique_length))
        fn = np.asarray(m.face_normals)
        front = fn @ view > 0
        tri, fn = tri[front], fn[front]
        shade = 0.35 + 0.6 * np.clip(fn @ light, 0.0, 1.0)
        polys.extend(np.stack([tri @ right, tri @ up], axis=2))
        depth.append(tri.mean(axis=1) @ view)
        colors.append(np.column_stack([shade * 0.80, shade * 0.82, shade * 0.86, np.ones_like(shade)]))
    if len(arr):
        p, n, t, b, s = element_frames(arr)
        front = n @ view > 0
        palette = np.array([[0.80, 0.36, 0.20], [0.20, 0.50, 0.75], [0.35, 0.62, 0.30], [0.85, 0.65, 0.15], [0.55, 0.35, 0.70]])
        radius = np.asarray(arr.columns.get("radius", s), dtype=float)
        lift = radius * 0.05
        for k, name in enumerate(arr.kinds):
            rows = np.flatnonzero((np.asarray(arr.kind) == k) & front)
            shape = arr.shapes[name]
            outline = max(shape.paths, key=lambda q: len(q.points)).points if shape.paths else np.zeros((0, 2))
            if len(rows) == 0 or len(outline) < 3:
                continue
            u, v = outline[:, 0], -outline[:, 1]  # SVG y-down -> the frame's b axis (see _frames)
            world = (p[rows, None, :] + (lift[rows] + 0.0)[:, None, None] * n[rows, None, :]
                     + s[rows, None, None] * (u[None, :, None] * t[rows, None, :] + v[None, :, None] * b[rows, None, :]))
            polys.extend(np.stack([world @ right, world @ up], axis=2))
            # painter's bias: an element is drawn after the triangles it lies on
            depth.append(p[rows] @ view + 1.5 * radius[rows] + bias)
            shade = 0.45 + 0.55 * np.clip(n[rows] @ light, 0.0, 1.0)
            c = palette[k % len(palette)]
            colors.append(np.column_stack([shade * c[0], shade * c[1], shade * c[2], np.ones_like(shade)]))
    fig = Figure(figsize=(size / 100, size / 100), dpi=100)
    FigureCanvasAgg(fig)
    ax = fig.add_axes((0, 0, 1, 1))
    ax.set_axis_off()
    ax.set_aspect("equal")
    if polys:
        order = np.argsort(np.concatenate(depth), kind="stable")
        allc = np.concatenate(colors)[order]
        coll = PolyCollection([polys[i] for i in order.tolist()], facecolors=allc, edgecolors=allc, linewidths=0.2)
        ax.add_collection(coll)
        pts = np.concatenate([q for q in polys])
        lo, hi = pts.min(axis=0), pts.max(axis=0)
        c, half = (lo + hi) / 2, 0.52 * float(max(hi - lo))
        ax.set_xlim(c[0] - half, c[0] + half)
        ax.set_ylim(c[1] - half, c[1] + half)
    buf = io.BytesIO()
    fig.savefig(buf, format="png", facecolor="white")
    return buf.getvalue()


def save_preview(arr: Arrangement, path: str | os.PathLike[str], mesh: Any = None, **kwargs: Any) -> Path:
    """Write :func:`render_preview` to ``path`` (.png, atomically)."""
    if Path(path).suffix.lower() != ".png":
        raise InputError(f"--out {str(path)!r}: the preview is written as .png")
    return atomic_write(path, render_preview(arr, mesh, **kwargs))
