"""The studio's 3D view (issue 20.7): a loaded mesh, and the generative brush on it.

The browser (``static/view3d.html``, three.js served from ``static/vendor/three``) shows
the mesh with orbit, pan and zoom, picks brush points on it by raycasting and sends them;
the session calls :meth:`strew.surface.SurfaceSynthState.brush` (Davison et al. §5.4 on a
surface, §5.7) with the palette's selected exemplars. No algorithm lives here.

Messages
--------
``load_mesh`` ``{path}``
    A mesh inside PROJECT_DIR, or ``examples/meshes/NAME``; replies ``mesh`` (vertices
    (V, 3), faces (F, 3), radius) and ``elements3d``.
``brush3d`` ``{points: [[x, y, z], ...], radius}``
    Paint along the points (on or near the surface); replies ``elements3d``: positions,
    normals, tangents (m, 3), scales, bounding-sphere radii (m,), kinds (m,) indices
    into ``names``.
``clear3d``
    Remove every element on the surface.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from .._errors import InputError
from ._common import Emit
from ._paths import resolve_in_project

__all__ = ["Surface3DMixin", "MESH_SUFFIXES", "MAX_MESH_FACES"]

MESH_SUFFIXES = (".ply", ".obj", ".stl", ".off", ".glb", ".gltf")
#: Largest mesh the 3D view loads (its vertices and faces travel as JSON).
MAX_MESH_FACES = 200_000


class Surface3DMixin:
    """The 3D view's part of :class:`~strew.studio._session.Session`."""

    mesh3d: Any = None
    surf3d: Any = None  # strew.surface.SurfaceSynthState, or None
    surf3d_version = -1

    def _mesh_path(self, name: Any) -> Path:
        if isinstance(name, str) and name.startswith("examples/meshes/"):
            from .._resources import examples_dir

            base = examples_dir() / "meshes"
            path = (base / name[len("examples/meshes/"):]).resolve()
            if path.parent != base.resolve() or path.suffix.lower() not in MESH_SUFFIXES or not path.is_file():
                raise InputError(f"load_mesh.path: no example mesh {name[:80]!r}")
            return path
        return resolve_in_project(self.root, name, suffixes=MESH_SUFFIXES, must_exist=True)

    def _on_load_mesh(self, msg: dict, emit: Emit) -> list[dict]:
        from .. import surface

        mesh = surface.load_mesh(self._mesh_path(msg.get("path")))
        if len(mesh.faces) > MAX_MESH_FACES:
            raise InputError(f"load_mesh: {len(mesh.faces)} faces is over the 3D view's limit of {MAX_MESH_FACES}")
        self.mesh3d, self.surf3d = mesh, None
        V = np.asarray(mesh.vertices, float)
        centre = V.mean(axis=0)
        radius = float(np.linalg.norm(V - centre, axis=1).max())
        reply = {"type": "mesh", "vertices": np.round(V, 6).ravel(), "faces": np.asarray(mesh.faces, np.int64).ravel(),
                 "centre": centre, "radius": radius}
        return [reply, self.elements3d_message(), self.status_message(f"mesh: {len(V)} vertices, {len(mesh.faces)} faces")]

    def _surface_state(self) -> Any:
        """The surface synthesis state for the palette's selection (made on first use and
        again when the palette changes; its elements are then dropped)."""
        from .. import surface
        from ..synth import Palette

        if self.mesh3d is None:
            raise InputError("brush3d: load a mesh first")
        if self.surf3d is None or self.surf3d_version != self.palette_version:
            usable = self._usable()
            if not usable:
                raise InputError("brush3d: the palette has no usable exemplar")
            self.surf3d = surface.new_synth_state(Palette(usable), self.mesh3d, selection=self._selection(),
                                                  rng=int(self.rng.integers(2**31)))
            self.surf3d_version = self.palette_version
        return self.surf3d

    def _on_brush3d(self, msg: dict, emit: Emit) -> list[dict]:
        pts = _points3(msg.get("points"))
        radius = msg.get("radius")
        if isinstance(radius, bool) or not isinstance(radius, (int, float)) or not np.isfinite(radius) or radius <= 0:
            raise InputError(f"brush3d.radius: expected a positive number, got {str(radius)[:40]!r}")
        st = self._surface_state()
        added = st.brush(pts, float(radius))
        return [self.elements3d_message(), self.status_message(f"3D brush: {added} elements added")]

    def _on_clear3d(self, msg: dict, emit: Emit) -> list[dict]:
        self.surf3d = None
        return [self.elements3d_message(), self.status_message("surface cleared")]

    def elements3d_message(self) -> dict[str, Any]:
        """The elements on the surface as flat arrays for instanced drawing."""
        empty: dict[str, Any] = {"type": "elements3d", "count": 0, "positions": [], "normals": [], "tangents": [],
                                 "scales": [], "radii": [], "kinds": [], "names": []}
        st = self.surf3d
        if st is None or st.n == 0:
            return empty
        from ..surface import element_frames

        arr = st.to_arrangement()
        p, n, t, _, s = element_frames(arr)
        return {"type": "elements3d", "count": len(arr), "positions": np.round(p, 6).ravel(), "normals": np.round(n, 5).ravel(),
                "tangents": np.round(t, 5).ravel(), "scales": np.round(s, 6),
                "radii": np.round(np.asarray(arr["radius"], float), 6), "kinds": np.asarray(arr.kind, np.int64),
                "names": list(arr.kinds)}


def _points3(raw: Any) -> np.ndarray:
    from ._protocol import MAX_POINTS

    if not isinstance(raw, list) or not 1 <= len(raw) <= MAX_POINTS:
        raise InputError(f"brush3d.points: expected 1 to {MAX_POINTS} points [x, y, z]")
    try:
        pts = np.array(raw, dtype=float)
    except (TypeError, ValueError):
        raise InputError("brush3d.points: expected a list of [x, y, z] numbers") from None
    if pts.ndim != 2 or pts.shape[1] != 3 or not np.isfinite(pts).all():
        raise InputError("brush3d.points: expected a list of finite [x, y, z] numbers")
    return pts
