"""Fig. 3 of Loi et al.: a two-scale arrangement.

Blobs on a uniform partition; inside each blob, a grid with a random orientation whose
every edge carries a zig stroke (boundary edges stay as they are).
Run: strew run fig03_two_scales.py --out fig03.svg   (or: python fig03_two_scales.py)
"""

from pathlib import Path

from strew.program import *
from strew.program import pi, run_size

here = Path(__file__).parent
size = run_size(2000)
blob = scale(import_svg(here / "blob.svg"), 2.2)
zig = import_svg(here / "zig.svg")


# Mapper: places a blob in a face, or nothing where it would cross the frame (so that
# every blob lies in the picture).
def map_blob_to(face):
    new_blob = rotate(blob, random(face, 0, 2 * pi, 0))
    placed = match_point(new_blob, bbox_center(new_blob), centroid(face))
    (cx, cy), w, h = bbox_center(placed), bbox_width(placed), bbox_height(placed)
    if min(cx - w / 2, cy - h / 2) < 0 or max(cx + w / 2, cy + h / 2) > size:
        return nothing()
    return placed


# Mapper: replaces an edge by a zig stroke.
def map_curve_to(edge):
    if is_boundary(edge):
        return to_curve(edge)
    src_c = point_labeled(zig, "start")
    dst_c = point_labeled(zig, "end")
    src_v = location(source_vertex(edge))
    dst_v = location(target_vertex(edge))
    return match_points(zig, src_c, dst_c, src_v, dst_v)


# Mapper: generates an arrangement in a face.
def map_arrangement_to(face):
    # grid partition with a random orientation
    theta = random(face, 0, 2 * pi, 1)
    width = bbox_width(face) / 5
    lines1 = stripes_properties(theta, width)
    lines2 = stripes_properties(theta + pi / 2, width)
    init = grid_partition(lines1, lines2, CROP_ADD_BOUNDARY)
    # mapping operator: maps a curve on each edge
    sub = map_to_edges(map_curve_to, init)
    return sub(face)


# Init: uniform partition
props = irregular_properties(10 / (size * size))
init_tex = uniform_partition(props, KEEP_OUTSIDE)
# Mapping operators: a blob in each face, then an arrangement in each blob
blob_tex = map_to_faces(map_blob_to, init_tex)
arrangement = map_to_faces(map_arrangement_to, blob_tex)

demo_size = 2000

if __name__ == "__main__":
    export_svg(arrangement, size)
