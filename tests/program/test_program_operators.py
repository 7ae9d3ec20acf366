"""Partitions, border options, mapping and merging operators (Loi et al. §5, §6, §7)."""

from __future__ import annotations

import math

import numpy as np
import pytest
import shapely

import strew
from strew.program import *
from strew.program import ArrangementFunction, Curves, MapperError, PlanarMap

pi = math.pi
SQUARE = shapely.box(0, 0, 400, 400)


def test_star_import_is_exactly_the_paper_operators():
    import strew.program as P

    expected = {
        "stripes_properties", "set_edge_labels", "set_face_labels", "stripes_partition", "grid_partition",
        "irregular_properties", "set_weighted_vertex_labels", "set_weighted_edge_labels",
        "set_weighted_face_labels", "uniform_partition", "random_partition",
        "CROP", "CROP_ADD_BOUNDARY", "KEEP_INSIDE", "KEEP_OUTSIDE",
        "map_to_vertices", "map_to_edges", "map_to_faces",
        "incident_faces", "incident_edges", "incident_vertices", "source_vertex", "target_vertex",
        "left_face", "right_face", "match_point", "match_points", "match_face", "location", "location_at",
        "centroid", "contour", "append", "to_curve", "has_label", "is_boundary", "point_labeled",
        "curve_labeled", "random", "union", "inside", "outside", "import_svg", "export_svg", "bbox_width",
        "bbox_height", "bbox_center", "scale", "rotate", "translate", "nothing",
    }
    assert set(P.__all__) == expected and len(P.__all__) == len(expected)
    ns: dict = {}
    exec("from strew.program import *", ns)
    assert set(ns) - {"__builtins__"} == expected
    for name in expected - {"CROP", "CROP_ADD_BOUNDARY", "KEEP_INSIDE", "KEEP_OUTSIDE"}:
        paper = "".join(w.capitalize() for w in name.split("_")).replace("Svg", "SVG").replace("Bbox", "BBox")
        assert paper in getattr(P, name).__doc__, name


def test_stripes_partition_counts_and_cycled_labels():
    p = set_face_labels(set_edge_labels(stripes_properties(0, 20, 10), "e1", "e2"), "yellow", "blue")
    pm = stripes_partition(p, border=CROP_ADD_BOUNDARY)(shapely.box(0, 0, 300, 300))
    # 300 / 30 = 10 periods of two stripes: 20 faces, alternating widths 20 and 10
    faces = pm.bounded_faces
    assert len(faces) == 20
    for f in faces:
        h = bbox_height(f)
        assert f.labels == ({"yellow"} if np.isclose(h, 20) else {"blue"})
        assert np.isclose(h, 20) or np.isclose(h, 10)
    assert {e.labels for e in pm.edges if not is_boundary(e) or bbox_height(e) == 0} >= {frozenset({"e1"}), frozenset({"e2"})}
    # plain CROP: only the lines, no bounded face
    assert stripes_partition(p, border=CROP)(shapely.box(0, 0, 300, 300)).n_faces == 1
    # issue 21: by default, face labels close the stripes with the outline (Fig. 5a) ...
    default = stripes_partition(p)(shapely.box(0, 0, 300, 300))
    assert len(default.bounded_faces) == 20 and all(f.labels for f in default.bounded_faces)
    # ... and stripes without face labels stay open lines (a hatching)
    assert stripes_partition(stripes_properties(0, 20))(shapely.box(0, 0, 300, 300)).n_faces == 1
    with pytest.raises(strew.InputError, match="stripes faces are infinite"):
        stripes_partition(p, border=KEEP_INSIDE)


def test_grid_partition_counts_and_two_labels_per_face():
    s1 = set_face_labels(stripes_properties(0, 50), "yellow")
    s2 = set_face_labels(stripes_properties(pi / 2, 50), "blue")
    for border, n in [(CROP_ADD_BOUNDARY, 64), (KEEP_INSIDE, 64), (KEEP_OUTSIDE, 64)]:
        pm = grid_partition(s1, s2, border)(SQUARE)
        assert len(pm.bounded_faces) == n
        assert all(f.labels == {"yellow", "blue"} for f in pm.bounded_faces)
        assert np.allclose(pm.face_areas(), 2500)
    # a region that is not aligned with the grid shows the four border options
    region = shapely.box(25, 25, 375, 375)
    crop_add = grid_partition(s1, s2, CROP_ADD_BOUNDARY)(region)
    keep_in = grid_partition(s1, s2, KEEP_INSIDE)(region)
    keep_out = grid_partition(s1, s2, KEEP_OUTSIDE)(region)
    crop = grid_partition(s1, s2, CROP)(region)
    assert len(crop_add.bounded_faces) == 64 and np.isclose(crop_add.face_areas().sum(), region.area)
    assert len(keep_in.bounded_faces) == 36 and np.allclose(keep_in.face_areas(), 2500)
    assert len(keep_out.bounded_faces) == 64 and np.allclose(keep_out.face_areas(), 2500)
    assert len(crop.bounded_faces) == 36  # only whole cells close without the boundary
    for pm in (crop, crop_add):
        assert all(region.buffer(1e-6).covers(shapely.LineString(e.points)) for e in pm.edges)
    assert all(region.buffer(1e-6).covers(f.polygon) for f in keep_in.bounded_faces)
    assert all(f.polygon.intersection(region).area > 0 for f in keep_out.bounded_faces)
    assert any(not region.buffer(1e-6).covers(f.polygon) for f in keep_out.bounded_faces)


