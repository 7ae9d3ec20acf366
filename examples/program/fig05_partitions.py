"""Fig. 5 of Loi et al.: the four partitions, with cycled and weighted labels.

Panels: stripes with a cycle of two widths and cycled face labels; a grid whose faces
get one label from each stripes set; a uniform partition with weighted face labels; a
random partition with weighted edge labels. Faces and edges are coloured by label.
Run: strew run fig05_partitions.py --name grid --out grid.svg
"""

from strew.program import *
from strew.program import pi

size = 2000

# (a) stripes: widths cycle 80, 40; face labels cycle yellow, blue
p = set_face_labels(stripes_properties(pi / 6, 80, 40), "yellow", "blue")
stripes = stripes_partition(p, border=CROP_ADD_BOUNDARY)

# (b) grid: each face gets one label per stripes set ("yellow" + "blue" = both)
s1 = set_face_labels(stripes_properties(0, 120), "yellow", "none")
s2 = set_face_labels(stripes_properties(pi / 2, 120, 60), "blue", "none2")
grid = grid_partition(s1, s2, CROP_ADD_BOUNDARY)

# (c) uniform partition with weighted face labels
pu = set_weighted_face_labels(irregular_properties(1 / 150**2), "red", 0.2, "green", 0.3)
uniform = uniform_partition(pu, CROP_ADD_BOUNDARY)

# (d) random partition with weighted edge labels
pr = set_weighted_edge_labels(irregular_properties(1 / 150**2), "thick", 0.5)
random_cells = random_partition(pr, CROP_ADD_BOUNDARY)

arrangement = grid
demo_panels = ["stripes", "grid", "uniform", "random_cells"]
demo_size = 1000

if __name__ == "__main__":
    export_svg(arrangement, size)
