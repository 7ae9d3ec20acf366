"""Fig. 11(d) of Loi et al.: a mosaic with random face deletion.

A grid partition; a circle is matched into every cell; an aging effect deletes some
faces at random (a deterministic per-face random value).
Run: strew run fig11d_mosaic.py --out mosaic.svg
"""

from pathlib import Path

from strew.program import *
from strew.program import pi

here = Path(__file__).parent
size = 2000
circle = curve_labeled(import_svg(here / "petal.svg", tolerance=0.04), "petal")  # within 0.04 of the circle: 42 points

tiles = grid_partition(stripes_properties(0, 80), stripes_properties(pi / 2, 80), KEEP_INSIDE)
mosaic = union(tiles, map_to_faces(lambda f: scale(match_face(circle, f), 0.8), tiles))


def age(face):
    # delete about a quarter of the faces
    if random(face, 0, 1, 0) < 0.25:
        return nothing()
    return contour(face)


arrangement = map_to_faces(age, mosaic)
demo_size = 800

if __name__ == "__main__":
    export_svg(arrangement, size)