@pytest.mark.parametrize("partition", [uniform_partition, random_partition])
def test_irregular_partition_density_and_borders(partition):
    d = 1 / 40**2
    region = shapely.box(0, 0, 800, 800)
    pm = partition(irregular_properties(d), CROP_ADD_BOUNDARY)(region, seed=3)
    assert np.isclose(pm.face_areas().sum(), region.area)
    keep_in = partition(irregular_properties(d), KEEP_INSIDE)(region, seed=3)
    # a density d gives cells of mean area 1 / d (§5.1: samples per unit area)
    assert abs(keep_in.face_areas().mean() * d - 1) < 0.2
    assert d * region.area < len(pm.bounded_faces) < 1.3 * d * region.area
    keep_out = partition(irregular_properties(d), KEEP_OUTSIDE)(region, seed=3)
    assert len(keep_in.bounded_faces) < len(pm.bounded_faces) <= len(keep_out.bounded_faces)
    assert all(region.buffer(1e-5).covers(f.polygon) for f in keep_in.bounded_faces)
    assert all(f.polygon.intersection(region).area > 0 for f in keep_out.bounded_faces)
    assert shapely.union_all([f.polygon for f in keep_out.bounded_faces]).covers(region.buffer(-1e-6))


def test_uniform_is_more_regular_than_random():
    from scipy.spatial import cKDTree

    d = 1 / 30**2
    spreads = {}
    for part in (uniform_partition, random_partition):
        pm = part(irregular_properties(d), KEEP_INSIDE)(shapely.box(0, 0, 900, 900), seed=1)
        spreads[part.__name__] = np.std(pm.face_areas()) / np.mean(pm.face_areas())
    assert spreads["uniform_partition"] < 0.5 * spreads["random_partition"]
    del cKDTree


def test_weighted_labels_follow_probabilities():
    p = set_weighted_face_labels(irregular_properties(1 / 20**2), "red", 0.25, "green", 0.5)
    p = set_weighted_edge_labels(p, "thick", 1.0)
    p = set_weighted_vertex_labels(p, "dot", 0.5)
    pm = random_partition(p, KEEP_INSIDE)(shapely.box(0, 0, 1000, 1000), seed=2)
    labs = [f.labels for f in pm.bounded_faces]
    n = len(labs)
    red = sum("red" in s for s in labs) / n
    green = sum("green" in s for s in labs) / n
    none = sum(not s for s in labs) / n
    assert abs(red - 0.25) < 0.06 and abs(green - 0.5) < 0.06 and abs(none - 0.25) < 0.06
    # one draw per cell: a face never gets its neighbours' labels (sides are right)
    assert all(len(s) <= 1 for s in labs)
    assert all(e.labels == {"thick"} for e in pm.edges)
    dots = sum("dot" in v.labels for v in pm.vertices) / pm.n_vertices
    assert 0.35 < dots < 0.65


def test_bad_partition_arguments_name_the_problem():
    with pytest.raises(strew.InputError, match="widths must be positive"):
        stripes_properties(0, -1)
    with pytest.raises(strew.InputError, match="density must be positive"):
        irregular_properties(0)
    with pytest.raises(strew.InputError, match="border must be"):
        grid_partition(stripes_properties(0, 1), stripes_properties(1, 1), "sideways")
    with pytest.raises(strew.InputError, match="parallel"):
        grid_partition(stripes_properties(0, 1), stripes_properties(0, 2), CROP)
    with pytest.raises(strew.InputError, match="pairs label, weight"):
        set_weighted_face_labels(irregular_properties(1), "a", 0.5, "b")
    with pytest.raises(strew.InputError, match="set_weighted_edge_labels"):
        set_edge_labels(irregular_properties(1), "a")


def _grid(w=100, border=KEEP_INSIDE):
    return grid_partition(stripes_properties(0, w), stripes_properties(pi / 2, w), border)


