"""Fig. 8 of Loi et al.: merging operators.

A hatching (stripes) and blobs on a uniform partition, merged by union, by inside (the
hatching masked by the blobs, with their outlines added) and by outside (the hatching
around the blobs, cropped).
Lengths are for the gallery's 1000-unit square and scale with ``--size`` (``run_size``);
a blob that would cross the frame is left out, so that every blob lies in the picture.
Run: strew run fig08_merges.py --name inside_blobs --out inside.svg
"""

from pathlib import Path

from strew.program import *
from strew.program import pi, run_size

here = Path(__file__).parent
size = run_size(1000)
unit = size / 1000
blob = scale(import_svg(here / "blob.svg"), 0.9 * unit)

hatching = stripes_partition(stripes_properties(pi / 4, 16 * unit))
sites = uniform_partition(irregular_properties(1 / (200 * unit) ** 2), KEEP_OUTSIDE)


# Mapper: a blob at the centre of a face, or nothing where it would cross the frame.
def map_blob_to(face):
    placed = match_point(rotate(blob, random(face, 0, 2 * pi, 0)), bbox_center(blob), centroid(face))
    (cx, cy), w, h = bbox_center(placed), bbox_width(placed), bbox_height(placed)
    if min(cx - w / 2, cy - h / 2) < 0 or max(cx + w / 2, cy + h / 2) > size:
        return nothing()
    return placed


blobs = map_to_faces(map_blob_to, sites)

union_both = union(hatching, blobs)
inside_blobs = inside(hatching, blobs, CROP_ADD_BOUNDARY)
outside_blobs = outside(hatching, blobs, CROP)

arrangement = inside_blobs
demo_panels = ["union_both", "inside_blobs", "outside_blobs"]
demo_size = 1000

if __name__ == "__main__":
    export_svg(arrangement, size)
