"""Element textures on 3D surfaces (Davison et al. §5.7; Sakurai & Miyata §5.3).

Needs the ``surface`` extra (``pip install 'strew[surface]'``: trimesh, potpourri3d).

Public entry points:

:func:`load_mesh`
    Read and validate a triangle mesh (OBJ, PLY, STL, OFF, GLB/glTF).
:func:`orientation_field`
    A smooth tangent direction field (automatic, from strokes or from singularities).
:func:`pack`
    Poisson disk and fill-gap on the surface, bounding spheres never overlapping.
:func:`save_glb` / :func:`to_glb`
    GLB with one node per element sharing one mesh per kind, or with
    ``instancing=True`` one node per kind with EXT_mesh_gpu_instancing.
:func:`save_preview` / :func:`render_preview`
    A PNG preview without a GPU.
:func:`chart`
    Elements near a point in a flat geodesic chart (log map), for 2D metrics.
:func:`lift`
    A flat arrangement as 3D elements on a plane (GLB output of 2D results).
:func:`local_map`
    Davison's m_p (§5.1, §5.7): exemplar offsets to surface points by a geodesic walk
    in the field's frame.
:func:`grow`
    Ijiri et al.'s growth from one seed on the surface, in the field's frame (§5).
:func:`synthesize` / :func:`new_synth_state`
    Davison et al.'s region growing on the surface (§5.7) with the brush, filler and
    eraser (§5.4) on a :class:`SurfaceSynthState`, and view priority (§5.8) with a
    :class:`Camera`.

A surface arrangement is a :class:`strew.Arrangement` with the columns
``z nx ny nz tx ty tz`` (see :mod:`strew.surface._frames`); ``strew.save(arr,
"scene.json")`` writes it as a version 2 document.
"""

from __future__ import annotations

from ._field import OrientationField, load_field, orientation_field
from ._frames import SURFACE_COLUMNS, element_frames, element_matrices, is_surface, lift
from ._grow import grow
from ._gltf import save_glb, shape_mesh, to_glb, to_scene
from ._mesh import MESH_FORMATS, load_mesh
from ._preview import render_preview, save_preview
from ._sample import pack
from ._synth import SurfaceSynthState, new_synth_state, synthesize
from ._view import Camera
from ._walk import chart, local_map, locate

__all__ = [
    "Camera",
    "SurfaceSynthState",
    "new_synth_state",
    "synthesize",
    "grow",
    "chart",
    "MESH_FORMATS",
    "OrientationField",
    "SURFACE_COLUMNS",
    "element_frames",
    "element_matrices",
    "is_surface",
    "lift",
    "load_field",
    "load_mesh",
    "local_map",
    "locate",
    "orientation_field",
    "pack",
    "render_preview",
    "save_glb",
    "save_preview",
    "shape_mesh",
    "to_glb",
    "to_scene",
]
