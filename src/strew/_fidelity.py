"""Exemplar fidelity: does a result read as more of the exemplar's texture?

:func:`fidelity` measures a result (grown, synthesized, painted...) against the exemplar
it continues and returns a :class:`FidelityReport`. Everything works on element centres
``(x, y)`` with their kind, rotation and bounding radius (shape radius x scale).

Metrics (each one scalar discrepancy between result and exemplar):

``fraction[k]``
    |share of kind k in the result - share in the exemplar| (visible elements).
``density[k]``
    |density of kind k / the exemplar's - 1|: the share of kind k among the window's
    elements times the number of elements per unit area of their Voronoi cells (only the
    cells that elements beyond the domain cannot change), so that frames, margins and
    crops do not bias it.
``g[a,b]``
    RMS difference of the pair correlation functions g_ab(r) over
    ``0 < r <= 4 s`` (``s`` the exemplar's median nearest-neighbour distance), bins of
    ``s / 5`` with linear (triangular) binning. Edge correction: the translation
    (Ohser-Stoyan) correction ``|W| / |W ∩ (W + d)|``, whose set covariance
    ``|W ∩ (W + d)|`` is computed for any polygon by an FFT of the window's raster.
    g_ab = g_ba for this estimator, so unordered pairs are reported. Pairs at lags the
    window barely holds (``|W ∩ (W + d)| < 0.02 |W|``) are left out.
``nn[a>b]``
    Distances from each element of kind a to its nearest element of kind b: the mean
    absolute difference of the deciles (10 % ... 90 %), in units of ``s``. Neighbours
    are searched among all elements of the domain; border correction (Hanisch): an
    element counts only when its nearest-neighbour distance is below its distance to
    the domain's boundary.
``regularity``
    Lattice-like exemplars only: the share of interior elements whose neighbours within
    ``1.3 s`` are the exemplar's dominant pattern (the same count, and every pattern
    offset matched within ``0.25 s``), measured in each element's local frame (offsets
    turned by -rotation, trying the shape's symmetric turns). One-sided: the result
    fails when it is less regular than the exemplar by more than the tolerance.
    An exemplar is lattice-like when at least 70 % of its own interior elements match.
``orientation.relative`` / ``orientation.bearing``
    Total-variation distances between the histograms of the rotation of each element
    relative to its 6 nearest neighbours, and of the bearing of those neighbours in the
    element's local frame (both taken modulo the shapes' rotational symmetry; kinds
    that look the same at every angle, such as discs, are left out).
``empty_circle``
    |q95 of the result's empty circles / the exemplar's - 1|: empty circles are the
    Delaunay circumcircles (centred on Voronoi vertices) lying wholly inside the window,
    q95 their 95th percentile radius. The maximum of each is in ``info``; the local map
    compares each window's largest empty circle with the exemplar's largest.
``eq5``
    Davison et al.'s Eq. 5: the mean over (a deterministic sample of) result elements of
    the distance of its neighbourhood to the most similar exemplar neighbourhood (the
    synth module's brute-force measure, with voids left out). The exemplar's own value
    is 0 by construction.

Tolerances come from the exemplar's own sampling noise. The exemplar's window is split
five ways into two halves of equal area (left/right, top/bottom, a 2 x 2 checkerboard,
alternate vertical and alternate horizontal quarter bands; g, which needs lags up to
4 s inside each half, uses the first three); each metric's discrepancy between the two
halves is measured, and
``spread`` is their root mean square. A half holds half the elements, so its statistic
has twice the variance of the whole exemplar's, and the difference of two halves four
times: ``sigma = spread / 2`` estimates the whole exemplar's own noise, and the result
(10-50 x larger, hence nearly noise-free) should differ from it by about ``sigma``.
The result's own sampling noise adds: the tolerance is
``MULTIPLE * sigma * sqrt(1 + A_exemplar / A_result)`` with ``MULTIPLE = 4`` (a 3 sigma
band widened for the uncertainty of a spread estimated from five splits; calibrated on
fresh, larger draws of the suite's classes), and never below the floor
of :data:`FLOORS` (kind fractions 0.05 and density 10 % as the issue sets; the others
small, to absorb binning of perfect lattices whose halves agree exactly). For ``eq5``
the tolerance is ``EQ5_MULTIPLE = 2.5`` times the mean of half-against-half Eq. 5 (one
half as exemplar, the other as output, both ways). A faithful output is matched against
the whole exemplar, which holds twice the neighbourhoods, so it usually scores below
that level; but incomplete neighbourhoods at a small exemplar's frame push it up (fresh
larger draws of the sparse class reach twice the level), hence 2.5. Its floor is Eq. 5 of
the exemplar itself with Gaussian positional noise of 0.05 s, which nobody sees.
Eq. 5 is measured in the global frame, as synth matches neighbourhoods: a texture turned
as a whole fails it even where the local-frame metrics pass. A result made in a rotating
mode (grow's rotate and flow modes, recorded in its ``meta``) is measured in each
element's local frame instead (``eq5_frame``), with the same tolerance.

Edges. The result is compared in its interior: the region eroded by ``2 s``, or by its
wall reach (below) where larger. The exemplar's window is its region (a crop, where
elements may cross the frame) or, when every element is drawn wholly inside the frame,
the region eroded by the median element radius (such an element has its centre at least
its radius from the frame). Kind shares (``fraction`` and both factors of ``density``)
are counted by minus sampling (the border method of point-process statistics: only
centres at least ``d`` from the domain's boundary count, unbiased for a stationary
texture): where several kinds are each kept wholly inside the frame by about their own
radius and keep off by different distances, the frame is a wall, the band along it holds
only the smaller kinds and a layer of the larger ones packs against it, and ``d`` is
twice the largest distance a kind keeps (at most its radius; ``_wall_reach``); otherwise
``d`` is 0. A stationary result continues the exemplar's interior (Davison §5.1 copies
interior neighbourhoods), so the whole frame's shares would under-count large stones.

Voids (the synth ``void`` column, Davison §5.6) are invisible: they are left out of
every metric; their share of the exemplar (and of the result, if it keeps them) is
reported in ``info`` and not judged, since synth hides them by default.

The local map evaluates the same metrics (all but ``eq5``) in square windows of the
exemplar's area, stepped by half a side, over the result's interior. A window carries
its own noise as the whole result does, so its noise term is
``MULTIPLE * sigma * sqrt(1 + A_exemplar / A_window)`` (about sqrt(2) sigma for a whole
window; floors as above), or, where larger, the window-to-window noise measured in the
exemplar itself: square sub-windows of half its side at 5 x 5 offsets, each compared with
the whole exemplar, their mean square scaled by the Poisson law (variance x area constant)
to ``MULTIPLE * sqrt(c / A_window + c / A_exemplar)``. Half-splits alone miss the noise of a
window's phase: the halves of an exemplar framed on whole periods of a lattice (rings)
agree almost exactly, while a window anywhere on a larger draw holds 3 to 5 columns of
hubs; fresh larger draws of rings failed about half their windows on density[hub].
Each window's score is its worst discrepancy / tolerance
(above 1: it fails); the worst window is reported.

Known limits: a result smaller than the exemplar (after the margin) is compared on a
crop that may cut coarse structures (rings, clusters) and so differ from the exemplar
by more than the halves show; compare results at least a few times the exemplar's
area. A lattice of elements at random rotations reads as not lattice-like (the pattern
is sought in each element's own frame). A kind with a dozen elements in the exemplar
gets wide tolerances: that is its sampling noise, not leniency.
"""

from __future__ import annotations

import html
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import shapely

from ._errors import InputError
from .arrangement import Arrangement
from .region import Region

__all__ = ["fidelity", "FidelityReport", "MetricResult", "pair_correlation", "nearest_neighbor_distances", "MULTIPLE", "EQ5_MULTIPLE", "FLOORS"]

MULTIPLE = 4.0
EQ5_MULTIPLE = 2.5
# floors of the tolerances: fraction and density as the issue sets; the others absorb the
# binning of exemplars whose halves agree exactly (perfect lattices)
FLOORS = {
    "fraction": 0.05,
    "density": 0.10,
    "g": 0.15,
    "nn": 0.05,
    "regularity": 0.05,
    "orientation": 0.05,
    "empty_circle": 0.10,
    "eq5": 0.0,
}
R_MAX = 4.0  # g(r) up to R_MAX * s
BIN = 0.2  # g bins of BIN * s
LATTICE_REACH = 1.3  # neighbours within LATTICE_REACH * s form an element's pattern
LATTICE_MATCH = 0.25  # a pattern offset matches within LATTICE_MATCH * s
LATTICE_SHARE = 0.7  # lattice-like when this share of the exemplar's interior matches
ORIENT_K = 6
RESULT_MARGIN = 2.0  # result interior: region eroded by RESULT_MARGIN * s
EQ5_SAMPLE = 400
EQ5_JITTER = 0.05  # the Eq. 5 floor: the exemplar with this positional noise (x s)
EQ5_FRAME_R = 0.5  # a kind has a frame for local-frame Eq. 5 when its rotations' resultant reaches this
EQ5_FRAMES = ("auto", "global", "local")
MIN_RECORDS = 30  # an orientation histogram or empty-circle quantile needs this many
MIN_NN = 5  # nearest-neighbour deciles need this many elements
DECILES = np.linspace(0.1, 0.9, 9)


# -- small geometry helpers ------------------------------------------------------------


def _symmetry_order(geom: shapely.Geometry) -> int:
    """Largest m <= 12 with the shape unchanged by a turn of 2 pi / m about its origin.

    Returns 0 when it is unchanged even at m = 12 (a disc: orientation meaningless).
    """
    if geom.is_empty:
        return 0
    g = geom if geom.area > 0 else geom.buffer(max(1e-9, 0.02 * math.sqrt(max(geom.length, 1e-12))))
    area = g.area
    if area <= 0:
        return 1
    for m in range(12, 1, -1):
        turned = shapely.affinity.rotate(g, 360.0 / m, origin=(0, 0))
        if shapely.symmetric_difference(g, turned).area <= 0.02 * area:
            return 0 if m == 12 else m
    return 1


