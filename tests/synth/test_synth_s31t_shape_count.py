"""Helper s31t: the compiled shape-neighbour count of sticks' growth limit (issue 13).

``_grow._shape_crowded`` counts, for each copy, the visible output shapes within its
reach in a compiled loop (``_kernels.shape_crowded``): centres within reach count at
once, centres beyond reach plus both bounding radii never, and the pairs between are
measured edge by edge. The count must be exactly shapely's ``distance <= reach`` for
any shape, also where a shape does not hold its own centre (a frame, an L), holds
another whole (a slab) or has no area (a line), and output voids never count.
"""

from types import SimpleNamespace

import numpy as np
import shapely

from strew.synth import _grow
from strew.synth._shapes import element_geometries


def _fake_state(rng):
    shapes = {
        "stick": shapely.box(-12.0, -1.3, 12.0, 1.3),
        "frame": shapely.box(-6.0, -6.0, 6.0, 6.0).difference(shapely.box(-4.0, -4.0, 4.0, 4.0)),
        "ell": shapely.Polygon([(-2, -2), (8, -2), (8, 0), (0, 0), (0, 9), (-2, 9)]),
        "slab": shapely.box(-20.0, -20.0, 20.0, 20.0),  # holds small shapes whole
        "line": shapely.LineString([(-7.0, 0.0), (0.0, 3.0), (7.0, 0.0)]),
    }
    ne = 30  # exemplar elements: six of each kind, random turns and scales
    kind = np.repeat(np.arange(5), 6)
    prep = SimpleNamespace(
        shapes={k: SimpleNamespace(geometry=g) for k, g in shapes.items()},
        kind=kind,
        rotation=rng.uniform(0, 2 * np.pi, ne),
        scale=rng.uniform(0.6, 1.4, ne),
        void=np.arange(ne) == ne - 1,  # one void element (a line): never counted
    )
    n = 160
    osrc = rng.integers(0, ne, n)
    osrc[:4] = ne - 1
    state = SimpleNamespace(prep=prep, pos=rng.uniform(0, 120, (n, 2)), src=osrc, n=n)
    return state


def test_compiled_shape_count_is_shapely_distance_count():
    rng = np.random.default_rng(5)
    state = _fake_state(rng)
    prep = state.prep
    m = 600
    src = rng.integers(0, len(prep.kind) - 1, m)
    pts = rng.uniform(-10, 130, (m, 2))
    pts[:300] = state.pos[rng.integers(0, state.n, 300)] + rng.normal(0, 3.0, (300, 2))
    reach = rng.uniform(2.0, 12.0, len(prep.kind))
    g = element_geometries(prep, src, pts)
    vis = np.flatnonzero(~prep.void[state.src])
    og = element_geometries(prep, state.src[vis], state.pos[vis])
    cnt = np.count_nonzero(shapely.distance(g[:, None], og[None, :]) <= reach[src][:, None], axis=1)
    assert len(np.unique(cnt)) > 4  # crowded and empty neighbourhoods alike
    for v in np.unique(cnt):
        sel = cnt == v
        lim = np.full(len(prep.kind), v)
        assert not _grow._shape_crowded(state, pts[sel], src[sel], lim, reach).any()  # at its count: room
        if v > 0:
            lim[:] = v - 1
            assert _grow._shape_crowded(state, pts[sel], src[sel], lim, reach).all()  # one below: crowded
    # no limit (-1): never crowded
    assert not _grow._shape_crowded(state, pts, src, np.full(len(prep.kind), -1), reach).any()
