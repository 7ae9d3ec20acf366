"""Fig. 7 of Loi et al.: using mappers.

(top) Puzzle bricks: a grid with cycled labels, a mapper keeping vertical edges in
staggered rows, then a puzzle tab matched on every edge with match_points.
(middle) Rosettes: four construction lines matched on each face centroid of a uniform
partition, then overlapping circles mapped on the resulting vertices.
(bottom) Random cells (cropped by the frame, so they fill it) shrunk, with a stroke
picked from a small set on each edge.
Lengths are for the gallery's 800-unit square and scale with ``--size`` (``run_size``).
Run: strew run fig07_mappers.py --name rosettes --out rosettes.svg
"""

from pathlib import Path

from strew.program import *
from strew.program import pi, run_size

here = Path(__file__).parent
size = run_size(2000)
k = size / 800  # the lengths below are for an 800-unit square
tab = import_svg(here / "puzzle.svg")
cross = scale(import_svg(here / "cross.svg"), 2.0 * k)
petal = scale(import_svg(here / "petal.svg", tolerance=0.04), 1.6 * k)  # within 0.04 of the circle: 42 points
wiggles = import_svg(here / "wiggles.svg")

# -- puzzle bricks ---------------------------------------------------------------------
rows = set_face_labels(set_edge_labels(stripes_properties(0, 100 * k), "row"), "odd", "even")
cols = set_edge_labels(stripes_properties(pi / 2, 100 * k), "A", "B")
bricks = grid_partition(rows, cols, CROP_ADD_BOUNDARY)


def keep_staggered(edge):
    # horizontal lines and the boundary stay; vertical edges alternate with the rows
    if is_boundary(edge) or has_label(edge, "row"):
        return to_curve(edge)
    row_odd = has_label(left_face(edge), "odd") or has_label(right_face(edge), "odd")
    if has_label(edge, "A") == row_odd:
        return to_curve(edge)
    return nothing()


def puzzle_edge(edge):
    if is_boundary(edge):
        return to_curve(edge)
    src, dst = location(source_vertex(edge)), location(target_vertex(edge))
    # the tab points to either side at random. MatchPoints applies a rotation (Table 3:
    # "rigid"), so rotating the tab beforehand would be undone; matching its start to
    # the edge's target instead turns it over to the other side.
    if random(edge, 0, 1, 0) < 0.5:
        src, dst = dst, src
    return match_points(tab, point_labeled(tab, "start"), point_labeled(tab, "end"), src, dst)


puzzle = map_to_edges(puzzle_edge, map_to_edges(keep_staggered, bricks))

# -- rosettes ----------------------------------------------------------------------------
cells = uniform_partition(irregular_properties(1 / (110 * k) ** 2), KEEP_INSIDE)


def construction_lines(face):
    arms = rotate(cross, random(face, 0, pi / 2, 0))
    return match_point(arms, point_labeled(arms, "center"), centroid(face))


def flower(vertex):
    return match_point(petal, point_labeled(petal, "center"), location(vertex))


rosettes = map_to_vertices(flower, map_to_faces(construction_lines, cells))

# -- shrunk random cells with strokes -----------------------------------------------------
random_cells = random_partition(irregular_properties(1 / (160 * k) ** 2), CROP_ADD_BOUNDARY)
shrunk = map_to_faces(lambda face: scale(contour(face), 0.8), random_cells)


def near_frame(p):
    return min(p[0], p[1], size - p[0], size - p[1]) < 40 * k


def stroke(edge):
    # cells cropped by the frame keep a straight side along it: a wiggle there would
    # poke out of the square
    if near_frame(location(source_vertex(edge))) and near_frame(location(target_vertex(edge))):
        return to_curve(edge)
    pick = ["w1", "w2", "w3"][int(random(edge, 0, 3, 0)) % 3]
    w = curve_labeled(wiggles, pick)
    return match_points(w, point_labeled(wiggles, "start"), point_labeled(wiggles, "end"), location(source_vertex(edge)), location(target_vertex(edge)))


cells_with_curves = map_to_edges(stroke, shrunk)

arrangement = puzzle
demo_panels = ["puzzle", "rosettes", "cells_with_curves"]
demo_size = 800

if __name__ == "__main__":
    export_svg(arrangement, size)
