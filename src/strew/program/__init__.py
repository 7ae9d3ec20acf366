"""Programmable stationary arrangements (Loi, Hurtut, Vergne, Thollot, Inria RR-8713, 2015).

A script builds an *arrangement*, a function of a region that returns curves (§3), from
three kinds of operators, all named as in the paper's appendix tables (in snake_case):

- partitions (Table 1): :func:`stripes_partition`, :func:`grid_partition`,
  :func:`uniform_partition`, :func:`random_partition`, their properties and labels, and
  the border options :data:`CROP`, :data:`CROP_ADD_BOUNDARY`, :data:`KEEP_INSIDE`,
  :data:`KEEP_OUTSIDE` (§5.2);
- mapping operators (Table 2): :func:`map_to_vertices`, :func:`map_to_edges`,
  :func:`map_to_faces`, which apply a user *mapper* to every cell; mappers use the
  built-ins of Table 3 (incidence, adjacency, geometry, labels, random values);
- merging operators (Table 4): :func:`union`, :func:`inside`, :func:`outside`;

plus the utilities of Table 5 (:func:`import_svg`, :func:`export_svg`, bounding boxes,
:func:`scale`, :func:`rotate`, :func:`translate`, :func:`nothing`).

Evaluating an arrangement on a region gives a planar map (§4)::

    from strew.program import *

    grid = grid_partition(stripes_properties(0, 50), stripes_properties(pi / 2, 50), CROP)
    arrangement = map_to_faces(lambda f: scale(contour(f), 0.8), grid)
    pm = arrangement(2000)            # PlanarMap on [0, 2000]^2

``strew run SCRIPT.py --out out.svg`` runs a script and evaluates its module-level
``arrangement``. Besides ``__all__`` (exactly the paper's operators and the border
constants), this module offers :class:`PlanarMap`, :class:`Curves`, :func:`evaluate`,
:func:`run` (the method contract: script and region in, Arrangement out, provenance in
``meta``), :func:`run_script` (the planar map too) and :func:`to_strew` for use from Python, and :func:`run_size` (the
``--size`` a script is run at) for scripts that scale with it.

Worlds too large for one evaluation (issue 19.1): ``strew world program SCRIPT --size WxH
--tile-size T [--halo H] [--workers N] --out world.parquet`` (or
``strew.tiles.world("program", SCRIPT, (W, H), tile_size=T)``) evaluates the script tile
by tile; the partitions are fixed in the plane and every random value is keyed by what it
draws, so the tiles' pieces make the map of one evaluation whatever ``T`` and ``N``, as
long as the halo holds every cell that reaches into a tile (see ``strew.program._world``).
"""

from __future__ import annotations

from math import pi  # noqa: F401  (handy in scripts; not exported by *)

from ._builtins import (
    append,
    bbox_center,
    bbox_height,
    bbox_width,
    centroid,
    contour,
    curve_labeled,
    has_label,
    incident_edges,
    incident_faces,
    incident_vertices,
    is_boundary,
    left_face,
    location,
    location_at,
    match_face,
    match_point,
    match_points,
    nothing,
    point_labeled,
    random,
    right_face,
    rotate,
    scale,
    source_vertex,
    target_vertex,
    to_curve,
    translate,
)
from ._curves import Curve, Curves
from ._operators import (
    CROP,
    CROP_ADD_BOUNDARY,
    KEEP_INSIDE,
    KEEP_OUTSIDE,
    ArrangementFunction,
    Border,
    MapperError,
    grid_partition,
    inside,
    irregular_properties,
    map_to_edges,
    map_to_faces,
    map_to_vertices,
    outside,
    random_partition,
    set_edge_labels,
    set_face_labels,
    set_weighted_edge_labels,
    set_weighted_face_labels,
    set_weighted_vertex_labels,
    stripes_partition,
    stripes_properties,
    uniform_partition,
    union,
)
from ._planar_map import DEFAULT_GRID, Edge, Face, PlanarMap, Vertex, induce
from ._script import SPEC, ScriptError, evaluate, export_svg, import_svg, run, run_script, run_size, to_strew

__all__ = [
    # Table 1: partition operators
    "stripes_properties",
    "set_edge_labels",
    "set_face_labels",
    "stripes_partition",
    "grid_partition",
    "irregular_properties",
    "set_weighted_vertex_labels",
    "set_weighted_edge_labels",
    "set_weighted_face_labels",
    "uniform_partition",
    "random_partition",
    # §5.2: border options
    "CROP",
    "CROP_ADD_BOUNDARY",
    "KEEP_INSIDE",
    "KEEP_OUTSIDE",
    # Table 2: mapping operators
    "map_to_vertices",
    "map_to_edges",
    "map_to_faces",
    # Table 3: mappers' built-in operators
    "incident_faces",
    "incident_edges",
    "incident_vertices",
    "source_vertex",
    "target_vertex",
    "left_face",
    "right_face",
    "match_point",
    "match_points",
    "match_face",
    "location",
    "location_at",
    "centroid",
    "contour",
    "append",
    "to_curve",
    "has_label",
    "is_boundary",
    "point_labeled",
    "curve_labeled",
    "random",
    # Table 4: merging operators
    "union",
    "inside",
    "outside",
    # Table 5: useful functions
    "import_svg",
    "export_svg",
    "bbox_width",
    "bbox_height",
    "bbox_center",
    "scale",
    "rotate",
    "translate",
    "nothing",
]

# Not in __all__ (``from strew.program import *`` brings only the paper's names):
_EXTRAS = (
    ArrangementFunction,
    Border,
    Curve,
    Curves,
    DEFAULT_GRID,
    Edge,
    Face,
    MapperError,
    PlanarMap,
    ScriptError,
    Vertex,
    evaluate,
    induce,
    run,
    run_script,
    SPEC,
    run_size,
    to_strew,
)