def test_mapping_operators_visit_every_cell():
    seen = {"v": 0, "e": 0, "f": 0}

    def count(kind):
        def m(cell):
            seen[kind] += 1
            return nothing()

        return m

    g = _grid()
    assert map_to_vertices(count("v"), g)(SQUARE).n_edges == 0
    map_to_edges(count("e"), g)(SQUARE).n_edges
    map_to_faces(count("f"), g)(SQUARE).n_edges
    assert seen == {"v": 25, "e": 40, "f": 16}
    # contour of every face gives the grid back, with one edge per cell side
    pm = map_to_faces(contour, g)(SQUARE)
    assert (pm.n_vertices, pm.n_edges, pm.n_faces) == (25, 40, 17)
    shrunk = map_to_faces(lambda f: scale(contour(f), 0.5), g)(SQUARE)
    assert len(shrunk.bounded_faces) == 16 and np.allclose(shrunk.face_areas(), 2500)
    assert shrunk.n_edges == 64


def test_mapper_builds_sub_scale_arrangement():
    inner = _grid(10, CROP_ADD_BOUNDARY)
    two_scale = map_to_faces(lambda f: inner(f), _grid(100))
    pm = two_scale(SQUARE)
    assert len(pm.bounded_faces) == 16 * 100
    with pytest.raises(MapperError, match="evaluate it on the cell's face"):
        map_to_faces(lambda f: inner, _grid(100))(SQUARE)


def test_merges():
    hatch = stripes_partition(stripes_properties(pi / 4, 10))
    disk = Curves.polygon(shapely.Point(200, 200).buffer(100).exterior.coords[:-1])
    disk_area = shapely.Polygon(disk.curves[0].points)
    both = union(hatch, disk)(SQUARE)
    lines_only = hatch(SQUARE)
    assert both.n_edges > lines_only.n_edges
    for border in (CROP, CROP_ADD_BOUNDARY, KEEP_INSIDE, KEEP_OUTSIDE):
        ins = inside(hatch, disk, border)(SQUARE)
        out = outside(hatch, disk, border)(SQUARE)
        ins_lines = [shapely.LineString(e.points) for e in ins.edges]
        out_lines = [shapely.LineString(e.points) for e in out.edges]
        if border is CROP:
            assert all(disk_area.buffer(1e-5).covers(line) for line in ins_lines)
            assert all(line.intersection(disk_area).length < 1e-5 for line in out_lines)
            total = sum(x.length for x in ins_lines) + sum(x.length for x in out_lines)
            assert np.isclose(total, sum(shapely.LineString(e.points).length for e in lines_only.edges), rtol=1e-6)
        elif border is CROP_ADD_BOUNDARY:
            assert len(ins.bounded_faces) > 10  # the outline closes the hatch pieces
            assert np.isclose(ins.face_areas().sum(), disk_area.area, rtol=1e-6)
        elif border is KEEP_INSIDE:
            assert all(disk_area.buffer(1e-5).covers(line) for line in ins_lines)
            assert all(line.intersection(disk_area).length < 1e-5 for line in out_lines)
        else:
            assert all(line.intersection(disk_area).length > 0 for line in ins_lines)
            assert any(not disk_area.buffer(1e-5).covers(line) for line in ins_lines)
            assert all(line.difference(disk_area).length > 0 for line in out_lines)
    with pytest.raises(strew.InputError, match="union: A2: expected an arrangement"):
        union(hatch, 3)


def test_merge_keeps_face_labels():
    g = grid_partition(set_face_labels(stripes_properties(0, 100), "a", "b"), stripes_properties(pi / 2, 100), KEEP_INSIDE)
    lines = stripes_partition(stripes_properties(0.3, 17))
    pm = union(g, lines)(SQUARE)
    labelled = [f for f in pm.bounded_faces if f.labels]
    assert len(labelled) == len(pm.bounded_faces) > 16
    for f in pm.bounded_faces:
        y = centroid(f)[1]
        assert f.labels == ({"a"} if int(y // 100) % 2 == 0 else {"b"})


def test_arrangement_regions():
    g = _grid()
    assert isinstance(g, ArrangementFunction)
    assert isinstance(g(400), PlanarMap)
    assert g(strew.Region.rectangle(400, 400)).n_faces == g(400).n_faces
    with pytest.raises(strew.InputError, match="region"):
        g("big")
    with pytest.raises(strew.InputError, match="size must be a positive"):
        g(-1)


def test_contour_and_to_curve_keep_face_labels():
    g = grid_partition(set_face_labels(stripes_properties(0, 100), "a", "b"), set_face_labels(stripes_properties(pi / 2, 100), "c", "d"), KEEP_INSIDE)
    ref = {tuple(np.round(centroid(f), 6)): f.labels for f in g(SQUARE).bounded_faces}
    for m in (map_to_faces(contour, g), map_to_edges(to_curve, g), map_to_faces(lambda f: scale(contour(f), 0.5), g)):
        got = {tuple(np.round(centroid(f), 6)): f.labels for f in m(SQUARE).bounded_faces}
        assert got == ref and len(ref) == 16
    assert {frozenset(v) for v in ref.values()} == {frozenset(x) for x in ({"a", "c"}, {"a", "d"}, {"b", "c"}, {"b", "d"})}
