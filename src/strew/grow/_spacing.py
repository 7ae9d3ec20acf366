"""Unsaturated exemplars: each element keeps its reference's nearest distance (not in the paper).

§5.4 (b) merges a new seed only with an object within ``l_short``, half the shortest
reference edge, and §5.2 matches a seed against its *connected* neighbours w(e_tar)
alone. A sparse exemplar drawn with a fixed count (a dart throw stopped well before it
is full: ``_variants.EDGE`` stones p2, 60 stones of radius 4 and gap 4 in 200 x 200)
keeps wide empty places between its elements, and nothing in §5 keeps them: a ring slot
of one element lands in the empty part of a neighbour's ring, farther than ``l_short``
from everything, and is placed there (helper g34d, ``benchmarks/g34d_probe.py``: within
one mean spacing each element had 0.86 elements its ring did not pair, 0.42 placed
before it and 0.44 after; its reference element had 2.98 neighbours there and the
output element 3.54; the copied ring offsets themselves were kept, 0.99 of their length
at the end, ``_fit_position`` moved elements 0.04 spacings, ``_nudge`` none, the hole
passes 1). The result was 22 % denser than the exemplar (empty_circle 0.158 against
0.149; the class's own generator at that size passes).

In the exemplar every pair of elements lies at least the larger of their two
nearest-neighbour distances apart (by definition of the nearest neighbour). Where the
exemplar leaves room (:func:`free_share`), growth keeps most of that: an element is not
placed nearer a placed one than :data:`KEEP_SHARE` of the larger of their reference
elements' nearest distances.
Saturated and lattice exemplars have no room, and there the rule would only turn growth
noise into holes (forced on the default stones, ``--varied`` stones v23: density
0.002 -> 0.111 against a tolerance of 0.1), so it applies only where
:func:`free_share` is at least :data:`FREE_MIN`, to exemplars of one kind (two kinds of
one size in bands of dots and bars, stripes p2, have as much room between the bands,
and the rule failed them: nn[bar>bar] 0.068 against 0.062).
"""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree

from ..arrangement import Arrangement

#: the least :func:`free_share` at which elements keep their reference's nearest
#: distance. Of the audit's one-kind exemplars (variant seeds 1-26, ``--varied``
#: labels; ``benchmarks/g34d_room.py``), the sparse stones (EDGE stones p2) have
#: 0.26-0.46; saturated stones (p1) 0.03-0.14, the default stones 0.00-0.01, sticks,
#: lattices, bricks and scales 0.
FREE_MIN = 0.2

#: the share of the larger reference nearest distance kept between two elements. The
#: whole distance pushes the output's nearest distances above the exemplar's (each
#: element's is at least its reference's): at 1.0 stones p2s7 seed 1 failed
#: nn[stone>stone] 0.153/0.12, at 0.9 p2s17 seed 1 0.163/0.15 (main passes both); at
#: 0.85 stones p2s7-p2s26 seed 1 and p2s23 seeds 2-3 all pass (p2s23: 868 stones, the
#: generator's 735, main's 1011; benchmarks/results/g34d_p2_rows.txt)
KEEP_SHARE = 0.85


def free_share(ex: Arrangement, step: float = 0.25) -> float:
    """Share of the exemplar's interior where one more element would fit.

    The element is the exemplar's smallest (bounding disc), kept the least gap between
    bounding discs that any two elements of the exemplar keep; the interior lies
    ``2 r_max + gap`` inside the frame; sampled on a grid of ``step`` times the disc's
    needed clearance. 0 for a lattice or a dart throw run until nothing fits.
    """
    xy = np.asarray(ex.xy, dtype=float)
    if len(xy) < 4 or ex.region is None:
        return 0.0
    rad = np.array([float(ex.shapes[k].radius) for k in ex.kinds])[np.asarray(ex.kind)] * np.asarray(ex.scale, dtype=float)
    tree = cKDTree(xy)
    k = min(8, len(xy))
    d, q = tree.query(xy, k=k)
    gap = max(float((d[:, 1:] - rad[:, None] - rad[q[:, 1:]]).min()), 0.0)
    need = float(rad.min()) + gap
    if need <= 0:
        return 0.0
    x0, y0, x1, y1 = ex.region.bounds
    m = float(2 * rad.max() + gap)
    h = step * need
    gx, gy = np.meshgrid(np.arange(x0 + m, x1 - m, h), np.arange(y0 + m, y1 - m, h))
    if gx.size == 0:
        return 0.0
    dd, qq = tree.query(np.c_[gx.ravel(), gy.ravel()], k=k)
    return float(np.mean(np.min(dd - rad[qq], axis=1) >= need))


def reference_nn(ex: Arrangement, mode: str, keep: bool | None) -> np.ndarray | None:
    """Each exemplar element's nearest-neighbour distance where elements keep it, or None.

    ``keep`` True or False forces the rule on or off (``GrowParams.keep_nn``); None
    decides by the exemplar: one kind, no voids, :func:`free_share` at least
    :data:`FREE_MIN`, fixed mode (the audits measured it there).
    """
    if keep is False or len(ex) < 2:
        return None
    if keep is None and (mode != "fixed" or len(ex.kinds) != 1 or "void" in ex.columns
                         or free_share(ex) < FREE_MIN):
        return None
    xy = np.asarray(ex.xy, dtype=float)
    return cKDTree(xy).query(xy, k=2)[0][:, 1]
