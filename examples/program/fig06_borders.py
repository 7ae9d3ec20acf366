"""Fig. 6 of Loi et al.: the four border options.

A uniform partition of a blob-shaped domain, (a) cropped, (b) cropped with the domain's
outline added, (c) keeping only the cells inside, (d) keeping every cell that meets it.
Each tile of a coarse grid holds one domain. Lengths are for the gallery's 1000-unit
square and scale with ``--size`` (``run_size``), so every size draws the same picture.
Run: strew run fig06_borders.py --name keep_outside --out keep_outside.svg
"""

from pathlib import Path

from strew.program import *
from strew.program import pi, run_size

here = Path(__file__).parent
size = run_size(2000)
k = size / 1000  # the lengths below are for a 1000-unit square
blob = import_svg(here / "blob.svg")
props = irregular_properties(1 / (70 * k) ** 2)
tiles = grid_partition(stripes_properties(0, 1000 * k), stripes_properties(pi / 2, 1000 * k), KEEP_INSIDE)


def panel(border):
    def mapper(face):
        domain = scale(match_face(blob, face), 0.8)
        return uniform_partition(props, border)(domain)

    return map_to_faces(mapper, tiles)


crop = panel(CROP)
crop_add_boundary = panel(CROP_ADD_BOUNDARY)
keep_inside = panel(KEEP_INSIDE)
keep_outside = panel(KEEP_OUTSIDE)

arrangement = keep_outside
demo_panels = ["crop", "crop_add_boundary", "keep_inside", "keep_outside"]
demo_size = 1000

if __name__ == "__main__":
    export_svg(arrangement, size)
