"""Fig. 12(b) of Loi et al.: two-scale cracks.

A random partition whose edges carry a crack stroke, applied again, at a smaller
scale, inside each of its own faces.
Run: strew run fig12b_cracks.py --out cracks.svg
"""

from pathlib import Path

from strew.program import *

here = Path(__file__).parent
size = 2000
crack = import_svg(here / "crack.svg")


def crack_edge(edge):
    if is_boundary(edge):
        return to_curve(edge)
    return match_points(crack, point_labeled(crack, "start"), point_labeled(crack, "end"), location(source_vertex(edge)), location(target_vertex(edge)))


def cracked(density, border):
    return map_to_edges(crack_edge, random_partition(irregular_properties(density), border))


large = cracked(1 / 400**2, CROP_ADD_BOUNDARY)
small = cracked(1 / 90**2, CROP)


def fine_cracks(face):
    return small(face)


arrangement = union(large, map_to_faces(fine_cracks, large))
demo_size = 800

if __name__ == "__main__":
    export_svg(arrangement, size)
