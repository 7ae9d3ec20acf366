"""Flow mode on a smooth field and on a sharp one (issue 14 point 2), measured by
``benchmarks/g43f_smooth.py`` (results ``benchmarks/results/g43f_*``).

Smooth: the hexagonal lattice grown from the centre of a square of 16 spacings along a
gentle arc (two concentric arcs about a centre 32 spacings below the square's middle:
the field turns 19 degrees over the interior; ``--field arc``), the smallest of the
measured smooth fields whose Nye bound (a lattice following the field exactly, each
needed dislocation costing its 5 and its 7) leaves a six share of at least 0.95
(0.956 here). On main every interior element keeps six neighbours at the spacing (the
lattice stays nearly rigid: its six-fold bond direction is within 5.6 degrees of the
field's at the 90th percentile), no hole, nothing across the edge.

Sharp: the held-out quarter circles over 16 spacings (``benchmarks/flow14p_heldout.py``,
``qc16_2,2``; Nye bound 0.834): the bend is taken up by 5-7 dislocation cores (nine on
main), no hole, nothing across the edge. That the cores are isolated is not asserted:
the sites without six neighbours group in twos at most here on an AVX-512 machine but
in sevens with the suite's AVX2 pins (flow growth is chaotic in the last bit), and on
10 of the 13 sharp held-out hexagon cases measured (16-24 spacings, five starts) some
cores are within two spacings of another (``benchmarks/results/g43f_sharp_hex_r1.txt``).

Both hold on main (src unchanged by g43f): a guard on what point 2 asks that main
meets, not the test of a change.
"""

from __future__ import annotations

import numpy as np
from scipy.spatial import Delaunay
from test_grow_flow14d_stretch import hex_ref  # noqa: F401 (a fixture)
from test_grow_flow_gaps import SP, _holes, _quarter_circles, _shares

from strew import Region
from strew.fields import flow_field
from strew.grow._growth import GrowParams, grow_reference


def _arc(a: float):
    c = np.array([a / 2, -2 * a])
    strokes = []
    for r in (2 * a + a / 4, 2 * a + 3 * a / 4):
        h = np.arcsin(0.75 * a / r)
        th = np.linspace(np.pi / 2 + h, np.pi / 2 - h, 30)
        strokes.append(c + np.c_[r * np.cos(th), r * np.sin(th)])
    return flow_field(strokes)


def _across(out, region: Region) -> int:
    return int((~np.asarray(region.contains_geometry(out.geometry, tolerance=1e-9))).sum())


def _cores(xy: np.ndarray, region: Region) -> np.ndarray:
    """The interior 5-7 cores (a Delaunay five with a seven beside, bonds under 1.3
    spacings; ``benchmarks/g42f_cores.py``): the midpoints of their 5-7 bonds, (k, 2)."""
    inner = region.distance_to_boundary(xy) > 2 * SP
    ind, nb = Delaunay(xy).vertex_neighbor_vertices
    nbrs = [[j for j in nb[ind[i] : ind[i + 1]] if np.hypot(*(xy[j] - xy[i])) < 1.3 * SP] for i in range(len(xy))]
    cnt = np.array([len(v) for v in nbrs])
    out = []
    for i in np.flatnonzero(inner & (cnt == 5)):
        j = next((j for j in nbrs[i] if cnt[j] == 7), None)
        if j is not None:
            out.append(0.5 * (xy[i] + xy[j]))
    return np.array(out).reshape(-1, 2)


def test_flow_smooth_arc_keeps_six_neighbours_inside_the_region(hex_ref):
    a = 16 * SP
    region = Region.rectangle(a, a)
    out = grow_reference(hex_ref, GrowParams(region=region, mode="flow", flow=_arc(a)), rng=1)
    assert _shares(out.xy, region)[0] >= 0.90  # 1.000 on main
    assert _holes(out.xy, region) == 0
    assert _across(out, region) == 0


def test_flow_sharp_quarter_circles_leave_dislocations_and_no_holes(hex_ref):
    a = 16 * SP
    region = Region.rectangle(a, a)
    params = GrowParams(region=region, mode="flow", flow=_quarter_circles(a), start=(2 * SP, 2 * SP))
    out = grow_reference(hex_ref, params, rng=1)
    assert _holes(out.xy, region) == 0
    assert _across(out, region) == 0
    cores = _cores(out.xy, region)
    assert len(cores) >= 3  # nine on main: the field's bend is taken up by dislocations
    # (no bound on the largest group of non-six sites: 2 on main unpinned, 7 with the
    # suite's AVX2 pins, and 6-14 from the side starts, benchmarks/results/g43f_point2.md:
    # that the sharp fields' defects are isolated is what point 2 still lacks)
