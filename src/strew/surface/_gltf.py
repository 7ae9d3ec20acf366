"""GLB/glTF output of surface arrangements (issue 20, point 5).

One glTF mesh per kind and one node per element that references it (instancing by
shared meshes, which Blender, three.js, Godot and Unity all read), written by trimesh;
or, with ``instancing=True``, one node per kind with the ``EXT_mesh_gpu_instancing``
extension (per-instance translation, rotation and scale).
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


def to_glb(arr: Arrangement, *, instancing: bool = False, **kwargs: Any) -> bytes:
    """GLB bytes of :func:`to_scene` (same arguments).

    With ``instancing``, each kind is one node carrying the ``EXT_mesh_gpu_instancing``
    extension (per-instance TRANSLATION, ROTATION, SCALE accessors) instead of one node
    per element: a smaller file that three.js and Blender (4.x) draw as GPU instances.
    The extension is declared used but not required, so readers without it still open
    the file (and draw one copy of each kind).
    """
    if not instancing:
        return bytes(to_scene(arr, **kwargs).export(file_type="glb"))
    return _instanced_glb(arr, **kwargs)


def _instanced_glb(arr: Arrangement, *, mesh: Any = None, element_meshes: Mapping[str, Any] | None = None,
                   style: str = "extrude") -> bytes:
    import json
    import struct

    from scipy.spatial.transform import Rotation

    trimesh = require("trimesh")
    element_meshes = dict(element_meshes or {})
    unknown = set(element_meshes) - set(arr.kinds)
    if unknown:
        raise InputError(f"element_meshes: unknown kind {sorted(unknown)[0]!r} (known: {', '.join(arr.kinds)})")
    mats = element_matrices(arr)
    scene = trimesh.Scene()
    if mesh is not None:
        scene.add_geometry(_as_trimesh(mesh, "mesh"), geom_name="surface", node_name="surface")
    kind_idx = np.asarray(arr.kind)
    rows_of: dict[str, np.ndarray] = {}
    for k, name in enumerate(arr.kinds):
        rows = np.flatnonzero(kind_idx == k)
        if len(rows) == 0:
            continue
        geom = _as_trimesh(element_meshes[name], f"element_meshes.{name}") if name in element_meshes else shape_mesh(arr.shapes[name], style=style)
        scene.add_geometry(geom, geom_name=name, node_name=f"instances:{name}")
        rows_of[f"instances:{name}"] = rows
    glb = bytes(scene.export(file_type="glb"))
    # split the GLB: header, JSON chunk, BIN chunk
    jlen = struct.unpack_from("<I", glb, 12)[0]
    doc = json.loads(glb[20:20 + jlen])
    rest = 20 + jlen
    binary = bytearray(glb[rest + 8: rest + 8 + struct.unpack_from("<I", glb, rest)[0]]) if rest < len(glb) else bytearray()
    doc.setdefault("bufferViews", [])
    doc.setdefault("accessors", [])
    if not doc.get("buffers"):
        doc["buffers"] = [{"byteLength": 0}]

    def accessor(data: np.ndarray, kind: str) -> int:
        data = np.ascontiguousarray(data, dtype=np.float32)
        while len(binary) % 4:
            binary.append(0)
        doc["bufferViews"].append({"buffer": 0, "byteOffset": len(binary), "byteLength": data.nbytes})
        binary.extend(data.tobytes())
        doc["accessors"].append({"bufferView": len(doc["bufferViews"]) - 1, "componentType": 5126, "count": int(len(data)),
                                 "type": kind, "min": data.min(axis=0).tolist(), "max": data.max(axis=0).tolist()})
        return len(doc["accessors"]) - 1

    for node in doc.get("nodes", []):
        rows = rows_of.get(node.get("name", ""))
        if rows is None:
            continue
        m = mats[rows]
        s = np.linalg.norm(m[:, :3, 0], axis=1)
        rot = m[:, :3, :3] / s[:, None, None]
        quat = Rotation.from_matrix(rot).as_quat()  # (x, y, z, w), as glTF stores them
        node.pop("matrix", None)
        node["extensions"] = {"EXT_mesh_gpu_instancing": {"attributes": {
            "TRANSLATION": accessor(m[:, :3, 3], "VEC3"),
            "ROTATION": accessor(quat, "VEC4"),
            "SCALE": accessor(np.repeat(s[:, None], 3, axis=1), "VEC3"),
        }}}
    doc["buffers"][0]["byteLength"] = len(binary)
    used = doc.setdefault("extensionsUsed", [])
    if "EXT_mesh_gpu_instancing" not in used:
        used.append("EXT_mesh_gpu_instancing")
    text = json.dumps(doc, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    while len(binary) % 4:
        binary.append(0)
    total = 12 + 8 + len(text) + 8 + len(binary)
    return (struct.pack("<III", 0x46546C67, 2, total) + struct.pack("<I", len(text)) + b"JSON" + text
            + struct.pack("<I", len(binary)) + b"BIN\x00" + bytes(binary))


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