def _set_covariance(window: shapely.Geometry, cell: float, reach: float) -> tuple[np.ndarray, float, int]:
    """|W ∩ (W + d)| on a grid of lags ``d`` (an FFT autocorrelation of W's raster).

    Returns
    -------
    cov : (2 L + 1, 2 L + 1) float
        ``cov[L + j, L + i]`` is the area for lag ``(i * cell, j * cell)``.
    cell : float
    L : int
    """
    x0, y0, x1, y1 = window.bounds
    # |W ∩ (W + d)| changes by about (perimeter x |dd|) for a lag change dd, so a raster of
    # about 256 cells across the window keeps its relative error near 1 %
    cell = max(cell, max(x1 - x0, y1 - y0) / 256.0)
    nx = max(1, int(math.ceil((x1 - x0) / cell)))
    ny = max(1, int(math.ceil((y1 - y0) / cell)))
    xs = x0 + (np.arange(nx) + 0.5) * cell
    ys = y0 + (np.arange(ny) + 0.5) * cell
    gx, gy = np.meshgrid(xs, ys)
    shapely.prepare(window)
    mask = shapely.contains_xy(window, gx.ravel(), gy.ravel()).reshape(ny, nx).astype(float)
    L = int(math.ceil(reach / cell)) + 1
    sy, sx = _fft_size(ny + L + 1), _fft_size(nx + L + 1)
    f = np.fft.rfft2(mask, s=(sy, sx))
    ac = np.fft.irfft2(f * np.conj(f), s=(sy, sx))
    rows = np.r_[np.arange(-L, 0) % sy, np.arange(0, L + 1)]
    cols = np.r_[np.arange(-L, 0) % sx, np.arange(0, L + 1)]
    cov = ac[np.ix_(rows, cols)] * cell * cell
    return np.maximum(cov, 0.0), cell, L


def _fft_size(n: int) -> int:
    m = 1
    while m < n:
        m *= 2
    if m // 4 * 3 >= n:
        return m // 4 * 3
    return m


def _interior(geom: shapely.Geometry, margin: float) -> shapely.Geometry:
    inner = shapely.buffer(geom, -margin)
    return inner


# -- the measured sample -----------------------------------------------------------------


@dataclass
class _Sample:
    """Visible elements of one arrangement, in the comparison's common kind indices."""

    xy: np.ndarray  # (n, 2)
    kind: np.ndarray  # (n,) int, K = not an exemplar kind
    rotation: np.ndarray  # (n,)
    radius: np.ndarray  # (n,)
    sym: np.ndarray  # (n,) int symmetry order (0: isotropic)
    window: shapely.Geometry  # where statistics are taken
    region: shapely.Geometry  # the whole domain (for the Hanisch correction and empty circles)
    wall: float = 0.0  # kind counts (fraction, density) only from centres this far from the domain's boundary


def _visible(arr: Arrangement) -> np.ndarray:
    if "void" in arr:
        v = np.asarray(arr["void"])
        try:
            return ~v.astype(bool)
        except (TypeError, ValueError):
            raise InputError("void column: must hold booleans") from None
    return np.ones(len(arr), bool)


def _sample(arr: Arrangement, kinds: list[str], sym_of: dict[str, int], region: shapely.Geometry, window: shapely.Geometry) -> _Sample:
    vis = _visible(arr)
    lookup = {k: i for i, k in enumerate(kinds)}
    names = arr.kinds
    code = np.array([lookup.get(k, len(kinds)) for k in names], dtype=np.int64)
    kind = code[arr.kind[vis]] if len(names) else np.zeros(0, np.int64)
    rad_of = np.array([arr.shapes[k].radius for k in names], dtype=float)
    symk = np.array([sym_of.get(k, 1) for k in names], dtype=np.int64)
    return _Sample(
        xy=np.asarray(arr.xy[vis], float),
        kind=kind,
        rotation=np.asarray(arr.rotation[vis], float),
        radius=rad_of[arr.kind[vis]] * np.asarray(arr.scale[vis], float),
        sym=symk[arr.kind[vis]],
        window=window,
        region=region,
    )


# -- raw per-element and per-pair quantities (computed once, aggregated per window) ------


@dataclass
class _Raw:
    pairs: np.ndarray  # (m, 2) int, i < j, |d| <= R_MAX s
    dvec: np.ndarray  # (m, 2) float, xy[j] - xy[i]
    dist: np.ndarray  # (m,) float
    nn: np.ndarray  # (n, K) distance to the nearest element of each kind (inf: none)
    to_edge: np.ndarray  # (n,) distance to the region boundary
    lattice_ok: np.ndarray | None  # (n,) bool, None when not lattice-like
    lattice_valid: np.ndarray | None  # (n,) bool: all pattern neighbours could be seen
    rel: np.ndarray  # (q,) relative rotation bins per (element, neighbour) record
    bear: np.ndarray  # (q,) bearing bins
    orient_owner: np.ndarray  # (q,) element index of each record
    circ_c: np.ndarray  # (t, 2) empty circle centres (wholly inside the region)
    circ_r: np.ndarray  # (t,)
    cell_area: np.ndarray  # (n,) Voronoi cell area
    cell_ok: np.ndarray  # (n,) bool: the cell is bounded and decided by elements of the domain
    counted: np.ndarray  # (n,) bool: beyond the frame's wall reach (minus sampling of kind counts)


REL_BINS = 8
BEAR_BINS = 16


def _raw(sm: _Sample, K: int, s: float, template: tuple[int, np.ndarray] | None) -> _Raw:
    from scipy.spatial import Delaunay, cKDTree

    xy, n = sm.xy, len(sm.xy)
    tree = cKDTree(xy)
    pairs = tree.query_pairs(R_MAX * s, output_type="ndarray").astype(np.int64).reshape(-1, 2)
    dvec = xy[pairs[:, 1]] - xy[pairs[:, 0]]
    dist = np.hypot(dvec[:, 0], dvec[:, 1])
    nn = np.full((n, K), np.inf)
    for b in range(K):
        sel = np.flatnonzero(sm.kind == b)
        if len(sel) == 0:
            continue
        tb = cKDTree(xy[sel])
        d, j = tb.query(xy, k=min(2, len(sel)))
        d = d.reshape(n, -1)
        j = j.reshape(n, -1)
        first = np.where(sel[j[:, 0]] == np.arange(n), d[:, -1] if d.shape[1] > 1 else np.inf, d[:, 0])
        nn[:, b] = first
    to_edge = shapely.distance(sm.region.boundary, shapely.points(xy)) if n else np.zeros(0)
    lattice_ok = lattice_valid = None
    if template is not None and n:
        lattice_ok = _lattice_match(sm, tree, s, template)
        lattice_valid = to_edge >= LATTICE_REACH * s + 0.5 * s
    rel, bear, owner = _orientation_records(sm, tree)
    circ_c, circ_r = np.zeros((0, 2)), np.zeros(0)
    cell_area, cell_ok = np.zeros(n), np.zeros(n, bool)
    if n >= 3:
        try:
            tri = Delaunay(xy)
            simp = tri.simplices
            circ_c, circ_r, keep_t = _circumcircles(xy[simp])
            cell_area, cell_ok = _voronoi_cells(xy, simp[keep_t], circ_c, circ_r, to_edge, tri)
        except Exception:  # degenerate (collinear) point sets have no triangulation
            pass
        if len(circ_r):
            inside = shapely.contains_xy(sm.region, circ_c[:, 0], circ_c[:, 1])
            inside &= shapely.distance(sm.region.boundary, shapely.points(circ_c)) >= circ_r
            circ_c, circ_r = circ_c[inside], circ_r[inside]
    counted = to_edge >= sm.wall if sm.wall > 0 else np.ones(n, bool)
    return _Raw(pairs, dvec, dist, nn, to_edge, lattice_ok, lattice_valid, rel, bear, owner, circ_c, circ_r, cell_area, cell_ok, counted)


def _wall_reach(xy: np.ndarray, kind: np.ndarray, radius: np.ndarray, region: shapely.Geometry) -> float:
    """How far in from its frame an arrangement's kind shares are biased by the frame (0: not).

    A frame that elements of several sizes are kept wholly inside is a wall, not a window
    on a larger texture: each kind's centres keep off it by about the kind's radius, so
    a band along it holds only the smaller kinds, and the kinds kept off pack in a layer
    against the band (measured over 40 draws of the suite's three_sizes: no large stone
    within 1.0 R of the frame, R the largest radius; 1.5-1.8 x the interior's density of
    them at 1.0-1.5 R, small stones at 3 x theirs at 0.25-0.5 R; the shares settle from
    about 2 R on). With ``m_k`` the least distance of kind k's centres to the frame and
    ``r_k`` its largest bounding radius, the frame is such a wall when there are several
    kinds, every kind keeps ``m_k >= 0.75 r_k`` (held inside by its size: no kind crosses
    the frame as in a crop, nor is cut by it as rings' tiles are, whose hubs sit at the
    lattice's phase) and the kinds keep off by different distances (``max m >= 1.25 min
    m``: the band between holds only the nearer kinds; stripes' dots and bars, thrown as
    equal discs, keep the same). Its reach is then ``2 max_k min(m_k, r_k)`` (a kind kept
    off by more than its radius is chance: a few boulders), else 0.
    """
    kinds = np.unique(kind)
    if len(xy) == 0 or len(kinds) < 2:
        return 0.0
    edge = shapely.distance(region.boundary, shapely.points(xy))
    edge = np.where(shapely.contains_xy(region, xy[:, 0], xy[:, 1]), edge, 0.0)
    m = np.array([edge[kind == k].min() for k in kinds])
    r = np.array([radius[kind == k].max() for k in kinds])
    if not (np.all(m >= 0.75 * r) and m.max() >= 1.25 * m.min()):
        return 0.0
    return 2.0 * float(np.minimum(m, r).max())


def _voronoi_cells(xy: np.ndarray, simp: np.ndarray, cc: np.ndarray, cr: np.ndarray, to_edge: np.ndarray, tri: Any) -> tuple[np.ndarray, np.ndarray]:
    """Voronoi cell areas from the Delaunay triangles, and which cells are trustworthy.

    A cell is the sum, over its element's triangles, of the signed areas of the two
    triangles (element, edge midpoint, circumcentre). It is trusted when the element is
    inside the convex hull's interior and every circumcircle of its triangles is nearer
    than the domain's boundary (the cell then cannot change with elements beyond it).
    """
    n = len(xy)
    area = np.zeros(n)
    reach = np.zeros(n)
    for k in range(3):
        a, b, c = simp[:, k], simp[:, (k + 1) % 3], simp[:, (k + 2) % 3]
        pa = xy[a]
        mab = 0.5 * (pa + xy[b])
        mac = 0.5 * (pa + xy[c])

        def tri_area(p: np.ndarray, q: np.ndarray, r: np.ndarray) -> np.ndarray:
            return 0.5 * ((q[:, 0] - p[:, 0]) * (r[:, 1] - p[:, 1]) - (q[:, 1] - p[:, 1]) * (r[:, 0] - p[:, 0]))

        contrib = tri_area(pa, mab, cc) + tri_area(pa, cc, mac)
        orient = np.sign(tri_area(pa, xy[b], xy[c]))
        area += np.bincount(a, contrib * orient, minlength=n)
        order = np.lexsort((cr, a))  # by element, then circumradius: each group's last is its largest
        sa = a[order]
        last = np.r_[sa[1:] != sa[:-1], True]
        reach[sa[last]] = np.maximum(reach[sa[last]], cr[order][last])
    hull = np.zeros(n, bool)
    hull[np.unique(tri.convex_hull)] = True
    ok = ~hull & (reach <= to_edge) & (area > 0)
    return area, ok


