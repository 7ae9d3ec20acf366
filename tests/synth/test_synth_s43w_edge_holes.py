"""Issue 13 point 2 (s43w): gaps against the region's edge.

``fill_holes`` saw only Delaunay circumcircles of the output's centres lying in the
region; at an empty corner every such circle is centred outside, so once the copies
crossing the edge were dropped (``_grow._drop_clipped``) a corner could stay empty:
stones in 200 x 200 at seed 2 left the corner (200, 0) 38.7 from any stone centre,
against the exemplar's largest empty circle of 24.6.
"""

from __future__ import annotations

import numpy as np
import shapely
from scipy.spatial import cKDTree

from strew import Region
from strew.synth import Palette, fill, new_state
from strew.synth._exemplars import stones
from strew.synth._grow import largest_empty_circles


def test_no_gap_at_the_region_edge_wider_than_the_exemplar_largest_empty_circle():
    """Every place along the region's edge where a stone lies wholly inside is within
    the exemplar's largest empty circle of a stone of the output (after its clip). On
    main (and on h/s42w) the corner (200, 0) of seed 2 was 27.4 from every stone where
    a stone fits, against 24.6."""
    pal = Palette({"stones": stones(1.0)})
    r = float(pal["stones"]["radius"][0])
    s = new_state(pal, Region.rectangle(200, 200), rng=2)
    fill(s)
    lec = float(largest_empty_circles(s.prep)[0])
    out = s.to_arrangement()
    assert len(out) > 30
    inset = shapely.box(r, r, 200 - r, 200 - r).exterior
    pts = shapely.get_coordinates(shapely.segmentize(inset, 1.0))
    d, _ = cKDTree(out.xy).query(pts)
    assert float(d.max()) <= lec, (pts[np.argmax(d)], d.max(), lec)
