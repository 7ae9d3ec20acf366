"""One point-segment distance: the numpy form equals the compiled kernel's rule (issue 15.5)."""

from __future__ import annotations

import numpy as np
import shapely

from strew._kernels.geometry import point_segment_distance, seg_dist2


def test_numpy_distance_is_the_kernel_rule_bit_for_bit():
    rng = np.random.default_rng(7)
    p, a, b = (rng.normal(size=(300, 2)) * 10 for _ in range(3))
    b[:20] = a[:20]  # degenerate segments: the distance to their point
    d = point_segment_distance(p, a, b)
    k = np.array([np.sqrt(seg_dist2(*p[i], *a[i], *b[i])) for i in range(len(p))])
    assert np.array_equal(d, k)
    ref = shapely.distance(shapely.points(p), shapely.linestrings(np.stack([a, b], axis=1)))
    assert np.allclose(d, ref, rtol=1e-12, atol=1e-12)