def _circumcircles(t: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    from ._kernels.geometry import circumcircles

    return circumcircles(t[:, 0], t[:, 1], t[:, 2])


def _orientation_records(sm: _Sample, tree: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    n = len(sm.xy)
    aniso = sm.sym > 0
    if n < 2 or not aniso.any():
        z = np.zeros(0, np.int64)
        return z, z, z
    k = min(ORIENT_K, n - 1)
    dk, j = tree.query(sm.xy, k=k + 1)
    j = j[:, 1:]
    i = np.repeat(np.arange(n), k)
    j = j.ravel()
    # border correction (as Hanisch's): an element speaks only when its k nearest
    # neighbours are all nearer than the domain's boundary
    seen = np.repeat(dk[:, -1] <= shapely.distance(sm.region.boundary, shapely.points(sm.xy)), k)
    keep = aniso[i] & aniso[j] & seen
    i, j = i[keep], j[keep]
    mi, mj = sm.sym[i], sm.sym[j]
    period_rel = 2 * np.pi / np.where(sm.kind[i] == sm.kind[j], mi, np.lcm(mi, mj))
    u = ((sm.rotation[j] - sm.rotation[i]) % period_rel) / period_rel
    u = 2.0 * np.minimum(u, 1.0 - u)  # folded: the sign of a relative turn is not kept
    rel = np.minimum((u * REL_BINS).astype(np.int64), REL_BINS - 1)
    d = sm.xy[j] - sm.xy[i]
    period_b = 2 * np.pi / mi
    ub = ((np.arctan2(d[:, 1], d[:, 0]) - sm.rotation[i]) % period_b) / period_b
    bear = np.rint(ub * BEAR_BINS).astype(np.int64) % BEAR_BINS  # bins centred on 0: lattice bearings sit mid-bin
    return rel, bear, i


def _local_offsets(sm: _Sample, tree: Any, s: float, count: int, which: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(m, count + 1, 2) local-frame offsets to the neighbours within reach (NaN: none) and
    (m,) neighbour counts (``count + 1`` means more than ``count``)."""
    k = count + 2
    d, j = tree.query(sm.xy[which], k=min(k, len(sm.xy)), distance_upper_bound=LATTICE_REACH * s)
    d = d.reshape(len(which), -1)[:, 1:]
    j = j.reshape(len(which), -1)[:, 1:]
    found = np.isfinite(d)
    cnt = found.sum(axis=1)
    jj = np.where(found, j, 0)
    off = sm.xy[jj] - sm.xy[which][:, None, :]
    c, sn = np.cos(-sm.rotation[which]), np.sin(-sm.rotation[which])
    loc = np.stack([c[:, None] * off[..., 0] - sn[:, None] * off[..., 1], sn[:, None] * off[..., 0] + c[:, None] * off[..., 1]], axis=-1)
    loc[~found] = np.nan
    return loc, cnt


def _match(loc: np.ndarray, cnt: np.ndarray, sym: np.ndarray, s: float, template: tuple[int, np.ndarray]) -> np.ndarray:
    count, tpl = template
    ok = cnt == count
    best = np.full(len(loc), False)
    for m in sorted(set(int(v) for v in np.unique(sym))):
        sel = sym == m
        turns = [0.0] if m <= 1 else [2 * np.pi * t / m for t in range(m)]
        for t in turns:
            c, sn = np.cos(t), np.sin(t)
            tt = np.c_[c * tpl[:, 0] - sn * tpl[:, 1], sn * tpl[:, 0] + c * tpl[:, 1]]
            dd = np.hypot(loc[sel][:, None, :, 0] - tt[None, :, None, 0], loc[sel][:, None, :, 1] - tt[None, :, None, 1])
            hit = np.all(np.nanmin(np.where(np.isnan(dd), np.inf, dd), axis=2) <= LATTICE_MATCH * s, axis=1)
            best[sel] |= hit
    return ok & best


def _lattice_match(sm: _Sample, tree: Any, s: float, template: tuple[int, np.ndarray]) -> np.ndarray:
    loc, cnt = _local_offsets(sm, tree, s, template[0], np.arange(len(sm.xy)))
    return _match(loc, cnt, sm.sym, s, template)


def _lattice_template(sm: _Sample, s: float) -> tuple[tuple[int, np.ndarray] | None, float]:
    """The exemplar's dominant neighbour pattern, and the share of its interior that matches."""
    from scipy.spatial import cKDTree

    n = len(sm.xy)
    if n < 8:
        return None, float("nan")
    tree = cKDTree(sm.xy)
    edge = shapely.distance(sm.region.boundary, shapely.points(sm.xy))
    inner = np.flatnonzero(edge >= LATTICE_REACH * s + 0.5 * s)
    if len(inner) < 4:
        return None, float("nan")
    loc, cnt = _local_offsets(sm, tree, s, 12, inner)
    counts = np.bincount(cnt)
    count = int(np.argmax(counts[1:]) + 1) if len(counts) > 1 else 0
    if count == 0:
        return None, float("nan")
    with_count = np.flatnonzero(cnt == count)
    centre = sm.xy[inner].mean(axis=0)
    first = with_count[np.argmin(np.hypot(*(sm.xy[inner[with_count]] - centre).T))]
    tpl = loc[first, :count].copy()
    for _ in range(2):  # refine: average each slot over the elements with the dominant count
        sub = loc[with_count, : count + 1]
        dd = np.hypot(sub[:, None, :, 0] - tpl[None, :, None, 0], sub[:, None, :, 1] - tpl[None, :, None, 1])
        dd = np.where(np.isnan(dd), np.inf, dd)
        arg = np.argmin(dd, axis=2)
        near = np.take_along_axis(dd, arg[..., None], axis=2)[..., 0] <= LATTICE_MATCH * s
        pts = np.take_along_axis(sub, arg[..., None].repeat(2, axis=-1), axis=1)
        for k in range(count):
            if near[:, k].any():
                tpl[k] = pts[near[:, k], k].mean(axis=0)
    template = (count, tpl)
    share = float(_match(loc[:, : count + 1], np.minimum(cnt, count + 1), sm.sym[inner], s, template).mean())
    return template, share


# -- aggregation over a window -------------------------------------------------------------


@dataclass
class _Stats:
    area: float
    counts: np.ndarray  # (K + 1,)
    fraction: np.ndarray  # (K + 1,)
    density: np.ndarray  # (K,)
    g: np.ndarray  # (K, K, nb)
    nn: np.ndarray  # (K, K, 9) deciles (NaN: too few)
    regularity: float
    rel: np.ndarray  # (REL_BINS,)
    bear: np.ndarray  # (BEAR_BINS,)
    q95: float
    lec: float


def _stats(
    sm: _Sample,
    raw: _Raw,
    K: int,
    s: float,
    window: shapely.Geometry,
    *,
    cov: tuple[np.ndarray, float, int] | None = None,
    members: tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray] | None = None,
) -> _Stats:
    """Statistics of the elements inside ``window``.

    ``members`` may give, precomputed, the indices of the elements, of the pairs (both
    ends inside), of the orientation records (owner inside) and of the empty circles
    (centre inside) that belong to the window.
    """
    n = len(sm.xy)
    if members is None:
        inside = shapely.contains_xy(window, sm.xy[:, 0], sm.xy[:, 1]) if n else np.zeros(0, bool)
        idx = np.flatnonzero(inside)
        pidx = np.flatnonzero(inside[raw.pairs[:, 0]] & inside[raw.pairs[:, 1]]) if len(raw.pairs) else np.zeros(0, np.int64)
        ridx = np.flatnonzero(inside[raw.orient_owner]) if len(raw.orient_owner) else np.zeros(0, np.int64)
        cidx = np.flatnonzero(shapely.contains_xy(window, raw.circ_c[:, 0], raw.circ_c[:, 1])) if len(raw.circ_r) else np.zeros(0, np.int64)
    else:
        idx, pidx, ridx, cidx = members
    area = float(window.area)
    kin = sm.kind[idx]
    counts = np.bincount(kin, minlength=K + 1).astype(float)[: K + 1]
    # kind shares by minus sampling (the border method: only centres beyond the frame's
    # wall reach count, see _wall_reach): a stationary result's interior takes the
    # exemplar's interior shares, not those of the band along its frame
    ci = idx[raw.counted[idx]]
    shares = np.bincount(sm.kind[ci], minlength=K + 1).astype(float)[: K + 1]
    tot = shares.sum()
    fraction = shares / tot if tot else np.full(K + 1, np.nan)
    # density per kind: the kind's share of the window's counted elements times the
    # elements per unit area of their Voronoi cells that elements beyond the domain cannot
    # change; no frame, margin or crop biases either factor
    v = ci[raw.cell_ok[ci]]
    cell_total = float(raw.cell_area[v].sum())
    if len(v) >= 3 and cell_total > 0 and tot > 0:
        density = shares[:K] / tot * (len(v) / cell_total)
    else:
        density = np.full(K, np.nan)
    # g_ab(r), translation correction
    nb = int(round(R_MAX / BIN))
    edges = np.arange(nb + 1) * BIN * s
    ring = np.pi * (edges[1:] ** 2 - edges[:-1] ** 2)
    g = np.full((K, K, nb), np.nan)
    nk = counts[:K]
    lam2 = np.zeros((K, K))
    if area > 0:
        lam2 = np.outer(nk, nk) - np.diag(nk)  # n_a n_b, and n_a (n_a - 1) on the diagonal
        lam2 = lam2 / (area * area)
    if len(pidx):
        if cov is None:
            cov = _set_covariance(window, s / 6.0, R_MAX * s)
        cv, cell, L = cov
        p, dv, d = raw.pairs[pidx], raw.dvec[pidx], raw.dist[pidx]
        ix = np.clip(np.rint(dv[:, 0] / cell).astype(np.int64) + L, 0, 2 * L)
        iy = np.clip(np.rint(dv[:, 1] / cell).astype(np.int64) + L, 0, 2 * L)
        c = cv[iy, ix]
        # lags the window barely holds (|W ∩ (W + d)| below 2 % of |W|) would weigh a pair
        # by thousands: leave them out rather than let one pair swamp g
        w = np.where(c > 0.02 * area, 1.0 / np.maximum(c, 1e-300), 0.0)
        ka, kb = sm.kind[p[:, 0]], sm.kind[p[:, 1]]
        ok = (ka < K) & (kb < K)
        ka, kb, w, d = ka[ok], kb[ok], w[ok], d[ok]
        # linear binning onto bin centres
        t = d / (BIN * s) - 0.5
        lo = np.floor(t).astype(np.int64)
        fr = t - lo
        size = K * K * (nb + 2)
        acc = np.zeros(size)
        for a_, b_ in ((ka, kb), (kb, ka)):
            # each unordered pair goes to (a, b) and (b, a): (a, a) gets the ordered sum
            flat = (a_ * K + b_) * (nb + 2)
            acc += np.bincount(flat + np.clip(lo + 1, 0, nb + 1), w * (1 - fr), minlength=size)
            acc += np.bincount(flat + np.clip(lo + 2, 0, nb + 1), w * fr, minlength=size)
        acc = acc.reshape(K, K, nb + 2)[:, :, 1 : nb + 1]
        has = lam2 > 0
        g[has] = acc[has] / (lam2[has][:, None] * ring[None, :])
    else:
        g[lam2 > 0] = 0.0
    # nearest neighbour deciles; neighbours were found among all elements of the domain,
    # so only the domain's boundary hides any: Hanisch's border correction against it
    nnq = np.full((K, K, len(DECILES)), np.nan)
    for a in range(K):
        ia = idx[kin == a]
        if len(ia) < MIN_NN:
            continue
        for b in range(K):
            d = raw.nn[ia, b]
            d = d[np.isfinite(d) & (d <= raw.to_edge[ia])]
            if len(d) >= MIN_NN:
                nnq[a, b] = _deciles(d)
    reg = float("nan")
    if raw.lattice_ok is not None:
        v = idx[raw.lattice_valid[idx]]
        if len(v) >= 3:
            reg = float(raw.lattice_ok[v].mean())
    rel = np.bincount(raw.rel[ridx], minlength=REL_BINS).astype(float)
    bear = np.bincount(raw.bear[ridx], minlength=BEAR_BINS).astype(float)
    rel = rel / rel.sum() if rel.sum() >= MIN_RECORDS else np.full(REL_BINS, np.nan)
    bear = bear / bear.sum() if bear.sum() >= MIN_RECORDS else np.full(BEAR_BINS, np.nan)
    q95 = lec = float("nan")
    if len(cidx) >= MIN_RECORDS:
        rr = raw.circ_r[cidx]
        q95 = float(np.quantile(rr, 0.95))
        lec = float(rr.max())
    return _Stats(area, counts, fraction, density, g, nnq, reg, rel, bear, q95, lec)


def _deciles(d: np.ndarray) -> np.ndarray:
    """np.quantile(d, DECILES) (linear interpolation), without its per-call overhead."""
    d = np.sort(d)
    pos = DECILES * (len(d) - 1)
    lo = np.floor(pos).astype(np.int64)
    hi = np.minimum(lo + 1, len(d) - 1)
    fr = pos - lo
    return d[lo] * (1 - fr) + d[hi] * fr


# -- discrepancies -------------------------------------------------------------------------


def _family(name: str) -> str:
    return name.split("[")[0].split(".")[0]


def _discrepancies(a: _Stats, b: _Stats, kinds: list[str], s: float, *, lattice: bool, oriented: bool, other: bool) -> dict[str, float]:
    """Discrepancy of ``a`` (result or a half) against ``b`` (exemplar or the other half)."""
    K = len(kinds)
    out: dict[str, float] = {}
    for k, name in enumerate(kinds):
        out[f"fraction[{name}]"] = abs(a.fraction[k] - b.fraction[k])
    if other:
        out["fraction[other]"] = abs(a.fraction[K] - b.fraction[K])
    for k, name in enumerate(kinds):
        out[f"density[{name}]"] = abs(a.density[k] / b.density[k] - 1.0) if b.density[k] > 0 else float("nan")
    for i in range(K):
        for j in range(i, K):
            ga, gb = a.g[i, j], b.g[i, j]
            out[f"g[{kinds[i]},{kinds[j]}]"] = float(np.sqrt(np.mean((ga - gb) ** 2)))
    for i in range(K):
        for j in range(K):
            out[f"nn[{kinds[i]}>{kinds[j]}]"] = float(np.mean(np.abs(a.nn[i, j] - b.nn[i, j])) / s)
    if lattice:
        out["regularity"] = b.regularity - a.regularity  # one-sided: losing regularity fails
    if oriented:
        out["orientation.relative"] = 0.5 * float(np.sum(np.abs(a.rel - b.rel)))
        out["orientation.bearing"] = 0.5 * float(np.sum(np.abs(a.bear - b.bear)))
    out["empty_circle"] = abs(a.q95 / b.q95 - 1.0) if b.q95 > 0 else float("nan")
    return out


# -- the report ----------------------------------------------------------------------------


@dataclass
class MetricResult:
    """One metric: the result's discrepancy from the exemplar against its tolerance.

    ``value`` is the discrepancy (0 = identical), ``result`` and ``exemplar`` the plain
    statistic on each side where one exists (a share, a density, a radius...), ``spread``
    the exemplar's half-against-half discrepancy the tolerance was derived from.
    """

    name: str
    value: float
    tolerance: float
    passed: bool
    result: float | None = None
    exemplar: float | None = None
    spread: float | None = None
    applicable: bool = True

    def to_dict(self) -> dict[str, Any]:
        return {k: _json_num(v) for k, v in self.__dict__.items()}


def _json_num(v: Any) -> Any:
    if isinstance(v, (float, np.floating)):
        v = float(v)
        return v if math.isfinite(v) else None
    if isinstance(v, np.integer):
        return int(v)
    if isinstance(v, np.bool_):
        return bool(v)
    return v


@dataclass
class FidelityReport:
    """How faithfully a result continues an exemplar (see :func:`fidelity`).

    Attributes
    ----------
    faithful : bool
        Every applicable metric passed.
    failures : list of str
        Names of the metrics that failed.
    metrics : dict of str to MetricResult
    kinds : list of str
        The exemplar's visible kinds, in order.
    s : float
        The exemplar's median nearest-neighbour distance (the length unit).
    r : (nb,) float
        Bin centres of g(r).
    g_exemplar, g_result : dict of "a,b" to (nb,) float
    local : dict
        The local map: ``x0``, ``y0``, ``step``, ``window`` (side), ``score``
        (rows, cols) float (NaN where no window), ``worst_metric`` (rows, cols) str,
        and ``worst``: the worst window's ``bounds``, ``score`` and ``metric``.
    info : dict
        Counts, void shares, lattice detection, largest empty circles, windows' areas.
    """

    faithful: bool
    failures: list[str]
    metrics: dict[str, MetricResult]
    kinds: list[str]
    s: float
    r: np.ndarray
    g_exemplar: dict[str, np.ndarray]
    g_result: dict[str, np.ndarray]
    local: dict[str, Any]
    info: dict[str, Any] = field(default_factory=dict)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready dict (NaN and inf become null)."""

        def arr(a: Any) -> Any:
            return [_json_num(v) for v in np.asarray(a, float).ravel().tolist()] if np.ndim(a) <= 1 else [arr(row) for row in a]

        local = dict(self.local)
        local["score"] = arr(local["score"])
        local["worst_metric"] = [list(map(str, row)) for row in np.asarray(local["worst_metric"], dtype=object)]
        return {
            "faithful": bool(self.faithful),
            "failures": list(self.failures),
            "metrics": {k: m.to_dict() for k, m in self.metrics.items()},
            "kinds": list(self.kinds),
            "s": _json_num(self.s),
            "r": arr(self.r),
            "g_exemplar": {k: arr(v) for k, v in self.g_exemplar.items()},
            "g_result": {k: arr(v) for k, v in self.g_result.items()},
            "local": _jsonable(local),
            "info": _jsonable(self.info),
            "tolerance_rule": {"multiple": MULTIPLE, "eq5_multiple": EQ5_MULTIPLE, "floors": dict(FLOORS)},
        }

    def table(self) -> list[tuple[str, str, str, str, str]]:
        """Rows ``(metric, value, tolerance, exemplar -> result, verdict)`` as strings."""
        rows = []
        for m in self.metrics.values():
            if not m.applicable:
                rows.append((m.name, "-", "-", "", "n/a"))
                continue
            side = ""
            if m.exemplar is not None and m.result is not None:
                side = f"{_fmt(m.exemplar)} -> {_fmt(m.result)}"
            rows.append((m.name, _fmt(m.value), _fmt(m.tolerance), side, "pass" if m.passed else "FAIL"))
        return rows

    def __repr__(self) -> str:
        verdict = "faithful" if self.faithful else f"not faithful ({', '.join(self.failures)})"
        return f"FidelityReport({verdict}, {len(self.metrics)} metrics)"

    def _repr_html_(self) -> str:
        head = "<tr><th>metric</th><th>value</th><th>tolerance</th><th>exemplar &rarr; result</th><th></th></tr>"
        body = []
        for name, v, t, side, verdict in self.table():
            colour = "#b00" if verdict == "FAIL" else ("#888" if verdict == "n/a" else "#070")
            body.append(f"<tr><td>{html.escape(name)}</td><td>{v}</td><td>{t}</td><td>{html.escape(side)}</td><td style='color:{colour}'>{verdict}</td></tr>")
        worst = self.local.get("worst") or {}
        caption = "faithful" if self.faithful else "not faithful: " + html.escape(", ".join(self.failures))
        if worst:
            b = worst["bounds"]
            caption += f"; worst window ({b[0]:.4g}, {b[1]:.4g})-({b[2]:.4g}, {b[3]:.4g}) score {worst['score']:.3g} on {html.escape(str(worst['metric']))}"
        return f"<table><caption>{caption}</caption>{head}{''.join(body)}</table>"


def _fmt(v: Any) -> str:
    if v is None:
        return "-"
    v = float(v)
    if not math.isfinite(v):
        return "nan" if math.isnan(v) else "inf"
    return f"{v:.3g}"


def _jsonable(x: Any) -> Any:
    if isinstance(x, dict):
        return {str(k): _jsonable(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_jsonable(v) for v in x]
    if isinstance(x, np.ndarray):
        return _jsonable(x.tolist())
    return _json_num(x)


# -- public functions ----------------------------------------------------------------------


def _region_geom(arr: Arrangement, region: Region | None, pad: float) -> shapely.Geometry:
    reg = region if region is not None else arr.region
    if reg is not None:
        return reg.geometry
    vis = _visible(arr)
    xy = arr.xy[vis] if vis.any() else arr.xy
    if len(xy) == 0:
        return shapely.box(0, 0, 0, 0)
    x0, y0 = xy.min(axis=0)
    x1, y1 = xy.max(axis=0)
    return shapely.box(x0 - pad, y0 - pad, x1 + pad, y1 + pad)


def _median_nn(xy: np.ndarray) -> float:
    from scipy.spatial import cKDTree

    d, _ = cKDTree(xy).query(xy, k=2)
    return float(np.median(d[:, 1]))


def _check(arr: Any, name: str) -> Arrangement:
    if not isinstance(arr, Arrangement):
        raise InputError(f"{name}: must be an Arrangement, got {type(arr).__name__}")
    return arr


def _sym_of(*arrs: Arrangement) -> dict[str, int]:
    out: dict[str, int] = {}
    for a in arrs:
        for k, sh in a.shapes.items():
            if k not in out:
                out[k] = _symmetry_order(sh.geometry)
    return out


def pair_correlation(arr: Arrangement, region: Region | None = None, *, r_max: float | None = None, bins: int = 20) -> dict[str, Any]:
    """Pair correlation functions g_ab(r) of one arrangement, translation-corrected.

    Parameters
    ----------
    arr : Arrangement
        Void elements are left out.
    region : Region, optional
        The observation window; defaults to ``arr.region``, else the bounding box of the
        centres.
    r_max : float, optional
        Default 4 x the median nearest-neighbour distance.
    bins : int

    Returns
    -------
    dict
        ``r`` (bins,) bin centres and ``g``: ``"a,b"`` -> (bins,) float for each
        unordered kind pair (g_ab = g_ba); about 1 for a Poisson process.

    Examples
    --------
    >>> import numpy as np
    >>> from strew import Arrangement, Region, Shape
    >>> rng = np.random.default_rng(0)
    >>> p = rng.uniform(0, 100, (2000, 2))
    >>> a = Arrangement({"dot": Shape.circle(0.1)}, [0] * 2000, p[:, 0], p[:, 1], region=Region.rectangle(100, 100))
    >>> out = pair_correlation(a)
    >>> bool(abs(np.mean(out["g"]["dot,dot"][5:]) - 1) < 0.1)
    True
    """
    _check(arr, "arrangement")
    vis = _visible(arr)
    if vis.sum() < 2:
        raise InputError("arrangement: needs at least two visible elements for g(r)")
    s = _median_nn(arr.xy[vis])
    if not s > 0:
        raise InputError("arrangement: elements share one position; g(r) is undefined")
    r_max = R_MAX * s if r_max is None else float(r_max)
    if not (math.isfinite(r_max) and r_max > 0):
        raise InputError(f"r_max: must be a positive number, got {r_max!r}")
    if int(bins) < 1:
        raise InputError(f"bins: must be a positive integer, got {bins!r}")
    geom = _region_geom(arr, region, 0.0)
    kinds = [k for k in arr.kinds if np.any(arr.kind[vis] == arr.kinds.index(k))]
    sm = _sample(arr, kinds, {}, geom, geom)
    inside = shapely.contains_xy(geom, sm.xy[:, 0], sm.xy[:, 1])
    from scipy.spatial import cKDTree

    pairs = cKDTree(sm.xy).query_pairs(r_max, output_type="ndarray").astype(np.int64).reshape(-1, 2)
    pairs = pairs[inside[pairs[:, 0]] & inside[pairs[:, 1]]]
    dv = sm.xy[pairs[:, 1]] - sm.xy[pairs[:, 0]]
    d = np.hypot(dv[:, 0], dv[:, 1])
    cv, cell, L = _set_covariance(geom, min(r_max / 24.0, math.sqrt(geom.area) / 200.0) if geom.area > 0 else r_max / 24.0, r_max)
    ix = np.clip(np.rint(dv[:, 0] / cell).astype(np.int64) + L, 0, 2 * L)
    iy = np.clip(np.rint(dv[:, 1] / cell).astype(np.int64) + L, 0, 2 * L)
    c = cv[iy, ix]
    w = np.where(c > 0, 1.0 / np.maximum(c, 1e-300), 0.0)
    edges = np.linspace(0, r_max, int(bins) + 1)
    ring = np.pi * (edges[1:] ** 2 - edges[:-1] ** 2)
    area = geom.area
    K = len(kinds)
    nk = np.bincount(sm.kind[inside], minlength=K + 1)[:K].astype(float)
    out = {}
    for a in range(K):
        for b in range(a, K):
            sel = ((sm.kind[pairs[:, 0]] == a) & (sm.kind[pairs[:, 1]] == b)) | ((sm.kind[pairs[:, 0]] == b) & (sm.kind[pairs[:, 1]] == a))
            h = np.histogram(d[sel], bins=edges, weights=w[sel])[0]
            if a == b:
                h = 2 * h
                lam2 = nk[a] * (nk[a] - 1) / area**2
            else:
                lam2 = nk[a] * nk[b] / area**2
            out[f"{kinds[a]},{kinds[b]}"] = h / (lam2 * ring) if lam2 > 0 else np.full(int(bins), np.nan)
    return {"r": 0.5 * (edges[1:] + edges[:-1]), "g": out, "r_max": r_max}


def nearest_neighbor_distances(arr: Arrangement) -> dict[str, dict[str, float]]:
    """Median and mean distance from each kind to the nearest element of each kind.

    Returns
    -------
    dict
        ``"a>b"`` -> ``{"median", "mean", "count"}`` (void elements left out).
    """
    from scipy.spatial import cKDTree

    _check(arr, "arrangement")
    vis = _visible(arr)
    xy, kind = arr.xy[vis], arr.kind[vis]
    out: dict[str, dict[str, float]] = {}
    for a, na in enumerate(arr.kinds):
        ia = np.flatnonzero(kind == a)
        if len(ia) == 0:
            continue
        for b, nb in enumerate(arr.kinds):
            ib = np.flatnonzero(kind == b)
            if len(ib) == 0 or (a == b and len(ib) < 2):
                continue
            d, _ = cKDTree(xy[ib]).query(xy[ia], k=2 if a == b else 1)
            d = d[:, 1] if a == b else d
            out[f"{na}>{nb}"] = {"median": float(np.median(d)), "mean": float(np.mean(d)), "count": int(len(ia))}
    return out


def _frame_turns(exemplar: Arrangement, output: Arrangement, sym: dict[str, int]) -> np.ndarray:
    """Each output element's turn from its kind's frame in the exemplar (radians, (n,)).

    The frame of a kind is the circular mean of its exemplar rotations modulo the
    shape's symmetry (2 pi / order). A kind without one (a disc, or exemplar rotations
    spread all round: resultant length below :data:`EQ5_FRAME_R`) turns by 0.
    """
    turns = np.zeros(len(output))
    ex_names = np.asarray(exemplar.kind_names)
    out_names = np.asarray(output.kind_names)
    for name in np.unique(out_names):
        order = sym.get(str(name), 0)
        rot = exemplar.rotation[ex_names == name]
        if order == 0 or len(rot) == 0:
            continue
        z = np.exp(1j * order * rot).mean()
        if abs(z) < EQ5_FRAME_R:
            continue
        sel = out_names == name
        d = order * output.rotation[sel] - np.angle(z)
        turns[sel] = np.angle(np.exp(1j * d)) / order  # within (-pi / order, pi / order]
    return turns


def _eq5(exemplar_vis: Arrangement, output: Arrangement, measure: np.ndarray, sample: int, turns: np.ndarray | None = None) -> float:
    """Davison Eq. 5 of the ``measure`` elements of ``output`` against ``exemplar_vis``
    (kinds matched by name; a fixed-seed sample of ``sample`` elements). With ``turns``
    (n,) each measured element's neighbourhood is turned back by its turn first: Eq. 5
    in the element's local frame."""
    from .synth import _kernels as K
    from .synth._api import new_state
    from .synth._metric import neighborhood_distances
    from .synth._palette import RING_FACTOR, average_spacing

    if len(output) == 0 or len(exemplar_vis) < 2:
        return float("nan")
    if "neighborhood_radius" not in exemplar_vis:
        # Eq. 5 with the paper's r-bar (§6.1: three times the exemplar's average spacing)
        # for every element, not synth's larger r-bar for larger size classes (an
        # extension for synthesis, see synth._palette.element_parameters): the measure
        # then does not move with synthesis settings, and a larger class's wide
        # neighbourhoods do not swamp it (clusters: a scatter scored 0.92x the tolerance
        # with them, 2.3x without)
        rbar = RING_FACTOR * average_spacing(exemplar_vis.xy)
        exemplar_vis = exemplar_vis.with_columns(neighborhood_radius=np.full(len(exemplar_vis), rbar))
    state = new_state(exemplar_vis, None, rng=0)
    prep = state.prep
    ex_kind_names = np.asarray(exemplar_vis.kind_names)
    src = np.full(len(output), -1, np.int64)
    out_names = np.asarray(output.kind_names)
    for name in np.unique(out_names):
        cand = np.flatnonzero(ex_kind_names == name)
        if len(cand) == 0:
            continue
        sel = np.flatnonzero(out_names == name)
        # the exemplar element of that kind whose scale is closest carries r and r-bar (§4.1)
        j = np.argmin(np.abs(exemplar_vis.scale[cand][None, :] - output.scale[sel][:, None]), axis=1)
        src[sel] = cand[j]
    keep = src >= 0
    if not keep.any():
        return float("nan")
    if len(prep.kind) != len(exemplar_vis):  # the palette may reorder elements: map through positions
        return float("nan")
    state.add(src[keep], output.xy[keep], horizon=False)
    # measure the elements of the window only, with their whole neighbourhoods
    which = np.flatnonzero(measure[keep])
    if len(which) == 0:
        return float("nan")
    if len(which) > sample:
        which = np.sort(np.random.default_rng(0).choice(which, sample, replace=False))
    if turns is None:
        return float(neighborhood_distances(state, which).mean())
    # neighborhood_distances with each neighbourhood's offsets turned by -turn (its
    # element's local frame); the same kernels
    turn = np.asarray(turns, float)[keep][which]
    src_s = state.src
    sel = np.flatnonzero(prep.selected_elements).astype(np.int64)
    ptr, idx, off = K.grid_neighborhoods(state.pos, which, prep.rbar[src_s[which]])
    t = np.repeat(turn, np.diff(ptr))
    c, s = np.cos(t), np.sin(t)
    off = np.ascontiguousarray(np.c_[c * off[:, 0] + s * off[:, 1], -s * off[:, 0] + c * off[:, 1]])
    cands = np.tile(sel, (len(which), 1))
    costs = K.candidate_costs(ptr, off, prep.kind[src_s[idx]], 2.0 * prep.r[src_s[idx]], prep.rbar[src_s[which]], prep.kind[src_s[which]], 2.0 * prep.r[src_s[which]], cands, prep.nb_ptr, prep.nb_off, prep.nb_kind, prep.nb_d, prep.kind, prep.kind_cost)
    return float(costs.min(axis=1).mean())


def fidelity(exemplar: Arrangement, result: Arrangement, region: Region | None = None, *, eq5: bool = True, local: bool = True, eq5_frame: str = "auto") -> FidelityReport:
    """Measure how faithfully ``result`` continues ``exemplar``.

    Parameters
    ----------
    exemplar : Arrangement
        Its ``region`` (or the bounding box of its centres) is its frame.
    result : Arrangement
    region : Region, optional
        The result's domain; defaults to ``result.region``, else the bounding box of its
        centres.
    eq5 : bool
        Also measure Davison's Eq. 5 (a brute-force neighbourhood match, on a sample of
        400 result elements).
    local : bool
        Also compute the local fidelity map.
    eq5_frame : {"auto", "global", "local"}
        Measure Eq. 5 in the global frame, or in each result element's local frame
        (its neighbourhood turned back by the element's turn from its kind's frame in
        the exemplar; kinds without a frame, such as discs, are not turned). ``"auto"``:
        local for a result made in a rotating mode (``meta["params"]["mode"]`` is
        ``"rotate"`` or ``"flow"``, as grow records it), else global. The tolerance is
        the same either way.

    Returns
    -------
    FidelityReport

    Raises
    ------
    InputError
        Too few visible exemplar elements, an empty result, no kind in common, or a
        region too small to hold an interior.

    Examples
    --------
    >>> import numpy as np
    >>> from strew import Arrangement, Region, Shape
    >>> g = np.mgrid[0:10, 0:10].reshape(2, -1).T * 10.0 + 5
    >>> ex = Arrangement({"sq": Shape.rectangle(6, 6)}, [0] * 100, g[:, 0], g[:, 1], region=Region.rectangle(100, 100))
    >>> big = np.mgrid[0:40, 0:40].reshape(2, -1).T * 10.0 + 5
    >>> out = Arrangement({"sq": Shape.rectangle(6, 6)}, [0] * 1600, big[:, 0], big[:, 1], region=Region.rectangle(400, 400))
    >>> fidelity(ex, out, eq5=False).faithful
    True
    """
    _check(exemplar, "exemplar")
    _check(result, "result")
    if eq5_frame not in EQ5_FRAMES:
        raise InputError(f"eq5_frame: must be one of {', '.join(EQ5_FRAMES)}, got {eq5_frame!r}")
    if eq5_frame == "auto":
        params = result.meta.get("params") if isinstance(result.meta, dict) else None
        mode = params.get("mode") if isinstance(params, dict) else None
        eq5_frame = "local" if mode in ("rotate", "flow") else "global"
    if region is not None and not isinstance(region, Region):
        raise InputError(f"region: must be a Region, got {type(region).__name__}")
    ex_vis = _visible(exemplar)
    res_vis = _visible(result)
    if ex_vis.sum() < 3:
        raise InputError(f"exemplar: needs at least 3 visible elements, has {int(ex_vis.sum())}")
    if res_vis.sum() == 0:
        raise InputError("result: has no visible elements")
    kinds = [k for i, k in enumerate(exemplar.kinds) if np.any(exemplar.kind[ex_vis] == i)]
    res_kinds = {k for i, k in enumerate(result.kinds) if np.any(result.kind[res_vis] == i)}
    if not res_kinds & set(kinds):
        raise InputError(f"result: no kind in common with the exemplar (exemplar: {', '.join(kinds)}; result: {', '.join(sorted(res_kinds))})")
    K = len(kinds)
    from ._limits import check_kinds

    check_kinds(K, "exemplar")  # _raw holds an (n, K) table per sample, _stats K x K pairs
    s = _median_nn(exemplar.xy[ex_vis])
    if not (math.isfinite(s) and s > 0):
        raise InputError("exemplar: visible elements share positions; no length scale")
    sym = _sym_of(exemplar, result)

    # windows: the exemplar's frame less the median element radius; the result's interior
    ex_geom = _region_geom(exemplar, None, 0.5 * s)
    ex_win = ex_geom
    if exemplar.region is not None and bool(np.all(exemplar.region.contains_geometry(exemplar.geometry[ex_vis], tolerance=1e-6))):
        # drawn wholly inside its frame: centres keep about a radius off it
        ex_radius = float(np.median(np.array([exemplar.shapes[k].radius for k in exemplar.kinds])[exemplar.kind[ex_vis]] * exemplar.scale[ex_vis]))
        ex_win = _interior(ex_geom, ex_radius)
        if ex_win.is_empty or ex_win.area <= 0.25 * ex_geom.area:
            ex_win = ex_geom
    res_geom = _region_geom(result, region, 0.5 * s)
    ex = _sample(exemplar, kinds, sym, ex_geom, ex_win)
    res = _sample(result, kinds, sym, res_geom, res_geom)
    # kind counts by minus sampling beyond each side's wall reach (_wall_reach), the same
    # rule on both sides: the result's window is its interior beyond 2 s and its reach
    ex.wall = _wall_reach(ex.xy, ex.kind, ex.radius, ex_geom)
    while ex.wall > 0 and ex_win.intersection(_interior(ex_geom, ex.wall)).area < 0.25 * ex_win.area:
        ex.wall *= 0.8  # a small exemplar keeps a quarter of its window to count kinds in
    margin_used = max(RESULT_MARGIN * s, _wall_reach(res.xy, res.kind, res.radius, res_geom))
    res_win = _interior(res_geom, margin_used)
    if res_win.is_empty or res_win.area < 0.25 * ex_win.area:
        res_win, margin_used = res_geom, 0.0
    if res_win.is_empty or res_win.area <= 0:
        raise InputError("region: has no area to measure in")
    res.window = res_win

    template, ex_share = _lattice_template(ex, s)
    lattice = template is not None and ex_share >= LATTICE_SHARE
    tpl = template if lattice else None
    oriented = bool(np.any(ex.sym > 0))
    other = bool(np.any(res.kind == K))

    ex_raw = _raw(ex, K, s, tpl)
    res_raw = _raw(res, K, s, tpl)
    ex_stats = _stats(ex, ex_raw, K, s, ex_win)
    res_stats = _stats(res, res_raw, K, s, res_win)
    flags = dict(lattice=lattice, oriented=oriented, other=other)
    disc = _discrepancies(res_stats, ex_stats, kinds, s, **flags)

    # the exemplar's own noise: three splits into two halves of equal area
    halves = _halves(ex_win)
    split_disc: list[dict[str, float]] = []
    for ha, hb in halves:
        sa = _stats(ex, ex_raw, K, s, ha)
        sb = _stats(ex, ex_raw, K, s, hb)
        split_disc.append(_discrepancies(sa, sb, kinds, s, **flags))

    # the result's own sampling noise adds to the exemplar's: var = sigma^2 (1 + A_ex / A_res)
    noise_factor = math.sqrt(1.0 + ex_win.area / res_win.area)
    # a metric applies when the exemplar itself can provide it (a g for a pair of kinds
    # with at least two elements, nearest neighbours of a kind seen three times...)
    self_disc = _discrepancies(ex_stats, ex_stats, kinds, s, **flags)
    metrics: dict[str, MetricResult] = {}
    for name, value in disc.items():
        fam = _family(name)
        # g needs lags up to 4 s inside each half: the quarter bands are too narrow for it
        use = split_disc[:3] if fam == "g" else split_disc
        vals = np.array([abs(d.get(name, np.nan)) for d in use], float)
        vals = vals[np.isfinite(vals)]
        spread = float(np.sqrt(np.mean(vals**2))) if len(vals) else float("nan")
        tol = max(FLOORS[fam], MULTIPLE * spread / 2.0 * noise_factor) if math.isfinite(spread) else float("nan")
        # not measured: the exemplar cannot provide it, or its halves are too small to
        # show its own noise (then no honest tolerance exists)
        if not math.isfinite(self_disc.get(name, np.nan)) or not math.isfinite(tol):
            metrics[name] = MetricResult(name, float("nan"), tol, True, applicable=False, spread=spread)
            continue
        passed = bool(math.isfinite(value) and value <= tol)
        metrics[name] = MetricResult(name, float(value), float(tol), passed, _side(res_stats, name, kinds), _side(ex_stats, name, kinds), spread)
    if not lattice:
        metrics["regularity"] = MetricResult("regularity", float("nan"), float("nan"), True, applicable=False, exemplar=ex_share if math.isfinite(ex_share) else None)
    if not oriented:
        for nm in ("orientation.relative", "orientation.bearing"):
            metrics[nm] = MetricResult(nm, float("nan"), float("nan"), True, applicable=False)

    info: dict[str, Any] = {
        "exemplar_count": int(len(exemplar)),
        "result_count": int(len(result)),
        "exemplar_visible": int(ex_vis.sum()),
        "result_visible": int(res_vis.sum()),
        "exemplar_void_share": float(1 - ex_vis.mean()) if len(exemplar) else 0.0,
        "result_void_share": float(1 - res_vis.mean()) if len(result) else 0.0,
        "lattice": bool(lattice),
        "lattice_share_exemplar": ex_share if math.isfinite(ex_share) else None,
        "lattice_pattern": None if tpl is None else {"count": int(tpl[0]), "offsets": np.round(tpl[1], 6).tolist()},
        "exemplar_window_area": float(ex_win.area),
        "result_window_area": float(res_win.area),
        "area_ratio": float(res_win.area / ex_win.area) if ex_win.area > 0 else None,
        "result_margin": margin_used,
        "exemplar_wall_reach": ex.wall,
        "largest_empty_circle": {"exemplar": ex_stats.lec, "result": res_stats.lec},
        "symmetry_order": {k: int(v) for k, v in sym.items() if k in kinds},
    }

    if eq5:
        ex_only = exemplar.select(ex_vis)
        if "void" in ex_only:
            ex_only = ex_only.without_columns("void")
        res_only = result.select(res_vis)
        if "void" in res_only:
            res_only = res_only.without_columns("void")
        turns = _frame_turns(ex_only, res_only, sym) if eq5_frame == "local" else None
        v = _eq5(ex_only, res_only, shapely.contains_xy(res_win, res_only.x, res_only.y), EQ5_SAMPLE, turns)
        cross = []
        for ha, hb in halves[:2]:
            ia = shapely.contains_xy(ha, ex_only.x, ex_only.y)
            ib = shapely.contains_xy(hb, ex_only.x, ex_only.y)
            ea, eb = ex_only.select(ia), ex_only.select(ib)
            if len(ea) >= 3 and len(eb) >= 3:
                # one half is the exemplar, the other the output; an output element near the
                # cut keeps only its own half's neighbours, as a result's would at a seam
                cross += [_eq5(ea, eb, np.ones(len(eb), bool), EQ5_SAMPLE), _eq5(eb, ea, np.ones(len(ea), bool), EQ5_SAMPLE)]
        cross_arr = np.array([c for c in cross if math.isfinite(c)])
        level = float(cross_arr.mean()) if len(cross_arr) else float("nan")
        # floor: Eq. 5 of the exemplar itself with 5 % positional noise (of s), which no
        # one sees; it keeps near-perfect exemplars, whose halves agree, from a zero tolerance
        jit = np.random.default_rng(0).normal(0.0, EQ5_JITTER * s, (len(ex_only), 2))
        noisy = ex_only.replace(x=ex_only.x + jit[:, 0], y=ex_only.y + jit[:, 1]) if len(ex_only) else ex_only
        floor = _eq5(ex_only, noisy, np.ones(len(noisy), bool), EQ5_SAMPLE)
        floor = floor if math.isfinite(floor) else 0.0
        tol = max(floor, EQ5_MULTIPLE * level) if math.isfinite(level) else float("nan")
        if math.isfinite(v) and math.isfinite(tol):
            metrics["eq5"] = MetricResult("eq5", v, tol, bool(v <= tol), v, 0.0, level)
        else:
            metrics["eq5"] = MetricResult("eq5", v, tol, True, applicable=False)

    order = sorted(metrics, key=lambda k: (_ORDER.index(_family(k)), list(disc).index(k) if k in disc else 0))
    metrics = {k: metrics[k] for k in order}
    failures = [k for k, m in metrics.items() if m.applicable and not m.passed]

    nb = int(round(R_MAX / BIN))
    r = (np.arange(nb) + 0.5) * BIN * s
    g_ex = {f"{kinds[i]},{kinds[j]}": ex_stats.g[i, j] for i in range(K) for j in range(i, K)}
    g_res = {f"{kinds[i]},{kinds[j]}": res_stats.g[i, j] for i in range(K) for j in range(i, K)}

    if local:
        noise = _window_noise(ex, ex_raw, ex_stats, kinds, s, ex_win, flags)
        local_map = _local_map(res, res_raw, ex_stats, metrics, kinds, s, ex_win, res_win, flags, noise)
    else:
        local_map = _empty_local()
    return FidelityReport(not failures, failures, metrics, kinds, s, r, g_ex, g_res, local_map, info)


_ORDER = ["fraction", "density", "g", "nn", "regularity", "orientation", "empty_circle", "eq5"]


def _side(st: _Stats, name: str, kinds: list[str]) -> float | None:
    fam = _family(name)
    if fam in ("fraction", "density"):
        k = name[name.index("[") + 1 : -1]
        idx = len(kinds) if k == "other" and k not in kinds else kinds.index(k)
        return float(st.fraction[idx]) if fam == "fraction" else float(st.density[idx])
    if fam == "regularity":
        return st.regularity
    if fam == "empty_circle":
        return st.q95
    if fam == "nn":
        a, b = name[3:-1].split(">")
        return float(st.nn[kinds.index(a), kinds.index(b)][4])  # the median
    return None


def _halves(win: shapely.Geometry) -> list[tuple[shapely.Geometry, shapely.Geometry]]:
    """Five splits of ``win`` into two parts of equal area.

    Left / right, low / high, a 2 x 2 checkerboard, and four vertical and four horizontal
    bands taken alternately; cuts sit at quantiles of the window's area.
    """
    x0, y0, x1, y1 = win.bounds
    big = 1.0 + (x1 - x0) + (y1 - y0)

    def cut(axis: int, share: float) -> float:
        lo, hi = (x0, x1) if axis == 0 else (y0, y1)
        total = win.area
        for _ in range(40):  # bisection on the area left of (below) the cut
            mid = 0.5 * (lo + hi)
            box = shapely.box(x0 - big, y0 - big, mid, y1 + big) if axis == 0 else shapely.box(x0 - big, y0 - big, x1 + big, mid)
            if shapely.intersection(win, box).area < share * total:
                lo = mid
            else:
                hi = mid
        return 0.5 * (lo + hi)

    xs = [x0 - big] + [cut(0, q) for q in (0.25, 0.5, 0.75)] + [x1 + big]
    ys = [y0 - big] + [cut(1, q) for q in (0.25, 0.5, 0.75)] + [y1 + big]

    def cells(pred: Any) -> tuple[shapely.Geometry, shapely.Geometry]:
        a, b = [], []
        for i in range(4):
            for j in range(4):
                (a if pred(i, j) else b).append(shapely.box(xs[i], ys[j], xs[i + 1], ys[j + 1]))
        return shapely.intersection(win, shapely.union_all(a)), shapely.intersection(win, shapely.union_all(b))

    return [
        cells(lambda i, j: i < 2),
        cells(lambda i, j: j < 2),
        cells(lambda i, j: (i < 2) == (j < 2)),
        cells(lambda i, j: i % 2 == 0),
        cells(lambda i, j: j % 2 == 0),
    ]


def _window_tolerance(m: MetricResult, area: float, ex_area: float, noise: float | None = None) -> float:
    """A local window's tolerance for metric ``m``.

    The global rule's noise term scaled to the window, ``sigma sqrt(1 + A_ex / A_w)``, or,
    when larger, the window-to-window noise measured in the exemplar itself (``noise``:
    variance x area of :func:`_window_noise`), ``sqrt(c / A_w + c / A_ex)``.
    """
    fam = _family(m.name)
    if fam == "eq5" or m.spread is None or not math.isfinite(m.spread):
        return m.tolerance
    area = max(area, 1e-300)
    tol = max(FLOORS[fam], MULTIPLE * m.spread / 2.0 * math.sqrt(1.0 + ex_area / area))
    if noise is not None and math.isfinite(noise) and noise > 0:
        tol = max(tol, MULTIPLE * math.sqrt(noise / area + noise / ex_area))
    return tol


def _window_discrepancies(st: _Stats, ex_stats: _Stats, kinds: list[str], s: float, flags: dict[str, bool]) -> dict[str, float]:
    """A window's discrepancies against the exemplar; ``empty_circle`` also compares the
    window's largest empty circle with the exemplar's largest."""
    d = _discrepancies(st, ex_stats, kinds, s, **flags)
    if math.isfinite(ex_stats.lec) and ex_stats.lec > 0 and math.isfinite(st.lec):
        d["empty_circle"] = max(d.get("empty_circle", 0.0) if math.isfinite(d.get("empty_circle", np.nan)) else 0.0, st.lec / ex_stats.lec - 1.0)
    return d


WINDOW_SUB = 0.5  # the exemplar's sub-windows for window noise: squares of this x its side
WINDOW_PHASES = 5  # ... at this many offsets along each axis
WINDOW_MIN = 6  # a metric needs this many sub-windows that measure it


def _window_noise(ex: _Sample, raw: _Raw, ex_stats: _Stats, kinds: list[str], s: float, ex_win: shapely.Geometry, flags: dict[str, bool]) -> dict[str, float]:
    """Window-to-window noise of each metric, measured in the exemplar itself.

    The half-splits of the global rule have equal areas but fixed places: the halves of an
    exemplar framed on whole periods of a lattice (one hub lattice of rings) agree almost
    exactly, while a window of the same area laid anywhere on a larger draw holds 3 to 5
    columns of hubs depending on its phase. So square sub-windows of side ``WINDOW_SUB``
    x the exemplar window's are laid at ``WINDOW_PHASES`` x ``WINDOW_PHASES`` offsets
    (every phase of the frame's content), and each one's discrepancy from the whole
    exemplar is measured as a result window's would be. With the conservative Poisson law
    (variance ∝ 1 / area, which a lattice's phase noise, ∝ perimeter / area, also follows)
    the mean square ``rms^2`` of nested sub-windows of area ``a`` in a window of area ``A``
    is ``c (1 / a - 1 / A)``; the constant ``c`` (variance x area) is returned per metric.

    Returns
    -------
    dict of str to float
        ``c`` per metric name; metrics that fewer than :data:`WINDOW_MIN` sub-windows
        measure are left out (the global rule's scaling applies to them alone).
    """
    x0, y0, x1, y1 = ex_win.bounds
    A = float(ex_win.area)
    side = WINDOW_SUB * math.sqrt(A)
    if A <= 0 or side <= 0 or x1 - x0 < side or y1 - y0 < side:
        return {}
    a = side * side
    cov = _set_covariance(shapely.box(0, 0, side, side), s / 6.0, R_MAX * s)
    shapely.prepare(ex_win)
    sq: dict[str, list[float]] = {}
    for j in range(WINDOW_PHASES):
        for i in range(WINDOW_PHASES):
            bx0 = x0 + (x1 - x0 - side) * i / max(WINDOW_PHASES - 1, 1)
            by0 = y0 + (y1 - y0 - side) * j / max(WINDOW_PHASES - 1, 1)
            bx = shapely.box(bx0, by0, bx0 + side, by0 + side)
            if not shapely.contains(ex_win, bx):
                continue
            st = _stats(ex, raw, len(kinds), s, bx, cov=cov)
            for name, v in _window_discrepancies(st, ex_stats, kinds, s, flags).items():
                if math.isfinite(v):
                    sq.setdefault(name, []).append(v * v)
    out: dict[str, float] = {}
    for name, vals in sq.items():
        if len(vals) >= WINDOW_MIN and A > a:
            out[name] = float(np.mean(vals)) / (1.0 / a - 1.0 / A)
    return out


def _empty_local() -> dict[str, Any]:
    return {"x0": None, "y0": None, "step": None, "window": None, "score": np.zeros((0, 0)), "worst_metric": np.zeros((0, 0), dtype=object), "worst": None}


def _local_map(res: _Sample, raw: _Raw, ex_stats: _Stats, metrics: dict[str, MetricResult], kinds: list[str], s: float, ex_win: shapely.Geometry, res_win: shapely.Geometry, flags: dict[str, bool], noise: dict[str, float] | None = None) -> dict[str, Any]:
    side = math.sqrt(ex_win.area)
    step = 0.5 * side
    x0, y0, x1, y1 = res_win.bounds
    cols = max(1, int(math.floor((x1 - x0 - side) / step)) + 1) if x1 - x0 >= side else 0
    rows = max(1, int(math.floor((y1 - y0 - side) / step)) + 1) if y1 - y0 >= side else 0
    score = np.full((rows, cols), np.nan)
    worst_metric = np.full((rows, cols), "", dtype=object)
    if rows * cols == 0:
        return {"x0": x0, "y0": y0, "step": step, "window": side, "score": score, "worst_metric": worst_metric, "worst": None}
    # the windows of the result interior share one lag grid when they are whole squares
    square_cov = _set_covariance(shapely.box(0, 0, side, side), s / 6.0, R_MAX * s)
    # a window is 2 x 2 cells of side ``step``: bucket elements, pairs, records and circles
    n = len(res.xy)
    inner = shapely.contains_xy(res_win, res.xy[:, 0], res.xy[:, 1]) if n else np.zeros(0, bool)

    def cell_of(pts: np.ndarray) -> np.ndarray:
        cx = np.floor((pts[:, 0] - x0) / step).astype(np.int64)
        cy = np.floor((pts[:, 1] - y0) / step).astype(np.int64)
        ok = (cx >= 0) & (cx <= cols) & (cy >= 0) & (cy <= rows)
        return np.where(ok, cy * (cols + 1) + cx, -1)

    ncell = (rows + 1) * (cols + 1)

    def buckets(cell: np.ndarray) -> list[np.ndarray]:
        order = np.argsort(cell, kind="stable")
        bounds = np.searchsorted(cell[order], np.arange(ncell + 1))
        return [order[bounds[k] : bounds[k + 1]] for k in range(ncell)]

    pcell = np.where(inner, cell_of(res.xy), -1)
    pb = buckets(pcell)
    pair_first = pcell[raw.pairs[:, 0]] if len(raw.pairs) else np.zeros(0, np.int64)
    prb = buckets(pair_first)
    rb = buckets(pcell[raw.orient_owner]) if len(raw.orient_owner) else [np.zeros(0, np.int64)] * ncell
    cin = shapely.contains_xy(res_win, raw.circ_c[:, 0], raw.circ_c[:, 1]) if len(raw.circ_r) else np.zeros(0, bool)
    cb = buckets(np.where(cin, cell_of(raw.circ_c), -1)) if len(raw.circ_r) else [np.zeros(0, np.int64)] * ncell
    worst: dict[str, Any] | None = None
    for r in range(rows):
        for c in range(cols):
            bx = shapely.box(x0 + c * step, y0 + r * step, x0 + c * step + side, y0 + r * step + side)
            cells = [(r + dr) * (cols + 1) + c + dc for dr in (0, 1) for dc in (0, 1)]
            whole = bool(shapely.contains(res_win, bx))
            w = bx if whole else shapely.intersection(res_win, bx)
            if w.is_empty or w.area < 0.5 * side * side:
                continue
            idx = np.concatenate([pb[k] for k in cells])
            member = np.zeros(n, bool)
            member[idx] = True
            pcand = np.concatenate([prb[k] for k in cells])
            pidx = pcand[member[raw.pairs[pcand, 1]]] if len(pcand) else pcand
            ridx = np.concatenate([rb[k] for k in cells])
            cidx = np.concatenate([cb[k] for k in cells])
            st = _stats(res, raw, len(kinds), s, w, cov=square_cov if whole else None, members=(np.sort(idx), pidx, ridx, cidx))
            d = _window_discrepancies(st, ex_stats, kinds, s, flags)
            best, which = 0.0, ""
            for name, v in d.items():
                m = metrics.get(name)
                if m is None or not m.applicable or not math.isfinite(v) or not (m.tolerance > 0):
                    continue
                # the window's own noise: scale the global tolerance's noise term to
                # sigma sqrt(1 + A_ex / A_window); floors stay as they are
                ratio = v / _window_tolerance(m, w.area, ex_win.area, (noise or {}).get(name))
                if ratio > best:
                    best, which = ratio, name
            score[r, c] = best
            worst_metric[r, c] = which
            if worst is None or best > worst["score"]:
                worst = {"row": r, "col": c, "bounds": list(bx.bounds), "score": best, "metric": which}
    return {"x0": x0, "y0": y0, "step": step, "window": side, "score": score, "worst_metric": worst_metric, "worst": worst}


# -- figures ----------------------------------------------------------------------------------


def _fill_of(shape: Any) -> str:
    style = getattr(shape, "style", {}) or {}
    fill = style.get("fill")
    return fill if isinstance(fill, str) and fill.startswith("#") else "#808080"


def draw_arrangement(ax: Any, arr: Arrangement, *, title: str = "") -> None:
    """Draw ``arr``'s visible elements (filled by their kind's colour) into a matplotlib axes."""
    from matplotlib.collections import PolyCollection

    vis = _visible(arr)
    sub = arr.select(vis)
    if len(sub):
        geoms = sub.geometry_of("area_geometry")
        fills = [_fill_of(sub.shapes[k]) for k in sub.kinds]
        colours = []
        polys = []
        for g, k in zip(geoms, sub.kind):
            if g is None or g.is_empty:
                continue
            parts = getattr(g, "geoms", [g])
            for p in parts:
                if hasattr(p, "exterior"):
                    polys.append(np.asarray(p.exterior.coords))
                    colours.append(fills[k])
        ax.add_collection(PolyCollection(polys, facecolors=colours, edgecolors="none"))
    reg = arr.region
    if reg is not None:
        for ring in getattr(reg.geometry, "geoms", [reg.geometry]):
            xy = np.asarray(ring.exterior.coords)
            ax.plot(xy[:, 0], xy[:, 1], color="#999999", lw=0.6)
    x0, y0, x1, y1 = reg.bounds if reg is not None else (arr.bounds if len(arr) else (0, 0, 1, 1))
    ax.set_xlim(x0, x1)
    ax.set_ylim(y1, y0)  # SVG's y-down
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    if title:
        ax.set_title(title, fontsize=8)


def draw_local_map(ax: Any, report: FidelityReport, result: Arrangement | None = None, *, title: str = "", colorbar: bool = True) -> None:
    """Draw the local fidelity map (window scores; above 1 fails) over the result."""
    if result is not None:
        draw_arrangement(ax, result)
    loc = report.local
    score = np.asarray(loc["score"], float)
    if score.size and loc["step"]:
        x0, y0, step, side = loc["x0"], loc["y0"], loc["step"], loc["window"]
        rows, cols = score.shape
        # each window's score drawn on its central cell (the windows overlap by half)
        extent = (x0 + 0.5 * step, x0 + 0.5 * step + cols * step, y0 + 0.5 * step + rows * step, y0 + 0.5 * step)
        im = ax.imshow(np.ma.masked_invalid(score), extent=extent, origin="upper", cmap="RdYlGn_r", vmin=0.0, vmax=2.0, alpha=0.55, interpolation="nearest")
        w = loc.get("worst")
        if w:
            b = w["bounds"]
            ax.plot([b[0], b[2], b[2], b[0], b[0]], [b[1], b[1], b[3], b[3], b[1]], color="#c00000", lw=1.2)
        if colorbar:
            ax.figure.colorbar(im, ax=ax, fraction=0.046, pad=0.02, label="window score (> 1 fails)")
        ax.set_ylim(max(ax.get_ylim()), min(ax.get_ylim()))
    ax.set_xticks([])
    ax.set_yticks([])
    ax.set_title(title or "local fidelity map", fontsize=8)


def plot_fidelity(exemplar: Arrangement, result: Arrangement, report: FidelityReport, path: Any, *, title: str = "") -> Any:
    """Write one PNG: the exemplar and the result side by side, g_ab(r) of both for each
    kind pair, and the local fidelity map. Returns the path (written atomically)."""
    import io as _io

    import matplotlib

    matplotlib.use("Agg", force=False)
    from matplotlib.figure import Figure

    from .io import atomic_write

    pairs = list(report.g_exemplar)
    shown = pairs[:6]
    fig = Figure(figsize=(12, 7.5), dpi=100)
    gs = fig.add_gridspec(2, max(3, len(shown)), height_ratios=[1.6, 1.0])
    top = max(3, len(shown))
    span = top // 3
    ax_e = fig.add_subplot(gs[0, 0:span])
    ax_r = fig.add_subplot(gs[0, span : 2 * span])
    ax_m = fig.add_subplot(gs[0, 2 * span : top])
    draw_arrangement(ax_e, exemplar, title=f"exemplar ({report.info.get('exemplar_visible', len(exemplar))} visible)")
    verdict = "faithful" if report.faithful else f"not faithful: {', '.join(report.failures[:4])}{' ...' if len(report.failures) > 4 else ''}"
    draw_arrangement(ax_r, result, title=f"result ({report.info.get('result_visible', len(result))} visible): {verdict}")
    draw_local_map(ax_m, report, result)
    for i, key in enumerate(shown):
        ax = fig.add_subplot(gs[1, i])
        ax.plot(report.r / report.s, report.g_exemplar[key], color="#444444", label="exemplar")
        ax.plot(report.r / report.s, report.g_result[key], color="#d62728", label="result")
        ax.axhline(1.0, color="#bbbbbb", lw=0.6)
        m = report.metrics.get(f"g[{key}]")
        flag = "" if m is None or not m.applicable else (" ok" if m.passed else " FAIL")
        ax.set_title(f"g[{key}]{flag}", fontsize=8)
        ax.set_xlabel("r / s", fontsize=7)
        ax.tick_params(labelsize=7)
        if i == 0:
            ax.legend(fontsize=7)
    if title:
        fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    buf = _io.BytesIO()
    fig.savefig(buf, format="png")
    return atomic_write(path, buf.getvalue())
