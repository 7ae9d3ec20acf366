"""GLB/glTF output of surface arrangements (issue 20, point 5).

One glTF mesh per kind and one node per element that references it (instancing by
shared meshes, which Blender, three.js, Godot and Unity all read), written by trimesh.
A kind is drawn by its own 3D mesh where one is given (``element_meshes``), otherwise
its 2D shape becomes a thin slab (``"extrude"``) or a flat decal (``"decal"``) in the
element's tangent plane. The base surface goes in as the node ``surface``.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np
import shapely

from .._errors import InputError
from ..arrangement import Arrangement
from ..io._atomic import atomic_write
from ..shape import Shape
from ._deps import require
from ._frames import element_matrices
from ._mesh import _as_trimesh

__all__ = ["shape_mesh", "to_scene", "to_glb", "save_glb"]

_STYLES = ("extrude", "decal")


def _triangulate(geom: shapely.Geometry) -> tuple[np.ndarray, np.ndarray]:
    tris = shapely.get_parts(shapely.constrained_delaunay_triangles(geom))
    tris = tris[~shapely.is_empty(tris)]
    if len(tris) == 0:
        return np.zeros((0, 2)), np.zeros((0, 3), dtype=np.int64)
    coords = np.stack([np.asarray(t.exterior.coords)[:3] for t in tris])  # (m, 3, 2)
    flat = coords.reshape(-1, 2)
    verts, inv = np.unique(np.round(flat, 12), axis=0, return_inverse=True)
    faces = inv.reshape(-1, 3).astype(np.int64)
    # counter-clockwise seen from +z (the normal side)
    a, b, c = verts[faces[:, 0]], verts[faces[:, 1]], verts[faces[:, 2]]
    cw = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]) < 0
    faces[cw] = faces[cw][:, ::-1]
    return verts, faces


def shape_mesh(shape: Shape, *, style: str = "extrude", height: float | None = None) -> Any:
    """A trimesh for a 2D shape in the element frame (x tangent, y = n x t, z normal).

    The shape's y axis is mirrored (SVG's y-down becomes y-up) so that it reads the same
    seen from outside the surface. Open paths are drawn as thin ribbons.

    Parameters
    ----------
    shape : Shape
    style : {"extrude", "decal"}
        A slab of ``height`` (default a fifth of the shape's radius) standing on the
        surface, or a flat decal lifted by a thousandth of the radius.
    """
    trimesh = require("trimesh")
    if style not in _STYLES:
        raise InputError(f"style: expected one of {', '.join(_STYLES)}, got {style!r}")
    geom = shape.area_geometry
    r = max(shape.radius, 1e-12)
    if geom.is_empty or geom.area <= 1e-12 * r * r:
        geom = shape.line_geometry.buffer(0.03 * r)
    geom = shapely.affinity.scale(geom, 1.0, -1.0, origin=(0.0, 0.0))
    geom = shapely.make_valid(geom)
    verts, faces = _triangulate(geom)
    if len(faces) == 0:
        raise InputError("shape: nothing to draw in 3D (no area and no strokes)")
    if style == "decal":
        v3 = np.column_stack([verts, np.full(len(verts), 1e-3 * r)])
        return trimesh.Trimesh(v3, faces, process=False)
    h = 0.2 * r if height is None else float(height)
    return trimesh.creation.extrude_triangulation(verts, faces, h)


def to_scene(
    arr: Arrangement,
    *,
    mesh: Any = None,
    element_meshes: Mapping[str, Any] | None = None,
    style: str = "extrude",
) -> Any:
    """A :class:`trimesh.Scene`: the surface (optional) and one node per element.

    Parameters
    ----------
    arr : Arrangement
        A surface arrangement (3D columns, see :mod:`strew.surface`).
    mesh : path or trimesh.Trimesh, optional
        The surface, added as node ``"surface"``.
    element_meshes : mapping of kind -> path or trimesh.Trimesh, optional
        3D meshes for kinds (in the element frame, scaled by the element's scale).
    style : {"extrude", "decal"}
        How kinds without a mesh are drawn.
    """
    trimesh = require("trimesh")
    mats = element_matrices(arr)
    element_meshes = dict(element_meshes or {})
    unknown = set(element_meshes) - set(arr.kinds)
    if unknown:
        raise InputError(f"element_meshes: unknown kind {sorted(unknown)[0]!r} (known: {', '.join(arr.kinds)})")
    scene = trimesh.Scene()
    if mesh is not None:
        scene.add_geometry(_as_trimesh(mesh, "mesh"), geom_name="surface", node_name="surface")
    base = scene.graph.base_frame
    kind_idx = np.asarray(arr.kind)
    for k, name in enumerate(arr.kinds):
        rows = np.flatnonzero(kind_idx == k)
        if len(rows) == 0:
            continue
        if name in element_meshes:
            geom = _as_trimesh(element_meshes[name], f"element_meshes.{name}")
        else:
            geom = shape_mesh(arr.shapes[name], style=style)
        scene.add_geometry(geom, geom_name=name, node_name=f"{name}#{rows[0]}", transform=mats[rows[0]])
        for i in rows[1:].tolist():
            scene.graph.update(frame_from=base, frame_to=f"{name}#{i}", matrix=mats[i], geometry=name)
    scene.metadata["strew"] = {"elements": len(arr), "kinds": list(arr.kinds)}
    return scene


def to_glb(arr: Arrangement, **kwargs: Any) -> bytes:
    """GLB bytes of :func:`to_scene` (same arguments)."""
    data = to_scene(arr, **kwargs).export(file_type="glb")
    return bytes(data)


def save_glb(arr: Arrangement, path: str | os.PathLike[str], **kwargs: Any) -> Path:
    """Write a surface arrangement as ``.glb`` (atomically); ``kwargs`` as :func:`to_scene`.

    Examples
    --------
    >>> import trimesh, tempfile, os
    >>> from strew.surface import pack
    >>> m = trimesh.creation.icosphere(subdivisions=2)
    >>> a = pack(0.2, m, rng=1, field=None)
    >>> out = save_glb(a, os.path.join(tempfile.mkdtemp(), "scene.glb"), mesh=m)
    >>> len(trimesh.load(out).graph.nodes_geometry) == len(a) + 1
    True
    """
    if Path(path).suffix.lower() != ".glb":
        raise InputError(f"--out {str(path)!r}: a 3D scene is written as .glb")
    parent = Path(path).parent
    if not parent.exists():
        raise InputError(f"--out {str(path)!r}: folder {str(parent)!r} does not exist")
    return atomic_write(path, to_glb(arr, **kwargs))
