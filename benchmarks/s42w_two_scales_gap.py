"""s42w: why tests/synth/test_synth_tools.py::test_two_scales_in_one_output_with_per_element_radii fails on h/s42w
(stones left in the state vs kept by the clip, the emptiest grid point, pebbles added).

    PYTHONPATH=src python benchmarks/s42w_two_scales_gap.py
"""
import numpy as np
from strew import Region
from strew.synth import Palette, fill, new_state, set_selection
from strew.synth._exemplars import stones
pal = Palette({"stones": stones(1.0), "pebbles": stones(0.25, size=60)})
region = Region.rectangle(200, 200)
s = new_state(pal, region, selection="stones", rng=2)
fill(s)
print("stones", s.n, "clip keeps", len(s.to_arrangement(drop_overlaps=False)))
set_selection(s, "pebbles")
grid_pts = np.mgrid[5:200:5, 5:200:5].reshape(2, -1).T.astype(float)
dd = np.min(np.hypot(*(grid_pts[:, None] - s.pos[None]).transpose(2, 0, 1)), axis=1)
gap = grid_pts[np.argmax(dd)]
print("gap", gap, dd.max())
print("added", fill(s, tuple(gap)))
