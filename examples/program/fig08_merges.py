"""Fig. 8 of Loi et al.: merging operators.

A hatching (stripes) and blobs on a uniform partition, merged by union, by inside (the
hatching masked by the blobs, with their outlines added) and by outside (the hatching
around the blobs, cropped).
Run: strew run fig08_merges.py --name inside_blobs --out inside.svg
"""

from pathlib import Path

from strew.program import *
from strew.program import pi

here = Path(__file__).parent
size = 2000
blob = scale(import_svg(here / "blob.svg"), 1.2)

hatching = stripes_partition(stripes_properties(pi / 4, 16))
sites = uniform_partition(irregular_properties(1 / 300**2), KEEP_OUTSIDE)
blobs = map_to_faces(lambda f: match_point(rotate(blob, random(f, 0, 2 * pi, 0)), bbox_center(blob), centroid(f)), sites)

union_both = union(hatching, blobs)
inside_blobs = inside(hatching, blobs, CROP_ADD_BOUNDARY)
outside_blobs = outside(hatching, blobs, CROP)

arrangement = inside_blobs
demo_panels = ["union_both", "inside_blobs", "outside_blobs"]
demo_size = 1000

if __name__ == "__main__":
    export_svg(arrangement, size)
