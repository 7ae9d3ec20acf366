"""Tiled synthesis of worlds too large for one process (issue 19).

A rectangular world ``[0, W] x [0, H]`` is cut into square tiles of side ``tile_size``.
Following Wei's parallel Poisson disk sampling (SIGGRAPH 2008; its phase groups), the
tiles are coloured in a 2 x 2 pattern: tile ``(i, j)`` has phase ``(j % 2) * 2 + i % 2``.
Two tiles of one phase are a whole tile apart, so they never share a border zone and
can run at once. A tile runs the method (any method of the contract in
:mod:`strew._method`) on its rectangle grown by ``halo`` (clipped to the world), with
the finished elements of its lower-phase neighbours near it as ``context``; it keeps the
elements whose centre lies in its own half-open rectangle ``[x0, x1) x [y0, y1)`` or in
a finished neighbour's (see :func:`run_tile`), and drops those in unfinished ones.

On a torus (``periodic=True``, issue 18) the grid wraps: its counts per axis are even,
so the 2 x 2 colouring holds across the edges, and a neighbour across an edge is seen
moved by +-W or +-H. :func:`periodic` makes a repeat tile this way with any method
that takes ``context``.

Departure from Wei: Wei runs the phases as global barriers (all of phase 0, then all
of phase 1, ...). Here a tile waits only for its (up to 8) lower-phase neighbours, a
task graph rather than barriers; the inputs of each tile are the same, so the result is
the same, and a slow tile holds back only its neighbours.

Each tile draws from ``SeedSequence(seed, spawn_key=(tile_index,))`` (the same as
``SeedSequence(seed).spawn(n)[tile_index]``): a tile's result depends only on the seed,
its index and its neighbours' results, so the world is byte-identical whatever the
number of workers or the order in which tiles finish.

Runners: :func:`world` runs in-process (``workers=1`` or dask missing) or on Dask
(``workers=N`` starts a ``dask.distributed.LocalCluster``; ``scheduler="tcp://..."``
uses an existing cluster). Dask and pyarrow come with ``pip install 'strew[distributed]'``.
"""

from __future__ import annotations

import math
import time
import uuid
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ._errors import InputError

__all__ = ["Tile", "plan", "plan_periodic", "world", "tiled", "periodic", "WorldInfo", "tile_rng", "border_band", "DISTRIBUTED_HINT"]

DISTRIBUTED_HINT = "pip install 'strew[distributed]'"

# methods whose result is a stationary texture that tiles (issue 19 point 1). None
# overlaps across borders. Border strips against the interior (benchmarks/worlds_strips.py,
# s the mean spacing, 95% tile-bootstrap intervals): pack's density 1.007x at +-1s on
# bars and discs and 1.003x on the demo's stones (its ramp hand-over, _ramp), but 1.07x on
# the demo's trees (benchmarks/pack_seam_trees.py); synth's 1.001x at +-2s, stones 1.007x
# (a band of whole texture handed over), stones 0.95x at +-3s; ornament's flowers 0.997x
# at +-2s, every kind within 4% there (leaves 0.96x; they were 0.54x, buds 1.28x), and
# willow 0.981x (10 worlds, tiles 102-138; 1.26x before its later tiles grew on from
# their finished neighbours' elements, _HANDS_ON, _keep_groups; 1.037x before they refilled
# the dropped room at its scale, _ornament_holes), stems 1.014x, and at +-1s 0.991x, stems
# 1.006x (1.044x and 0.966x before _at_parent); spirals 0.993x at +-2s and 0.987x at
# +-1s (6 worlds, tiles 102-122; 1.054x and 1.035x on tiles 102-138 before their
# successes were placed at and kept with the row drawing their parent spiral,
# strew.ornament._context.PARENT_COLUMN); hierarchy 1.008x at +-1s and 0.984x at +-2s (3
# worlds, tiles 104-116; 0.830x and 0.835x on tile 100 while a handed-over circle raised
# the rules of every phase, not only its own: strew.ornament._engine._Grower._holes_of_phase).
# dots 1.026x at +-1s and 1.022x at +-2s (3 worlds, tiles 130-138; 0.823x and 0.871x on
# tiles 104-116 while a raised dot, filling its raised goal circle, overlapped and failed:
# strew.ornament.patterns.dots.dot_to_dot now shrinks it to fit; benchmarks/dot19r_handover.py,
# dot19s_holes.py). synth uses its context as a
# neighbourhood, not only an obstacle; ornament's tiles
# give one kind name shapes that differ a little, but its elements carry their geometry in
# ``parts``, so the tiles' libraries are made to agree (_harmonize).
# On a torus (periodic=True) any method with context tiles.
# program (issue 19.1): the tiles of a script need nothing from each other, their
# partitions being fixed in the plane (strew.program._world)
TILED_METHODS = ("pack", "synth", "ornament", "program")


@dataclass(frozen=True)
class Tile:
    """One tile of a world.

    Attributes
    ----------
    index : int
        Row-major index ``j * nx + i``.
    i, j : int
        Column and row.
    rect : (4,) tuple of float
        ``(x0, y0, x1, y1)``; the tile owns the centres in ``[x0, x1) x [y0, y1)``
        (the world's last column and row also own their far edge).
    phase : int
        ``(j % 2) * 2 + i % 2``: tiles of one phase never share a border zone.
    """

    index: int
    i: int
    j: int
    rect: tuple[float, float, float, float]
    phase: int


def plan(size: tuple[float, float], tile_size: float) -> tuple[list[Tile], int, int]:
    """The tiles of a ``size = (W, H)`` world, row-major, and the grid ``(nx, ny)``.

    The last column and row are narrower when ``tile_size`` does not divide the size.
    """
    w, h = (float(size[0]), float(size[1]))
    if not (math.isfinite(w) and math.isfinite(h) and w > 0 and h > 0):
        raise InputError(f"size: must be positive, got {size!r}")
    t = float(tile_size)
    if not (math.isfinite(t) and t > 0):
        raise InputError(f"tile_size: must be positive, got {tile_size!r}")
    nx, ny = max(1, math.ceil(w / t - 1e-9)), max(1, math.ceil(h / t - 1e-9))
    tiles = []
    for j in range(ny):
        for i in range(nx):
            rect = (i * t, j * t, min(w, (i + 1) * t), min(h, (j + 1) * t))
            tiles.append(Tile(j * nx + i, i, j, rect, (j % 2) * 2 + i % 2))
    return tiles, nx, ny


def plan_periodic(size: tuple[float, float], tile_size: float | None = None) -> tuple[list[Tile], int, int]:
    """The tiles of a periodic ``size = (W, H)`` world (a torus), row-major, and ``(nx, ny)``.

    The counts per axis are even (at least 2), so that the 2 x 2 phase colouring holds
    across the wrap: ``nx = 2 round(W / 2T)`` (at least 2) and the tiles are the equal
    ``W / nx x H / ny`` rectangles nearest to ``tile_size`` [default: 2 x 2 tiles].
    """
    w, h = (float(size[0]), float(size[1]))
    if not (math.isfinite(w) and math.isfinite(h) and w > 0 and h > 0):
        raise InputError(f"size: must be positive, got {size!r}")
    if tile_size is None:
        nx = ny = 2
    else:
        t = float(tile_size)
        if not (math.isfinite(t) and t > 0):
            raise InputError(f"tile_size: must be positive, got {tile_size!r}")
        nx, ny = (max(2, 2 * round(v / (2 * t))) for v in (w, h))
    tw, th = w / nx, h / ny
    tiles = []
    for j in range(ny):
        for i in range(nx):
            x1 = w if i == nx - 1 else (i + 1) * tw
            y1 = h if j == ny - 1 else (j + 1) * th
            tiles.append(Tile(j * nx + i, i, j, (i * tw, j * th, x1, y1), (j % 2) * 2 + i % 2))
    return tiles, nx, ny


def tile_rng(seed: int, index: int) -> np.random.Generator:
    """The Generator of tile ``index``: ``SeedSequence(seed, spawn_key=(index,))``."""
    return np.random.Generator(np.random.PCG64(np.random.SeedSequence(int(seed), spawn_key=(int(index),))))


def _neighbours(t: Tile, nx: int, ny: int, periodic: bool = False) -> list[int]:
    """Indices of the lower-phase tiles among the 8 around ``t`` (its dependencies);
    on a torus (``periodic``) the grid wraps."""
    return sorted(_links(t, nx, ny, (float(nx), float(ny)) if periodic else None))


def _deps(job: _Job, t: Tile, nx: int, ny: int) -> list[int]:
    """The tiles ``t`` waits for: its lower-phase neighbours, none for program (its
    partitions' phases run inside each tile, strew.program._world)."""
    return [] if job.method == "program" else _neighbours(t, nx, ny, job.periodic)


def _links(t: Tile, nx: int, ny: int, torus: tuple[float, float] | None) -> dict[int, list[tuple[float, float]]]:
    """The lower-phase neighbours of ``t`` and the translations that carry their
    elements next to ``t``: ``{index: [(dx, dy), ...]}``.

    In a plane every translation is (0, 0). On a torus of size ``torus = (W, H)`` the
    grid wraps: a neighbour across the edge is moved by +-W or +-H, and with 2 tiles
    along an axis the tile on the left is also the one on the right (two translations).
    """
    out: dict[int, list[tuple[float, float]]] = {}
    for dj in (-1, 0, 1):
        for di in (-1, 0, 1):
            if not (di or dj):
                continue
            i, j = t.i + di, t.j + dj
            if torus is None:
                if not (0 <= i < nx and 0 <= j < ny):
                    continue
                shift = (0.0, 0.0)
            else:
                shift = ((i // nx) * torus[0], (j // ny) * torus[1])
                i, j = i % nx, j % ny
            if (j % 2) * 2 + i % 2 < t.phase:
                out.setdefault(j * nx + i, []).append(shift)
    return dict(sorted(out.items()))


def _grow(rect: tuple[float, float, float, float], d: float, size: tuple[float, float] | None) -> tuple[float, float, float, float]:
    """``rect`` grown by ``d``, clipped to the world ``[0, W] x [0, H]`` (not on a torus: ``size`` None)."""
    x0, y0, x1, y1 = rect
    if size is None:
        return (x0 - d, y0 - d, x1 + d, y1 + d)
    return (max(0.0, x0 - d), max(0.0, y0 - d), min(size[0], x1 + d), min(size[1], y1 + d))


def _owner(x: np.ndarray, y: np.ndarray, job: _Job) -> np.ndarray:
    """Index of the tile whose half-open rectangle holds each centre (the world's far
    edges closed; on a torus, of the centre wrapped into the world)."""
    w, h = job.size
    if job.periodic:
        x, y = np.mod(x, w), np.mod(y, h)
    i = np.clip(np.floor(x / job.tile[0]), 0, job.grid[0] - 1).astype(np.int64)
    j = np.clip(np.floor(y / job.tile[1]), 0, job.grid[1] - 1).astype(np.int64)
    return j * job.grid[0] + i


def border_band(arr: Any, t: Tile, halo: float) -> Any:
    """The elements of tile ``t``'s result that a neighbour can see: centres within
    ``2 halo`` of its rectangle's edges (the only part sent on to dependent tiles)."""
    x0, y0, x1, y1 = t.rect
    # 2 halo, and farther for an element whose bounding disc is wider than the halo: it
    # can reach a neighbour's region from deeper inside (see run_tile's context)
    d = 2 * halo + (_radii(arr) if len(arr) else 0.0)
    inner = (arr.x > x0 + d) & (arr.x < x1 - d) & (arr.y > y0 + d) & (arr.y < y1 - d)
    return arr.select(~inner)


def _near(arr: Any, rect: tuple[float, float, float, float]) -> np.ndarray:
    x0, y0, x1, y1 = rect
    return (arr.x >= x0) & (arr.x <= x1) & (arr.y >= y0) & (arr.y <= y1)


def _reaches(arr: Any, rect: tuple[float, float, float, float]) -> np.ndarray:
    """(n,) bool: the elements whose bounding disc meets the rectangle ``rect``."""
    x0, y0, x1, y1 = rect
    x, y = np.asarray(arr.x, float), np.asarray(arr.y, float)
    dx = np.maximum(np.maximum(x0 - x, x - x1), 0.0)
    dy = np.maximum(np.maximum(y0 - y, y - y1), 0.0)
    return dx * dx + dy * dy < _radii(arr) ** 2


@dataclass(frozen=True)
class _Job:
    """What every tile task needs (sent once to each worker)."""

    method: str
    input: Any
    params: dict[str, Any]
    size: tuple[float, float]
    halo: float
    seed: int
    tile: tuple[float, float] = (0.0, 0.0)  # tile width and height (the last column/row may be narrower)
    grid: tuple[int, int] = (1, 1)
    periodic: bool = False

    @property
    def torus(self) -> tuple[float, float] | None:
        return self.size if self.periodic else None


def run_tile(job: _Job, t: Tile, *neighbours: Any) -> Any:
    """Run one tile: the method on its grown rectangle around its finished neighbours.

    Parameters
    ----------
    job : _Job
    t : Tile
    *neighbours : Arrangement
        The border bands of :func:`_neighbours` (t), in index order.

    Returns
    -------
    Arrangement
        The new elements whose centre lies in ``t`` or in a finished (lower-phase)
        neighbour (pack: also a few just past a border with a later one, :func:`_ramp`); ``meta`` holds only ``{"tile": index}``. On a torus the positions are
        not wrapped (they stay next to ``t``, as its dependents expect them).

    Notes
    -----
    The keep-rule. A tile keeps what it placed in its finished neighbours' part of its
    grown rectangle, and drops only what lies in the unfinished ones (they fill it
    themselves, seeing this tile's elements). Keeping only the centres in ``t`` left a
    thin empty seam: the gaps of a finished tile's edge were filled by elements centred
    on its side, which were then dropped (pack, 150 x 120 world, tiles 30: centres
    within 1 unit of a border at 0.81x the interior's density). An element kept in a
    neighbour's rectangle lies in ``t``'s grown rectangle, so every later tile that can
    touch it is a neighbour of ``t`` and sees it in ``t``'s border band.

    Two methods change the rule at borders with a later tile: synth keeps the elements
    whose disc reaches into a band of one element diameter about ``t`` (a whole band of
    texture, see ``_GROWS_FROM_CONTEXT``), and pack thins its elements within a halo of a
    later tile at random, the more the nearer and the smaller (:func:`_ramp`), so that the
    later tile refills scattered holes instead of packing against a flat front; it hands
    the dropped elements on in ``meta["holes"]``, and the later tile keeps on its side
    only what it placed in those holes (:func:`_in_holes`). synth hands on its dropped
    medium and large elements near ``t`` in ``meta["synth_holes"]``, and the later tile seeds a copy
    at each (``_SYNTH_HOLES_LARGE``).
    """
    from ._method import spec
    from .arrangement import concat
    from .region import Region

    if job.method == "program":
        from .program._world import run_tile as program_tile

        return program_tile(job, t)
    fn = spec(job.method).function()
    torus = job.torus
    grown = _grow(t.rect, _reach(job), None if torus else job.size)
    if grown[0] or grown[1]:
        import shapely

        region = Region(shapely.box(*grown))
    else:
        region = Region.rectangle(grown[2] - grown[0], grown[3] - grown[1])
    links = _links(t, job.grid[0], job.grid[1], torus)
    # every finished element that can touch the grown rectangle: centre within 2 halo,
    # and any element whose bounding disc meets it (wider than the halo, as ornament's
    # quarter-tile halo allows on small tiles: hierarchy at tile 24 overlapped a leaf whose
    # centre lay 2.1 halo away); across the wrap, moved next to t
    window = _grow(t.rect, 2 * job.halo, None if torus else job.size)
    parts = []
    for n, shifts in zip(neighbours, links.values()):
        if not len(n):
            continue
        for dx, dy in shifts:
            m = n.replace(x=n.x + dx, y=n.y + dy) if (dx or dy) else n
            parts.append(m.select(_near(m, window) | _reaches(m, grown)))
    parts = [p for p in parts if len(p)]
    context = concat(_harmonize(parts)) if parts else None
    # one element diameter, at most the halo (how far the tile's region reaches past it)
    band = min(2.0 * _input_extent(job), job.halo) if job.method in _GROWS_FROM_CONTEXT else 0.0
    if context is not None and job.method in _KEEPS_GROUPS:
        # ornament: the circles its finished neighbours' dropped successes grew into on
        # their side; the later tile refills them at that scale (_ornament_holes)
        context = context.with_meta(ornament_holes=_holes_in(neighbours, links, "ornament_holes"))
    if context is not None and job.method in _GROWS_FROM_CONTEXT:
        region = _outside_finished(region, t, job, links, band)
        context = context.with_meta(synth_holes=_synth_holes_in(neighbours, links))
    synth_kw = {"_balance_drop": _synth_drop(region, t, job, band)} if job.method == "synth" else {}
    if job.method == "ornament" and _keeps_first_phase(job) is not None:
        # the halo's edges that face a later tile stop no circle (_open_edges)
        synth_kw = {"_open": [e + [_OPEN_REACH * job.halo] for e in _open_edges(t, job, grown)]}
    params = job.params
    cells = _ornament_cells(job, grown)
    if cells is not None:  # the world's raster cell (_ornament_cells)
        params = {k: v for k, v in params.items() if k not in ("cells", "resolution")}
        synth_kw = {**synth_kw, "cells": cells}
    arr = fn(job.input, region, context=context, rng=tile_rng(job.seed, t.index), **_HANDS_ON.get(job.method, ({},))[0], **synth_kw, **params)
    owner = _owner(arr.x, arr.y, job)
    keep = (owner == t.index) | np.isin(owner, np.fromiter(links, np.int64, len(links)))
    if job.method in _GROWS_FROM_CONTEXT and len(arr):
        # the elements whose disc reaches into the band of one element diameter about
        # t's rectangle (see _GROWS_FROM_CONTEXT); an element kept there touches only
        # tiles within 1.5 diameters of t, which see it in t's border band
        keep |= _within(arr, t.rect, band + _radii(arr))
    meta: dict[str, Any] = {"tile": t.index}
    if job.method in _GROWS_FROM_CONTEXT and len(arr):
        meta["synth_holes"] = _synth_holes_out(arr, keep, t.rect, band)
    if job.method in _HANDS_OVER_BY_RAMP and len(arr):
        later = ~keep  # centred in a later tile, which refills its side
        theirs = keep & (owner != t.index)  # on a finished neighbour's side
        keep[theirs] = _in_holes(arr.select(theirs), neighbours, links, context)
        ramp = _ramp(arr, t, job)  # in a later tile: the few kept just past the border
        meta["holes"] = _hole_discs(arr, (later | keep) & ~ramp).tolist()  # a list: meta compares with ==
        keep = (keep | later) & ramp
    keep = _keep_groups(arr, keep, t, job, links)
    if job.method in _KEEPS_GROUPS and len(arr):
        meta["ornament_holes"] = _ornament_holes(arr, keep, job, t.rect)
    arr = _own_parts(arr.select(keep))
    return arr.replace(meta=meta, region=None)


# methods that grow the texture on from the context (synth: region growing, §5.4). A
# tile keeps also its elements on an unfinished neighbour's side whose disc reaches into
# the band of one element diameter D (the exemplar's largest, _input_extent) about its
# rectangle, so that the texture in that band is whole as the tile made it; the later
# tile's region leaves out its finished neighbours' rectangles grown by D
# (_outside_finished) and grows on from that band's outer edge. The band was cut by
# centres before (centres within D kept; the later tile's region only less the finished
# rectangles): the stones cut off left stone-shaped hollows in the kept band that only a
# stone placed just there refills, the later tile filled them and the band's gaps with
# pebbles, and a frozen context cannot yield to a larger element as the growing front
# does (_grow._split_conflicts). python benchmarks/worlds_strips.py --methods synth
# --widths 3,2,1 [--synth-exemplar three_sizes] (2640 x 2640, tiles 440, seeds 1,2),
# before -> after: two_sizes strips +-2s density 1.050x -> 1.001x, stones 0.910x ->
# 1.007x (+-1s 1.021x -> 1.000x, stones 0.978x); three_sizes +-2s 1.061x -> 1.004x,
# large 0.906x -> 1.005x, medium 0.964x -> 0.992x; folded profile chi2/dof 1.95 -> 0.75
# and 1.94 -> 0.96. What is left: at the outer edge of the band's largest elements
# (2.5-3 s into the later tile) the large kinds are still short (+-3s: stones 0.897x ->
# 0.953x, large 0.882x -> 0.959x, density 1.057x -> 1.014x and 1.050x -> 1.010x): the
# later tile still meets a frozen edge there, only a smoother one.
# pack fills gaps by design and keeps its neighbours' strip instead
_GROWS_FROM_CONTEXT = ("synth",)


# synth's hand-over of its dropped large elements (helper holes19e): the later tile's
# small elements filled the places of the finished tile's dropped large ones just past
# the kept band before a large one landed there (two_sizes, +-3s strips: stones 0.962x,
# three_sizes large 0.956x). The finished tile hands over the discs of its dropped
# elements of at least half its largest bounding radius, centred within two bands of
# its rectangle (meta["synth_holes"]); the later tile puts a copy of each one's kind at
# its centre before growing (strew.synth._context.add_holes).
# python benchmarks/synth_front_profile.py [--exemplar three_sizes] --seeds 1,2,3,4
# (the same as --variant holes:1 on the code before), before -> after: two_sizes +-3s
# stones 0.945x -> 1.007x, density 1.013x -> 0.993x; three_sizes +-1s large 0.961x ->
# 0.992x, +-3s large 0.953x -> 0.995x, medium 0.966x -> 0.980x, small 1.026x -> 1.010x.
# Left: the total density 2.5 s into the later tile (two_sizes 0.93x of the far bins,
# before 1.02x; its stones 0.75x -> 1.06x there), the copies being larger than pebbles.
# The cut was then lowered from 0.5 to 0.35 (helper synth19f) so that the medium elements
# are handed over too (three_sizes: small 2.6-3.2, medium 5.3-6.5, large 10.4-12.5; the
# cut falls between small and medium with room either side; two_sizes' pebbles, at most
# 4.6 against stones of 12.2-14.5, stay out, so its worlds are unchanged): the later
# tile's growth from the front left the medium elements short 2-4.5 s in (0.82-0.92x of
# the far bins) and put large ones in their places (3-3.5 s: 1.14-1.41x); the later tile
# adds the copies larger kinds first (strew.synth._context.add_holes). python
# benchmarks/worlds_strips.py --methods synth --synth-exemplar three_sizes --widths 3,2,1
# --seeds 1,2,3,4 --no-control --no-fidelity, e1d86dd -> now, large share +-3s 0.973
# [0.953, 0.994] -> 0.988 [0.967, 1.009], +-2s 0.975 [0.951, 1.001] -> 0.994 [0.971,
# 1.018], +-1s 0.975 [0.931, 1.017] -> 0.996 [0.952, 1.037]; medium +-3s 0.994 -> 1.013
# [0.996, 1.031]. Seeds 1-8: large +-3s 0.984 [0.969, 0.999] -> 0.994 [0.980, 1.009],
# +-2s 0.976 [0.957, 0.994] -> 0.990 [0.970, 1.008], +-1s 0.990 [0.959, 1.021] -> 0.995
# [0.966, 1.022]; medium +-3s 0.985 -> 1.008, +-2s 1.001 -> 0.984 [0.970, 0.999], +-1s
# 0.994 -> 0.979 [0.960, 1.000]. Left: medium 1.17-1.29x and large 0.87x 2.5-3.5 s in,
# large 0.71x at 3.5-4 s (the copies reach 3.6 s).
_SYNTH_HOLES_LARGE = 0.35  # of the tile's largest bounding radius
_SYNTH_HOLES_REACH = 2.0  # bands from the rectangle


def _synth_holes_out(arr: Any, keep: np.ndarray, rect: tuple[float, float, float, float], band: float) -> list[list[Any]]:
    """synth: ``[x, y, r, kind name]`` of the large elements ``keep`` drops near ``rect``
    (see ``_SYNTH_HOLES_LARGE``); a list: meta compares with ==."""
    r = _radii(arr)
    drop = ~keep & (r >= _SYNTH_HOLES_LARGE * float(r.max())) & _within(arr, rect, _SYNTH_HOLES_REACH * band)
    names = np.asarray(arr.kinds, dtype=object)[np.asarray(arr.kind, np.int64)]
    return [[float(arr.x[i]), float(arr.y[i]), float(r[i]), str(names[i])] for i in np.flatnonzero(drop)]


def _holes_in(neighbours: tuple[Any, ...], links: Mapping[int, list[tuple[float, float]]], key: str) -> list[list[Any]]:
    """The finished neighbours' ``meta[key]`` circles ``[x, y, r(, phase)]``, moved next to the tile across the wrap."""
    return [[x + dx, y + dy, *rest] for n, shifts in zip(neighbours, links.values())
            for dx, dy in shifts for x, y, *rest in n.meta.get(key, ())]


def _ornament_holes(arr: Any, keep: np.ndarray, job: _Job, rect: tuple[float, float, float, float]) -> list[list[Any]]:
    """ornament: the empty circles ``[x, y, r]``, centred in ``rect`` (the tile's own),
    that the rule successes it drops and places at their parent (_at_parent: willow's)
    grew into (see _handed_over in strew.ornament._engine); ``[x, y, r, phase]`` for a
    success grown in a named phase (hierarchy's): the later tile raises only the rules of
    that phase by it (strew.ornament._engine._Grower._holes_of_phase).

    A later tile raises the scale of a circle it grows into to the largest of these that
    holds its centre. Only those centred on this tile's side: with all the dropped
    successes' circles (those past the border too, grown into the empty halo of this
    tile's region) the later tile's own room grew at their scale as well, and the strips
    thinned (tile 100, seed 1: +-2 s density 0.919x, the later side's bins 0.73-0.98x).
    Only successes placed at their parent: flowers' successes, each with a stem that
    parents no rule, hand nothing over, and their worlds stay as they were. Nor spirals
    (a success drawn as one row of several elements; see below).
    """
    from .ornament._context import GOAL_COLUMN, PROXIES_COLUMN, parent_rows

    col = _KEEPS_GROUPS[job.method]
    if GOAL_COLUMN not in arr.columns or PROXIES_COLUMN not in arr.columns or keep.all():
        return []
    _, inv = np.unique(np.asarray(arr[col]), return_inverse=True)
    rows = ~keep & (_at_parent(arr, inv, parent_rows(job.input, arr[PROXIES_COLUMN])) >= 0)[inv]
    # nor a success drawn as one row of several elements (Pattern.group: a spiral, its
    # arms): it fills its circle about the circle's centre (0.8 of its radius), and a
    # refill raised to the dropped circle about its own, other centre rarely fits and
    # fails. Placed at their parent (PARENT_COLUMN), spirals handing over: tile 100, seed
    # 1, +-1 s density 0.915x, +-2 s 0.928x; handing nothing over 0.997x, 0.957x (1.023x,
    # 1.046x before; benchmarks/spi19p_parents.py, orn19m_willow.py analyze)
    rows &= np.array([len(r) == 1 for r in arr[PROXIES_COLUMN]], bool)
    if not rows.any():
        return []
    g = np.array([tuple(v) if v is not None else (np.nan,) * 3 for v in np.asarray(arr[GOAL_COLUMN], dtype=object)[rows]], float).reshape(-1, 3)
    ph = np.asarray(arr["phase"], dtype=object)[rows] if "phase" in arr.columns else np.full(int(rows.sum()), None, object)
    ok = np.isfinite(g).all(axis=1)
    x0, y0, x1, y1 = rect
    # only those on the tile's own side: a later tile grows its own room at its own scale
    ok &= (g[:, 0] >= x0) & (g[:, 0] < x1) & (g[:, 1] >= y0) & (g[:, 1] < y1)
    out = sorted({(float(a), float(b), float(c), str(p) if p else None) for (a, b, c), p in zip(g[ok].tolist(), ph[ok].tolist())},
                 key=lambda v: (v[0], v[1], v[2], "" if v[3] is None else v[3]))
    # (x, y, r) where no phase: the meta as it was
    return [list(v) if v[3] is not None else list(v[:3]) for v in out]


def _synth_holes_in(neighbours: tuple[Any, ...], links: Mapping[int, list[tuple[float, float]]]) -> list[list[Any]]:
    """synth: the finished neighbours' ``meta["synth_holes"]``, moved next to the tile across the wrap."""
    return [[x + dx, y + dy, r, k] for n, shifts in zip(neighbours, links.values())
            for dx, dy in shifts for x, y, r, k in n.meta.get("synth_holes", ())]


def _synth_drop(region: Any, t: Tile, job: _Job, band: float) -> Any:
    """synth: the part of ``region`` whose elements the tile drops (in its later
    neighbours' rectangles, beyond the band about ``t``; see ``run_tile``), a prepared
    shapely geometry, or None (no later neighbour). Passed to ``synthesize``
    (``_balance_drop``) for its balance rule (``strew.synth._grow.BALANCE_TILE``)."""
    import shapely

    later = _later_rects(t, job)
    if not later:
        return None
    ahead = shapely.intersection(region.geometry, shapely.union_all([shapely.box(*r) for r in later]))
    drop = shapely.difference(ahead, shapely.box(*_grow(t.rect, band, None)))
    if drop.is_empty or drop.area <= 0:
        return None
    shapely.prepare(drop)
    return drop


def _extent(arr: Any) -> float:
    """The largest bounding radius (shape radius x scale) of ``arr``'s elements."""
    return float(np.max(_radii(arr)))


def _radii(arr: Any) -> np.ndarray:
    """(n,) float: each element's bounding radius (shape radius x largest |scale|)."""
    radii = np.array([float(arr.shapes[k].radius) for k in arr.kinds])
    scale = np.max(np.abs(np.asarray(arr.scale, float).reshape(len(arr), -1)), axis=1)
    return radii[np.asarray(arr.kind, np.int64)] * scale


def _input_extent(job: _Job) -> float:
    """synth: the largest bounding radius of the selected exemplars' elements (an output
    element copies its exemplar element's shape and scale), the same for every tile."""
    from .synth._api import as_selection

    return max((_extent(a) for a in as_selection(job.input, job.params.get("selection")).exemplars() if len(a)), default=0.0)


def _within(arr: Any, rect: tuple[float, float, float, float], d: float) -> np.ndarray:
    """(n,) bool: centres within ``d`` of ``rect`` (in the box ``rect`` grown by ``d``)."""
    x0, y0, x1, y1 = rect
    return (arr.x >= x0 - d) & (arr.x <= x1 + d) & (arr.y >= y0 - d) & (arr.y <= y1 + d)


def _outside_finished(region: Any, t: Tile, job: _Job, links: Mapping[int, list[tuple[float, float]]], band: float = 0.0) -> Any:
    """``region`` less the finished neighbours' rectangles grown by ``band`` (the band
    about them whose texture they kept whole, see ``_GROWS_FROM_CONTEXT``).

    synth fills any gap it can (§5.4's filler grows wherever a candidate fits): run on
    the whole grown rectangle, a tile filled the gaps of its finished neighbours'
    interiors with small elements and kept them there (two_sizes, 880 x 880 in tiles of
    220, seed 2: 156 kept elements, all pebbles, median 8.5 from the border, up to 35;
    border strips 1.24x the interior's density, pebbles 1.43x, stones 0.63x; 1.01x
    without them). A band of one element extent into the finished rectangles (to fill
    the gaps a neighbour left where it dropped its elements) still gave 1.155x (seeds
    3-5): pebbles filled the interstices of the finished edge; without it 1.075x. The
    finished tile keeps its elements that cross onto ``t``'s side instead (run_tile).
    """
    import shapely

    from .region import Region

    w, h = job.size
    tw, th = job.tile
    nx = job.grid[0]
    boxes = []
    for n, shifts in links.items():
        i, j = n % nx, n // nx
        x1 = w if i == nx - 1 else (i + 1) * tw
        y1 = h if j == job.grid[1] - 1 else (j + 1) * th
        for dx, dy in shifts:
            boxes.append(shapely.box(i * tw + dx - band, j * th + dy - band, x1 + dx + band, y1 + dy + band))
    if not boxes:
        return region
    rest = shapely.difference(region.geometry, shapely.union_all(boxes))
    polys = [g for g in shapely.get_parts(rest) if isinstance(g, shapely.Polygon) and g.area > 0]
    if not polys:
        # a tile narrower than the bands: less the rectangles alone
        return _outside_finished(region, t, job, links) if band else region
    return Region(shapely.MultiPolygon(polys) if len(polys) != 1 else polys[0])


def _own_parts(arr: Any) -> Any:
    """``arr`` with every element's geometry in its ``parts`` when it has that column
    (ornament): the elements that draw their kind's shape get it as their one part."""
    from .arrangement import PARTS_COLUMN

    parts = arr.element_parts
    if parts is None or all(p is not None for p in parts):
        return arr
    names = arr.kinds
    col = [list(p) if p is not None else [arr.shapes[names[k]]] for p, k in zip(parts, arr.kind)]
    return arr.with_columns(**{PARTS_COLUMN: col})


def _harmonize(arrs: list[Any]) -> list[Any]:
    """Arrangements whose shape libraries agree, so that they concatenate.

    Tiles of ornament give one kind name shapes that differ a little (each run builds
    its own), but every element carries its geometry in ``parts``: where a later input
    names a kind's shape differently and all its elements of that kind have parts, the
    first input's shape is taken (drawing and overlaps read the parts). A kind without
    parts that differs is left for concat to refuse.
    """
    ref: dict[str, Any] = {}
    out = []
    for a in arrs:
        lib = dict(a.shapes)
        parts = a.element_parts
        for k, sh in a.shapes.items():
            if k not in ref:
                ref[k] = sh
            elif ref[k] != sh and parts is not None:
                idx = np.flatnonzero(a.kind == a.kinds.index(k))
                if all(parts[i] is not None for i in idx):
                    lib[k] = ref[k]
        out.append(a.replace(shapes=lib) if lib != a.shapes else a)
    return out


# methods whose tiles hand later tiles more than their drawn elements: the keyword that
# asks the method for it, and the private columns that carry it (dropped before a tile
# reaches the sink, _public). ornament: each element's proxies, so that a later tile grows
# on from its finished neighbours' elements as parents (Wong et al. §4.1: one run grows
# the whole panel) instead of meeting them as the panel's edge (strew.ornament._context)
_HANDS_ON: dict[str, tuple[dict[str, Any], tuple[str, ...]]] = {
    "ornament": ({"_tiled": True}, ("ornament_proxies", "ornament_group", "ornament_goal", "ornament_parent")),
}

# methods whose elements come in groups kept or dropped whole, by the mean of the group's
# centres (_keep_groups): the column naming each element's group
_KEEPS_GROUPS = {"ornament": "ornament_group"}


def _keep_groups(arr: Any, keep: np.ndarray, t: Tile, job: _Job, links: Mapping[int, Any]) -> np.ndarray:
    """(n,) bool: for methods of :data:`_KEEPS_GROUPS`, the keep-rule of :func:`run_tile`
    applied to each group's mean centre, for all its elements, and a group kept only with
    its parent's (strew.ornament._context.keep_whole); ``keep`` itself for the others."""
    col = _KEEPS_GROUPS.get(job.method)
    if col is None or col not in arr.columns or not len(arr):
        return keep
    from .ornament._context import GOAL_COLUMN, PROXIES_COLUMN, anchor_rows, cut_touching, keep_ancestors, keep_whole, late_phase, parent_rows

    _, inv = np.unique(np.asarray(arr[col]), return_inverse=True)
    w = np.ones(len(arr))
    x, y = np.asarray(arr.x, float), np.asarray(arr.y, float)
    tips = anchored = None
    if _GROUP_AT == "parents" and PROXIES_COLUMN in arr.columns:
        # a success's growing tip: the mean of its rows of a type some rule grows from
        # (parent_rows), all rows where a success has none
        tips = parent_rows(job.input, arr[PROXIES_COLUMN])
        w = np.where(np.bincount(inv, weights=tips)[inv] > 0, tips.astype(float), 1.0)
    cnt = np.bincount(inv, weights=w)
    mx = np.bincount(inv, weights=w * x) / cnt
    my = np.bincount(inv, weights=w * y) / cnt
    if tips is not None:
        # a success whose every row is a tip (willow) is placed where it grows from: its
        # parent's centre, where the tile drew its parent (_at_parent)
        at = _at_parent(arr, inv, tips)
        mx, my = np.where(at >= 0, x[np.maximum(at, 0)], mx), np.where(at >= 0, y[np.maximum(at, 0)], my)
        # a success holding a row of the pattern's tile anchors (the vase's flowers, on a
        # grid fixed in the world) is placed at those rows (anchor_rows)
        anchors = anchor_rows(job.input, arr[PROXIES_COLUMN]).astype(float)
        na = np.bincount(inv, weights=anchors, minlength=len(mx))
        if na.any():
            has = anchored = na > 0
            mx = np.where(has, np.bincount(inv, weights=anchors * x, minlength=len(mx)) / np.maximum(na, 1), mx)
            my = np.where(has, np.bincount(inv, weights=anchors * y, minlength=len(my)) / np.maximum(na, 1), my)
    o = _owner(mx, my, job)
    ok = (o == t.index) | np.isin(o, np.fromiter(links, np.int64, len(links)))

    placed = ok[inv]
    later = _later_rects(t, job)
    band = _LATE_BAND * job.halo
    # each element's distance to the nearest later tile
    d = np.full(len(arr), np.inf)
    for x0, y0, x1, y1 in later:
        d = np.minimum(d, np.hypot(np.maximum(np.maximum(x0 - x, x - x1), 0.0), np.maximum(np.maximum(y0 - y, y - y1), 0.0)))
    # the rows of the phases after the first that a pattern keeping its first phase keeps
    # up to the border too (_held_phase_rows: hierarchy's flowers)
    held = _held_phase_rows(arr, job) if later else None
    if held is not None:
        # only a success whose every row lies outside every later tile: the rows centred
        # in a later tile are its own (as every later phase's there)
        held &= ~np.bincount(inv, weights=(d <= 0.0), minlength=len(mx)).astype(bool)[inv]
    if later and band > 0:
        # the later phases' elements (flowers' buds) near a later tile are left to it
        late = late_phase(job.input, arr["phase"])
        if held is not None:
            late &= ~held
        placed &= ~((d < band) & late)
    first = _first_phase_depth(arr, t, job) if later else None
    first_rows = _first_phase_rows(first, job) if first is not None else None
    if first_rows is not None and anchored is not None and _FIRST_ANCHORED:
        # a success placed at its tile anchors (the vase's flowers, on the world's grid) is
        # the anchor's owner's, kept first phase or not: the tile holding the grid point
        # delivers its flower (anchor_rows)
        first_rows &= ~anchored[inv] | ok[inv]
    if first_rows is not None:
        placed |= first_rows
    beyond = None
    if _FIRST_BEYOND and first is not None and not _has_tile_anchors(job):
        # the first phase's rows deeper in a later tile (_first_phase_beyond)
        beyond = _first_phase_beyond(first, job) & (d <= 0.0)
    parent = _parent_rows(arr)
    if later:
        # a success this tile keeps by its own rows is not dropped for a dropped ancestor's
        # sake where one of its rows lies beyond every later tile's region (keep_ancestors)
        far = d >= _CUT_REACH * job.halo
        if first_rows is not None:
            # and, for a pattern that keeps its first phase, where it is one of those
            # (_first_phase_rows): a vine does not go for its parent's sake
            far = far | first_rows
        barred = None
        if not _ANCHORED_KEEP_LATE_IN_LATER and _has_tile_anchors(job):
            # a pattern with tile anchors (the vase's grid flowers) keeps no later phase's
            # ancestor inside a later tile over a grid point: there it covered grid points
            # whose flowers that tile had yet to deliver (keep_ancestors)
            barred = (d <= 0.0) & late_phase(job.input, arr["phase"])
            if _ANCHORED_BAR == "grid" and PROXIES_COLUMN in arr.columns:
                # only those over a grid point, where the later tile delivers a flower
                from .ornament._context import covers_anchor_grid

                barred &= covers_anchor_grid(job.input, arr[PROXIES_COLUMN], barred)
        kept_placed = keep_ancestors(arr["element"], parent, arr[col], placed, far, barred)
        if beyond is not None and beyond.any():
            # one by one, a vine deeper than half a halo in a later tile goes to it (placed
            # at its parent, _at_parent, or a kept vine's ancestor, keep_ancestors), unless
            # a row lost with it lies past the later tile's reach (a hole no tile refills;
            # _first_phase_beyond)
            kept = keep_whole(arr["element"], parent, arr[col], kept_placed)
            bar = np.zeros(len(arr), bool)
            for g in np.unique(inv[beyond & kept]):
                b2 = bar | (beyond & (inv == g))
                p2 = keep_ancestors(arr["element"], parent, arr[col], placed & ~b2, far, b2)
                k2 = keep_whole(arr["element"], parent, arr[col], p2)
                if (d[kept & ~k2] < _CUT_REACH * job.halo).all():
                    bar, kept_placed, kept = b2, p2, k2
        placed = kept_placed
    kept = keep_whole(arr["element"], parent, arr[col], placed)
    if later and GOAL_COLUMN in arr.columns and PROXIES_COLUMN in arr.columns:
        # the successes whose empty circle an element dropped here had bounded are left to
        # the later tile too (_CUT_ROUNDS rounds: more rounds hand over more, and the
        # later tile's refill then reaches too deep into this one)
        near = d < _CUT_BAND * job.halo  # within the later tile's reach, so that it refills them
        reach = _CUT_REACH * job.halo  # a success goes with its descendants (keep_whole)
        for _ in range(_CUT_ROUNDS):
            more = near & cut_touching(job.input, arr[PROXIES_COLUMN], arr[col], arr[GOAL_COLUMN], kept)
            if first_rows is not None:
                more &= ~first_rows  # the kept first phase stays whole (_first_phase_rows)
            if held is not None:
                more &= ~held  # and so do the phases held with it (_held_phase_rows)
            if not more.any():
                break
            trial = placed & ~np.isin(inv, inv[more])  # whole successes
            k2 = keep_whole(arr["element"], parent, arr[col], trial)
            if not (d[kept & ~k2] < reach).all():
                # one by one, leaving those whose descendants reach past the later tile's
                # reach (a hole no tile refills)
                trial, k2 = placed, kept
                for g in np.unique(inv[more]):
                    t2 = trial & (inv != g)
                    k3 = keep_whole(arr["element"], parent, arr[col], t2)
                    if (d[k2 & ~k3] < reach).all():
                        trial, k2 = t2, k3
                if np.array_equal(k2, kept):
                    break
            placed, kept = trial, k2
    return kept


# where _keep_groups places a rule success: "parents", its growing tip (the mean of the
# rows strew.ornament._context.parent_rows names), or its parent's centre where every
# row is a tip (_at_parent); "mean", the mean of all its rows' centres (the rule up to
# 3e74fcd)
_GROUP_AT = "parents"


def _at_parent(arr: Any, inv: np.ndarray, tips: np.ndarray) -> np.ndarray:
    """(groups,) int: for each rule success (``inv``: each row's group) whose every row
    is a tip (``tips``, strew.ornament._context.parent_rows) the row of its parent
    element, where the tile drew it; -1 for the others (placed by their tip's mean).

    Why (issue 19.4, willow): every willow type parents a rule (a stem branches anywhere
    along a stem and from a leaf's tip), so the tip is the whole success, a stem of up
    to 28 units with its leaves. By its rows' mean, a success that grew from the
    finished side across the border was dropped, and with it (keep_whole) every success
    grown from it, back into the finished side too: the finished tile kept 11 % of its
    rows within 3 units of a later tile and 25-45 % within 12 (tile 100, seed 1), and the
    later tile refilled the rest. A refill grows into the narrow holes of the cut, the
    scale of a rule's elements following its empty circle (Wong et al. §5: the pattern
    "simplifies as it wanders into narrower spaces"): refilled stems 8.5 units long on
    average against 10.5 in the interior, 4 % over 20 units against 13 % (seed 1, tiles
    100, 112, 124), and the strips were denser than the interior (+-1 s 1.050, +-2 s
    1.046) and short of stems (+-1 s 0.971). Placed at its parent, a success growing out
    of the finished side is kept (the later tile grows around it as around the rest of
    its context), and one grown from a row past the border goes to the later tile: the
    refilled stems fell from 944 to 631, +-1 s 1.012, stems 0.999; +-2 s 1.022
    (python benchmarks/orn19m_willow.py make/analyze, the same three worlds). A success
    with rows that parent no rule (flowers' stem and leaf) keeps its tip's mean
    (parent_rows' docstring); a seed's success (its parent not drawn) too. The parent is
    the row drawing it (_parent_rows): a spiral grows from an arm inside its parent
    spiral's row. Departure
    from the paper: Wong et al. grow one panel in one run (§4.1); this hand-over between
    runs is ours.
    """
    ng = int(inv.max()) + 1 if len(inv) else 0
    every = np.bincount(inv, weights=np.asarray(tips, float), minlength=ng) == np.bincount(inv, minlength=ng)
    row_of = {int(e): i for i, e in enumerate(np.asarray(arr["element"], np.int64).tolist())}
    at = np.full(ng, -1, np.int64)
    # the rows of a success share its parent (one rule success, strew.ornament._engine._commit)
    at[inv] = [row_of.get(int(p), -1) for p in np.asarray(_parent_rows(arr), np.int64).tolist()]
    return np.where(every, at, -1)


def _parent_rows(arr: Any) -> Any:
    """Per row, the ``element`` of the row drawing its parent: the private column
    strew.ornament._context.PARENT_COLUMN where the tile wrote it (a spiral's parent is
    an arm inside its parent spiral's row), else the public ``parent``."""
    from .ornament._context import PARENT_COLUMN

    return arr[PARENT_COLUMN] if PARENT_COLUMN in arr.columns else arr["parent"]


# how near a later tile (in halos) a tile leaves its late-phase elements to it (_keep_groups)
_LATE_BAND = 0.5
# for a pattern that keeps its first phase (no tile anchors): how many of its first phases
# a tile keeps up to its border (_held_phase_rows; 1: the first alone, as before w31h)
_KEEP_PHASES = 2
# for a pattern that keeps its first phase (_first_phase_rows): how far past the halo's
# open edges (in halos) circle centres may lie (strew.ornament._engine: the elements stay
# in the region), and how far past its rectangle (in halos) a tile keeps its first phase
_OPEN_REACH = 1.0
_KEEP_FIRST_REACH = 0.5
# whether _keep_groups leaves the first phase's rows deeper than that in a later tile to
# it, for a pattern without tile anchors (_first_phase_beyond; 0: kept, for measurement)
_FIRST_BEYOND = 1
# whether a kept first phase's success placed at its tile anchors goes with the anchors'
# owner (_keep_groups; 0: kept by the rows' own distance, as a success without anchors)
_FIRST_ANCHORED = 1
# for a pattern with tile anchors: whether keep_ancestors may keep a later phase's
# ancestor rows inside a later tile (1: as up to h/w25; 0: barred, _keep_groups)
_ANCHORED_KEEP_LATE_IN_LATER = 0
# which of those rows are barred: "inside", all; "grid", those over a grid point of the
# pattern's ``tile_anchor_grid`` (strew.ornament._context.covers_anchor_grid)
_ANCHORED_BAR = "grid"
# how many rounds of strew.ornament._context.cut_touching _keep_groups runs at most
_CUT_ROUNDS = 1
# how near a later tile (in halos) the successes of cut_touching lie
_CUT_BAND = 0.5
# how near a later tile (in halos) every row that cut_touching hands over lies: the later
# tile refills only its grown rectangle, a halo into this tile; a success with a row
# farther keeps its ancestors (strew.ornament._context.keep_ancestors)
_CUT_REACH = 0.9


def _public(job: _Job, arr: Any) -> Any:
    """``arr`` without the private columns of :data:`_HANDS_ON` (what the sink gets)."""
    private = _HANDS_ON.get(job.method, ({}, ()))[1]
    return arr.without_columns(*private) if any(c in arr.columns for c in private) else arr


# methods that hand a border over to a later tile by a ramp (_ramp) from a region grown
# by a quarter halo more (_reach): pack, whose Step 2 fills every gap it can
_HANDS_OVER_BY_RAMP = ("pack",)


def _reach(job: _Job) -> float:
    """How far a tile's region reaches beyond its rectangle: the halo, and for pack
    (:data:`_HANDS_OVER_BY_RAMP`) 1.25 halo where the tiles allow it.

    A later tile refills the holes of its finished neighbour's ramp (:func:`_ramp`, up
    to a halo deep): from a region a halo deep it reached the deepest ones only in
    part (two tiles, bar and disc, 64 seeds: centres 1-1.5 spacings into the finished
    tile at 0.91 of the interior's density; 1.0 with 1.25 halo). Bounds: a finished
    element that can touch the region has its centre within ``1.25 h + h / 2 <= 2 h``
    of the rectangle (``h >=`` the elements' diameter), in its tile's border band; and
    two tiles a tile apart keep elements in the middle one at most ``reach`` deep, apart
    when ``2 reach + h <= tile`` (a tile of at least 3.5 halos; the halo alone below).
    """
    h = job.halo
    if job.method not in _HANDS_OVER_BY_RAMP:
        return h
    return max(h, min(1.25 * h, (min(job.tile) - h) / 2.0))


def _ornament_pattern(job: _Job) -> Any:
    """The ornament pattern ``job`` grows, or None (another method, or an input that is
    no pattern: the method reports that itself)."""
    if job.method != "ornament":
        return None
    from .ornament._pattern import load_pattern

    try:
        return load_pattern(job.input)
    except Exception:  # not a pattern (the method reports it itself)
        return None


def _ornament_cells(job: _Job, grown: tuple[float, float, float, float]) -> int | None:
    """The raster cells an ornament tile's run uses along its region's longer side: as
    many as give the cell of one run over the whole world, or None (another method; a
    ``cells`` the caller set is scaled the same way).

    Why (issue 19.4, helper w26b). strew.ornament's default raster has cells of half the
    minimum radius, but at least 256 along the region's longer side (§4.1's raster
    buffer). A tile's region (the tile and its halo, 60-72 units for the vase at tile
    48) fell under that floor and grew on cells 2.7 times finer than the untiled world's
    (192 units: 256 cells of 0.75), and the vase grows fewer elements on a finer raster
    (72 x 72 panel, rng 1 and 2: 968 and 964 elements on the default 256 cells, 1,062
    and 1,032 on 96 cells of 0.75; benchmarks/w26b_cells.py). The tiled
    vase worlds were ~3.5 % short of the untiled control in every tile phase
    (benchmarks/results/w26_summary.txt). Given the world's cell, every tile places as
    one run over the whole world would. Departure from the paper: §4.1 sizes the raster
    for one panel; this hand-over of its cell between runs is ours.
    """
    if job.method != "ornament" or (not _has_tile_anchors(job) and _keeps_first_phase(job) is None):
        # the vase (tile anchors) and hierarchy (keeps its first phase), measured (w26b,
        # w27h); the other patterns' tuned tile rules (willow's _at_parent: test_orn19m_
        # willow_at_parent) assume the tile's own raster and were not measured on this one
        return None
    size = max(float(job.size[0]), float(job.size[1]))
    cells = job.params.get("cells", job.params.get("resolution"))
    if cells is None:
        pat = _ornament_pattern(job)
        if pat is None:
            return None
        mr = job.params.get("min_radius")
        mr = float(pat.min_radius if mr is None else mr)
        if not (mr > 0 and np.isfinite(mr)):
            return None  # the method reports it itself
        # strew.ornament._engine._Grower's default, for the whole world
        cells = int(np.clip(np.ceil(size / (0.5 * mr)), 256, 2048))
    cell = size / float(cells)
    side = max(grown[2] - grown[0], grown[3] - grown[1])
    return int(np.clip(np.ceil(side / cell - 1e-9), 8, 8192))


def _has_tile_anchors(job: _Job) -> bool:
    """Whether ``job`` grows an ornament pattern with tile anchors (its ``tile_anchors``
    attribute: the vase's grid flowers; strew.ornament._context.anchor_rows)."""
    pat = _ornament_pattern(job)
    return pat is not None and bool(getattr(pat, "tile_anchors", ()) or ())


def _keeps_first_phase(job: _Job) -> str | None:
    """The name of the first phase of an ornament pattern that keeps it across borders
    (its ``tile_keeps_first_phase`` attribute, hierarchy's vines), else None."""
    pat = _ornament_pattern(job)
    if pat is None or not getattr(pat, "tile_keeps_first_phase", False) or not pat.phases:
        return None
    return str(pat.phases[0].name)


def _first_phase_rows(first: tuple[np.ndarray, np.ndarray], job: _Job) -> np.ndarray:
    """(n,) bool: of the first phase's rows (``first``: :func:`_first_phase_depth`), those
    within ``_KEEP_FIRST_REACH`` halos of the tile's rectangle, which the tile keeps (with
    their ancestors: _keep_groups) even where they lie in a later tile.

    Why (issue 19.4, hierarchy). Wong et al. grow the whole vine structure before any
    flower (§5, Fig. 10: "the pattern starts from the seed points by growing the vines",
    a state precondition on each rule). A tile's region ends a halo past its border, and
    §4.1 discards a circle the region's boundary stops: the finished tile squeezed its
    vines into the first half halo past the border (1.8 and 3.1 times the interior's
    rate by quarter halo; benchmarks/hie15_halo.py), and the +-1 s strips held 1.32
    times the untiled control's vines (6 worlds, tiles 48-68). With the halo's edges
    that face a later tile open (_open_edges; no squeeze), the finished tile dropped its
    vines that crossed the border and every vine grown from them back into its side,
    and the later tile could not regrow them: its band held no circle of a vine's
    radius 8 among the finished tile's other kinds (vines 0.75, density 0.90 at +-1 s;
    helper wld17). Kept, the vines near the border are the ones one run grows there
    before any flower, and the later tile grows its own vines around them, and every
    later phase across the border. Past half a halo the open edge's own pile-up begins
    (3.4 times the interior's vines 2-2.5 s past the border when kept a halo deep), so
    those are left to the later tile. Departure from the paper: it grows one panel in
    one run; this hand-over between runs is ours.
    """
    ph, depth = first
    return ph & (depth <= _KEEP_FIRST_REACH * job.halo)


def _held_phase_rows(arr: Any, job: _Job) -> np.ndarray | None:
    """(n,) bool: the rows of the phases after the first that a tile keeps up to its
    border, as it grew them: for a pattern that keeps its first phase
    (:func:`_keeps_first_phase`) without tile anchors, its phases 2 to ``_KEEP_PHASES``
    where at least one phase follows them; None for the other patterns (or none held).
    _keep_groups leaves them neither to the late band (``_LATE_BAND``) nor to the cut
    rounds (strew.ornament._context.cut_touching); they still go with their success's
    tip and their parent (keep_whole), and only where no row of their success lies in
    a later tile (_keep_groups).

    Why (issue 19.4, helper w31h). Hierarchy's flowers (its second phase, each on a twig
    from a vine) were short in the +-2 s strips: twigs 0.78 of the untiled control's
    share (5 worlds, tiles 40-56, seed 19; benchmarks/results/w28h_summary.txt). No
    twig was lost: the finished tile grew its flowers up to the border and dropped
    them (world 160, tile 40, seed 19: of 22 twigs it grew within 1.5 s of a later
    tile it kept 5; 11 with the late band off, 19 with the cut rounds off too;
    benchmarks/w31h_trace.py), and the later tile refilled that band from its side:
    its flowers landed on the border itself, where the emptied band and its own side
    left circles of a flower's size (radius >= 5), and the band's inner half, narrower
    than a flower's circle once they stood, got leaves instead (finished side 0.5-1 s,
    tiles 40, 52, 56: flowers 16 against the control's 32, leaves 85 against 72;
    benchmarks/w31h_dropped.py). In one run
    (Wong et al. §5, Fig. 10) every flower grows before any leaf, into the circles the
    vine structure leaves, and the finished tile's flowers near the border are those:
    its vines there are one run's (_first_phase_rows). The later tile now grows its own
    flowers around them, as it grows its vines around the kept vines; the leaves and
    fillers near the border are still left to it. Departure from the paper: it grows
    one panel in one run; this hand-over between runs is ours.
    """
    if _KEEP_PHASES < 2 or _keeps_first_phase(job) is None or _has_tile_anchors(job) or "phase" not in arr.columns:
        return None
    pat = _ornament_pattern(job)
    if pat is None or len(pat.phases) <= _KEEP_PHASES:
        return None
    names = {str(p.name) for p in pat.phases[1:_KEEP_PHASES]}
    held = np.array([p in names for p in np.asarray(arr["phase"], dtype=object)], bool)
    return held if held.any() else None


def _first_phase_depth(arr: Any, t: Tile, job: _Job) -> tuple[np.ndarray, np.ndarray] | None:
    """For a pattern that keeps its first phase (:func:`_keeps_first_phase`): (n,) bool,
    the rows of that phase, and (n,) float, each row's distance past ``t``'s rectangle
    (0 inside); None for the other patterns (or no rows)."""
    first = _keeps_first_phase(job)
    if first is None or "phase" not in arr.columns or not len(arr):
        return None
    x, y = np.asarray(arr.x, float), np.asarray(arr.y, float)
    x0, y0, x1, y1 = t.rect
    depth = np.hypot(np.maximum(np.maximum(x0 - x, x - x1), 0.0), np.maximum(np.maximum(y0 - y, y - y1), 0.0))
    ph = np.array([p == first for p in np.asarray(arr["phase"], dtype=object)], bool)
    return ph, depth


def _first_phase_beyond(first: tuple[np.ndarray, np.ndarray], job: _Job) -> np.ndarray:
    """(n,) bool: of the first phase's rows (``first``: :func:`_first_phase_depth`), those
    more than ``_KEEP_FIRST_REACH`` halos past the tile's rectangle. For a pattern without tile
    anchors (hierarchy) _keep_groups leaves those inside a later tile to it, placed at
    their parent (_at_parent) or kept as a vine's ancestor (strew.ornament._context
    .keep_ancestors' ``barred``), where that leaves no hole.

    Why (issue 19.4, helper w27h). _first_phase_rows keeps the vines within half a halo
    of the border; past it the open edge's pile-up begins and the vines are the later
    tile's. But a vine is placed where its parent is drawn (_at_parent, every vine row
    parents a rule), and a kept vine keeps its ancestors (keep_ancestors), so a vine
    grown from the tile reached as deep as its chord: on the world's raster cell
    (_ornament_cells; world 192, tile 48, seed 1, corner tile) a vine 7.7 units past the
    border was kept, placed at its parent inside the tile, with a kept child 2.5 units
    past. Now such a vine, and what grew from it, goes to the later tile, which grows its
    own vines there, where every row lost with it lies within the later tile's reach
    (``_CUT_REACH`` halos, as _keep_groups' cut rounds; the later tile refills them).
    Dropped without that condition (every such vine, its subtree with it), the tiled
    world at tile 48 (seed 19) held 2,383 elements against the control's 2,537 (2,551
    kept), the holes 12-20 units inside the finished tiles (benchmarks/w26_phase_bins.py
    w27hnobar,w27hnew,w27hctl 19; benchmarks/results/w27h_summary.txt). Departure from
    the paper: Wong et al. grow one panel in one run (§4.1, §5); this hand-over is ours.
    """
    ph, depth = first
    return ph & (depth > _KEEP_FIRST_REACH * job.halo)


def _open_edges(t: Tile, job: _Job, grown: tuple[float, float, float, float]) -> list[list[float]]:
    """The parts ``[x0, y0, x1, y1]`` of the grown rectangle's edges that lie in a later
    tile (not on the world's edge, not in a finished tile): the ornament engine measures
    a circle there against the elements alone (strew.ornament._engine._closed_part).
    For the patterns of :func:`_keeps_first_phase` only (helper wld17's open edges, whose
    finished side was refilled short of vines without them, see _first_phase_rows)."""
    gx0, gy0, gx1, gy1 = grown
    w, h = job.size
    torus = job.torus is not None
    sides = []
    if torus or gx0 > 0:
        sides.append((gx0, gy0, gx0, gy1))
    if torus or gx1 < w:
        sides.append((gx1, gy0, gx1, gy1))
    if torus or gy0 > 0:
        sides.append((gx0, gy0, gx1, gy0))
    if torus or gy1 < h:
        sides.append((gx0, gy1, gx1, gy1))
    out = []
    for lx0, ly0, lx1, ly1 in _later_rects(t, job):
        for ax, ay, bx, by in sides:
            if ax == bx:  # vertical: x inside the later tile, y overlapping it
                lo, hi = max(ay, ly0), min(by, ly1)
                if lx0 < ax < lx1 and hi > lo:
                    out.append([ax, lo, ax, hi])
            else:
                lo, hi = max(ax, lx0), min(bx, lx1)
                if ly0 < ay < ly1 and hi > lo:
                    out.append([lo, ay, hi, ay])
    return out


def _later_rects(t: Tile, job: _Job) -> list[tuple[float, float, float, float]]:
    """The rectangles of the tiles around ``t`` that run after it (higher phase), moved
    next to ``t`` across the wrap on a torus."""
    nx, ny = job.grid
    w, h = job.size
    tw, th = job.tile
    out = []
    for dj in (-1, 0, 1):
        for di in (-1, 0, 1):
            i, j = t.i + di, t.j + dj
            if not (di or dj):
                continue
            if job.periodic:
                dx, dy = (i // nx) * w, (j // ny) * h
                i, j = i % nx, j % ny
            elif 0 <= i < nx and 0 <= j < ny:
                dx = dy = 0.0
            else:
                continue
            if (j % 2) * 2 + i % 2 <= t.phase:
                continue
            x1 = w if i == nx - 1 else (i + 1) * tw
            y1 = h if j == ny - 1 else (j + 1) * th
            out.append((i * tw + dx, j * th + dy, x1 + dx, y1 + dy))
    return out


def _ramp(arr: Any, t: Tile, job: _Job) -> np.ndarray:
    """(n,) bool: the elements a pack tile keeps near its later neighbours.

    An element whose centre lies at distance ``d`` from the nearest later tile's
    rectangle is dropped with probability ``(1 - min(1, d / halo)) * (a_min / a) ** 0.5
    * (c / c_max) ** 0.25`` (``a``: its area, ``a_min``: the smallest area among the
    tile's elements of its kind, ``c``: its kind's compactness, the shape's area over
    its circumscribed disc's, ``c_max``: the most compact kind's of the tile; the draws come from
    the tile's second stream, ``SeedSequence(seed, spawn_key=(index, 1))``); those in a
    later tile are kept only just past the border (below). The later tile refills the holes.

    Why (issue 19.4): dropping exactly the centres beyond the border left a rough front,
    nearly a wall, of a saturated packing. The later tile packed against it as against a
    region's edge: discs in its crevices (centres within half a spacing s on the
    finished side at 1.19 of the interior's density), then layers (0.83, 1.12, 0.93 over
    the next 1.5 s on its own side). Border strips of +-1 s came to 1.045 of the
    interior, bars' share 0.96 (benchmarks/worlds_strips.py, pack, 800 x 800, seeds 1-2;
    strew demo's stones: 1.065, hooks 0.948). Thinned over a halo, the finished side
    keeps a saturated packing with scattered holes, which the later tile refills, and
    the later tile meets no front: +-1 s 1.003, +-2 s 1.009, bars 0.993 and 0.982; the
    stones 1.005 and 1.014, but hooks 0.973 and 0.960: a large element's hole was
    refilled by smaller ones (two tiles: up to 1.10 of the density where the ramp
    starts). Large elements are therefore dropped less, by the square root of the area
    ratio (exponent 1 overshot: bars' share 1.04 in two tiles): +-1 s 1.007 and 1.003,
    +-2 s 1.005 and 1.011, every kind's share within 1.3 % (bars, the stones' three).

    Across kinds the weight is the compactness, not the area (issue 19.4, after the
    later tile came to keep on a finished side only what fills its holes,
    :func:`_in_holes`). With the tile's smallest element over all kinds, the stones'
    crescents (the smallest kind, 382 units of area against the ring's 460 and the
    hook's 620) were dropped most, and the later tile refilled every kind's holes with
    too many rings, the most compact kind (refilled / dropped: rings 1.06, hooks 0.95,
    crescents 0.97): within 1 s of a border crescents 0.970 [0.956, 0.986] of the
    interior's share, rings 1.016, hooks 1.016 (7200^2 in tiles of 900, seeds 1-4,
    python benchmarks/pack_seam_kinds.py). The area within each kind and no weight
    across kinds: crescents 1.001, rings 1.014, hooks 0.982 [0.966, 0.998], but bars
    and discs (bars half again as large, and less compact) lost their bars, 0.995 ->
    0.977 [0.965, 0.988] (benchmarks/worlds_strips.py --methods pack, seeds 1-4): a
    compact kind refills any kind's hole, so it is dropped more. With the compactness
    to the power 1/4 (bars 0.85 of the discs' weight, 0.82 by area before; the stones'
    hooks 0.875, crescents 0.89, rings 1): +-1 s rings 0.987, hooks 1.011, crescents
    1.005, +-2 s 0.994, 0.996, 1.010, density 0.990 and 0.999; bars 1.011 [0.999,
    1.023], discs 0.991, density 1.000 (+-2 s 0.999, 1.001, 1.003). Within a kind (a
    range of scales: the demo's trees, 0.2-1.0) the weight is the area's, as before.

    Past the border (centres in a later tile, which the tile used to drop whole) an
    element is kept with the probability at the border, ``1 - w`` (``w``: the weights
    above), falling linearly to 0 at ``_RAMP_PAST`` halos past ``t``'s rectangle: the
    smallest of a kind (``w = 1``) never, the large ones mostly near the border. Why
    (issue 19.4, strew demo's trees, scale 0.2-1.0): the later tile packs around its
    finished neighbours' elements, and pack's Step 1 (§4.1, sparse Poisson-disk
    placements at random scales, where nearly all large trees come from) samples the free
    region shrunk by the largest element's radius (30, 2.3 spacings s), so that it placed
    none next to the finished packing; Step 2 filled that band with small trees. Within
    half an s past a border the trees of scale 0.6-0.8 and 0.8-1.0 were at 0.48 and 0.25
    of the interior's density, the mean scale within 1 s at 0.966 (seed 1, python
    benchmarks/pack_seam_profile.py), the density within 1 s at 1.032 [1.020, 1.042]
    (seeds 1-4, python benchmarks/pack_seam_kinds.py --input trees --side 2400). The large
    trees the finished tile placed there (its region reaches 1.25 halo past the border)
    stand in for them; the later tile packs around them as around the rest. With
    ``_RAMP_PAST`` 0.25 (seeds 1-4 pooled): within 1 s density 1.001 [0.986, 1.014],
    oaks 1.015, pines 0.982, mean scale 0.990; within 2 s 0.986 [0.974, 0.997] (was
    0.994), 1.006, 0.993. Bars and discs +-1 s 0.997, 1.012, 0.990; stones 0.988, rings
    0.986, hooks 1.014, crescents 1.003 (worlds_strips.py --methods pack,pack_stones
    --seeds 1,2 --no-control). Left: the ramp's holes on the finished side are refilled
    to 0.90-0.93 of the interior's density (-2.5 s .. 0, before and after).
    Sakurai & Miyata pack one region in one run; this hand-over between runs is ours.
    """
    later = _later_rects(t, job)
    if not later:
        return np.ones(len(arr), bool)
    x, y = np.asarray(arr.x, float), np.asarray(arr.y, float)
    d = np.full(len(arr), np.inf)
    for x0, y0, x1, y1 in later:
        dx = np.maximum(np.maximum(x0 - x, x - x1), 0.0)
        dy = np.maximum(np.maximum(y0 - y, y - y1), 0.0)
        d = np.minimum(d, np.hypot(dx, dy))
    gen = np.random.Generator(np.random.PCG64(np.random.SeedSequence(job.seed, spawn_key=(t.index, 1))))
    u = gen.random(len(arr))
    sc = np.abs(np.asarray(arr.scale, float).reshape(len(arr), -1))
    area = np.array([float(arr.shapes[k].area) for k in arr.kinds])[np.asarray(arr.kind, np.int64)] * sc[:, 0] * sc[:, -1]
    # a_min per kind (issue 19.4): across kinds the area ratio dropped the smallest kind
    # most, whose holes the later tile refilled with the compact kinds (the docstring)
    k = np.asarray(arr.kind, np.int64)
    amin = np.full(len(arr.kinds), np.inf)
    np.minimum.at(amin, k, area)
    w = (amin[k] / np.maximum(area, 1e-300)) ** _RAMP_SIZE_EXPONENT
    # across kinds, by compactness (area / circumscribed disc's): a compact kind
    # refills any kind's hole, so it is dropped more (see the docstring)
    c = np.array([float(arr.shapes[n].area) / (math.pi * float(arr.shapes[n].radius) ** 2) for n in arr.kinds])
    w = w * (c[k] / np.max(c[np.unique(k)])) ** _RAMP_COMPACT_EXPONENT
    thr = (1.0 - np.minimum(d / job.halo, 1.0)) * w
    # past the border (centres in a later tile): kept with the probability at the border,
    # 1 - w, falling to 0 at _RAMP_PAST halos past t's rectangle (see the docstring)
    x0, y0, x1, y1 = t.rect
    past = np.hypot(np.maximum(np.maximum(x0 - x, x - x1), 0.0), np.maximum(np.maximum(y0 - y, y - y1), 0.0))
    band = _RAMP_PAST * job.halo
    keep_past = (1.0 - w) * np.maximum(1.0 - past / band, 0.0) if band > 0 else np.zeros(len(arr))
    return u >= np.where((d > 0) | (past <= 0), thr, 1.0 - keep_past)


# the exponent of the area ratio in _ramp's drop probability
_RAMP_SIZE_EXPONENT = 0.5
# the exponent of the kinds' compactness ratio in _ramp's drop probability
_RAMP_COMPACT_EXPONENT = 0.25
# how far past its rectangle (in halos) a pack tile's ramp keeps elements in a later tile
_RAMP_PAST = 0.25


def _hole_discs(arr: Any, dropped: np.ndarray) -> np.ndarray:
    """(m, 3) float: ``x, y, r`` of the ``dropped`` elements (those :func:`_ramp` dropped
    and those centred in a later tile): position and bounding radius. The holes a later
    tile refills (:func:`_in_holes`); they travel in the tile's ``meta["holes"]``."""
    idx = np.flatnonzero(dropped)
    if not len(idx):
        return np.zeros((0, 3))
    return np.c_[np.asarray(arr.x, float)[idx], np.asarray(arr.y, float)[idx], _radii(arr.select(dropped))]


def _in_holes(arr: Any, neighbours: tuple[Any, ...], links: Mapping[int, list[tuple[float, float]]], context: Any) -> np.ndarray:
    """(n,) bool: the elements of ``arr`` in a hole that a finished neighbour's ramp left
    (pack, :data:`_HANDS_OVER_BY_RAMP`): nearer to one of the elements it dropped
    (``meta["holes"]``, moved next to ``t`` across the wrap) than to every element of
    ``context``, nearness being the distance between positions less the bounding radii
    (an additively weighted Voronoi diagram of the finished packing before the hand-over).

    A later tile keeps what it placed on a finished neighbour's side only there. Why
    (issue 19.4): one pack run leaves room for the smallest of a wide range of scales
    (strew demo's trees, scale 0.2-1.0, halo about 4.8 spacings s): the later tile's
    region, reaching 1.25 halo into the finished one, added small trees into the gaps of
    its kept packing as well as into the holes (two tiles, python
    benchmarks/pack_seam_split.py, 8 seeds: 363 elements in gaps against 1,403 in holes,
    5-10 % of the density over the whole reach: +-1 s 1.078 of the far density; centres
    in the dropped elements' bounding discs kept only: 1.041). Holes as discs alone
    missed the interstices between adjacent dropped elements, where the ramp drops nearly
    all of them (bar and disc, tests/worlds/test_border_strips.py: 0.76 of the density
    just before a border); the weighted Voronoi cells of the dropped elements tile the
    holes, those centred past the border included (without them the cells of the kept
    ones reached over the border: 0.93 there). Weights, two tiles (8 seeds) / the world
    (python benchmarks/pack_seam_trees.py): the bounding radii +-1 s 0.985 / 1.012, +-2 s
    0.963 / 0.984; the radii of discs of the elements' areas 1.051 / 1.052 and 1.031 /
    1.053; none (plain Voronoi) 1.057 and 1.041 (two tiles); bar and disc (600 x 500 in
    tiles of 50, seeds 11-12) +-1 s 0.997, 1.000 and 1.000 (0.909 with the discs alone).
    Sakurai & Miyata's fill-gap stops after 200 consecutive cancellations (§4.2), not at
    saturation, so a second run over a packing adds to it; this filter between runs is ours.
    """
    discs = [np.asarray(n.meta["holes"], float) + (dx, dy, 0.0)
             for n, shifts in zip(neighbours, links.values()) if len(n.meta.get("holes", ())) for dx, dy in shifts]
    if not discs or not len(arr):
        return np.zeros(len(arr), bool)
    from scipy.spatial import cKDTree

    xy = np.c_[np.asarray(arr.x, float), np.asarray(arr.y, float)]
    h = np.concatenate(discs)

    def nearest(cx: np.ndarray, cy: np.ndarray, r: np.ndarray) -> np.ndarray:
        # min over j of |p - c_j| - r_j: j within the nearest centre's distance + max(r)
        tree = cKDTree(np.c_[cx, cy])
        d1, _ = tree.query(xy)
        out = np.empty(len(xy))
        for m, (p, near) in enumerate(zip(xy, tree.query_ball_point(xy, d1 + float(np.max(r)) + 1e-9))):
            near = np.asarray(near, np.int64)
            out[m] = np.min(np.hypot(cx[near] - p[0], cy[near] - p[1]) - r[near])
        return out

    if context is None or not len(context):
        return np.ones(len(arr), bool)
    dh = nearest(h[:, 0], h[:, 1], h[:, 2])
    dk = nearest(np.asarray(context.x, float), np.asarray(context.y, float), _radii(context))
    return dh < dk


@dataclass
class WorldInfo:
    """What a world run made (the elements went to ``sink``).

    Attributes
    ----------
    meta : dict
        Provenance: method, params, seed, size, tile_size, halo, tiles, elements.
    shapes : dict
        The shape library (from the first tile with elements).
    counts : (n_tiles,) int ndarray
        Elements per tile.
    seconds : float
    workers : int
    dashboard : str or None
    """

    meta: dict[str, Any]
    shapes: dict[str, Any]
    counts: np.ndarray
    seconds: float
    workers: int
    dashboard: str | None = None
    kinds: dict[str, int] = field(default_factory=dict)


def _default_halo(method: str, input: Any, params: Mapping[str, Any], tile_size: float) -> float:
    """Twice the largest element extent for pack (radius x scale + margin), a quarter
    tile for methods whose elements are known only after the run."""
    if method == "pack":
        from .shape import Shape

        shapes = input.values() if isinstance(input, Mapping) else (input if isinstance(input, (list, tuple)) else [input])
        r = max((s.radius for s in shapes if isinstance(s, Shape)), default=0.0)
        sc = params.get("scale", (1.0, 1.0))
        hi = max((v[1] for v in sc.values()), default=1.0) if isinstance(sc, Mapping) else float(sc[1])
        m = params.get("margin", 0.0)
        m = max(m.values(), default=0.0) if isinstance(m, Mapping) else float(m or 0.0)
        if r > 0:
            return 2.0 * (r * hi + m)
    return tile_size / 4.0


def _connect(scheduler: str | None, workers: int, processes: bool, timeout: float) -> tuple[Any, Any]:
    """A dask Client (and the LocalCluster it owns, or None)."""
    try:
        from dask.distributed import Client, LocalCluster
    except ImportError:
        raise InputError(f"workers: running on Dask needs dask.distributed: {DISTRIBUTED_HINT}") from None
    if scheduler is not None:
        try:
            return Client(scheduler, timeout=timeout, set_as_default=False), None
        except (OSError, TimeoutError, ValueError) as exc:
            raise InputError(f"scheduler: no Dask scheduler answers at {scheduler} within {timeout:g} s ({type(exc).__name__})") from None
    # ":0": any free port for the dashboard (its link is printed); the default :8787
    # fails the start when another cluster or program holds it
    # silence_logs=CRITICAL: a task that raises (a refused halo, a script error) is
    # re-raised here as one message; at ERROR every worker also logged "Compute Failed"
    # with the traceback, one per tile (issue 17: no traceback)
    import dask

    with dask.config.set(_LOCAL_CONFIG):
        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=processes,
                               dashboard_address=":0", silence_logs=50)
    return Client(cluster, set_as_default=False), cluster


# the LocalCluster's housekeeping, made rarer (issue 19.5): on 2 cores every periodic
# callback of the scheduler, the 2 nannies and the 2 workers takes a core from the tiles.
# An idle cluster of 2 workers spent 47 ms CPU a second in the client process
# (scheduler, nannies) and 32 ms in each worker; with these, 7.5 and 2.5 ms
# (/tmp/dask19/idle.py). The event loops' 20 ms tick (a blocked-loop watchdog) cost the
# most; the workers' 10 ms stack sampling feeds only the dashboard's profile page; the
# memory monitors (100 ms) and system monitor (500 ms) feed its graphs. An existing
# cluster (scheduler=...) keeps its own settings.
_LOCAL_CONFIG = {
    "distributed.admin.tick.interval": "1s",
    "distributed.worker.profile.enabled": False,
    "distributed.worker.memory.monitor-interval": "1s",
    "distributed.admin.system-monitor.interval": "2s",
    "distributed.admin.system-monitor.gil.enabled": False,
}


def world(
    method: str,
    input: Any,
    size: tuple[float, float] | str,
    *,
    tile_size: float | None,
    halo: float | None = None,
    seed: int = 0,
    periodic: bool = False,
    workers: int = 1,
    scheduler: str | None = None,
    processes: bool = True,
    timeout: float = 10.0,
    sink: Callable[[int, Any], None] | None = None,
    progress: Callable[[int, int | None, str], None] | None = None,
    should_cancel: Callable[[], bool] | None = None,
    on_dashboard: Callable[[str], None] | None = None,
    **params: Any,
) -> WorldInfo:
    """Fill a ``size = (W, H)`` world tile by tile with ``method``.

    Parameters
    ----------
    method : {"pack", "synth"}
    input : object
        The method's input (shapes, palette, pattern), as for the method itself.
    size : (W, H) or "WxH"
    tile_size : float
        Side of a tile (document units); at least twice ``halo``. With ``periodic``
        optional: the tiles are the equal rectangles nearest to it that make an even
        count per axis [default: 2 x 2 tiles] (:func:`plan_periodic`).
    halo : float, optional
        How far a tile grows into its neighbours and sees their elements
        [default: twice the largest element extent for pack, a quarter tile otherwise].
    seed : int
        Tile ``k`` draws from ``SeedSequence(seed, spawn_key=(k,))``.
    periodic : bool
        The world is a torus (issue 18): tiles across the edges are neighbours, their
        elements seen moved by +-W, +-H; any method with ``context`` then tiles. The
        elements that ``sink`` receives are wrapped into ``[0, W) x [0, H)``.
    workers : int
        1 runs in this process; N > 1 on a local Dask cluster of N single-threaded
        workers (processes unless ``processes=False``).
    scheduler : str, optional
        ``"tcp://HOST:PORT"`` of a running Dask scheduler (``workers`` is then ignored).
    timeout : float
        Seconds to wait for ``scheduler`` before an :class:`InputError`.
    sink : callable, optional
        ``sink(tile_index, arrangement)``, called in this process for every finished tile
        (in completion order). Without it the tiles are dropped (counts only).
    progress, should_cancel : callable, optional
        As for methods: ``progress(tiles_done, tiles, "N el/s")``.
    on_dashboard : callable, optional
        Called with the Dask dashboard link when a cluster is used.
    **params
        The method's parameters (checked by its spec).

    Returns
    -------
    WorldInfo
    """
    from ._method import _jsonable, spec
    from ._version import __version__

    if method not in TILED_METHODS and not periodic:
        raise InputError(f"method: {method!r} does not tile; use one of {', '.join(TILED_METHODS)}")
    if isinstance(size, str):
        try:
            w, _, h = size.lower().partition("x")
            size = (float(w), float(h))
        except ValueError:
            raise InputError(f"size: expected WxH, got {size!r}") from None
    size = (float(size[0]), float(size[1]))
    if periodic:
        tiles, nx, ny = plan_periodic(size, tile_size)
        tw, th = size[0] / nx, size[1] / ny
    else:
        if tile_size is None:
            raise InputError("tile_size: give the side of a tile")
        tiles, nx, ny = plan(size, tile_size)
        tw = th = float(tile_size)
    tmin = min(tw, th)
    s = spec(method)
    checked = s.validate(params)
    params = {k: v for k, v in params.items()}
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
        raise InputError(f"seed: must be a non-negative integer, got {seed!r}")
    if halo is None:
        halo = _default_halo(method, input, checked, tmin)
    if not (math.isfinite(halo) and 0 < halo <= tmin / 2):
        if periodic:
            raise InputError(f"size: a periodic {size[0]:g} x {size[1]:g} tile is cut into {nx} x {ny} tiles (an even "
                             f"count per axis, for the 2x2 phases across the wrap) of {tw:g} x {th:g}, less than twice "
                             f"the halo {halo:g} (the elements' reach): make the size at least {4 * halo:g} on each side")
        raise InputError(f"halo: must be in (0, tile_size / 2] = (0, {tmin / 2:g}], got {halo:g} "
                         f"(elements too large for tiles of {tmin:g}: raise tile_size)")
    if isinstance(workers, bool) or not isinstance(workers, (int, np.integer)) or workers < 1:
        raise InputError(f"workers: must be a positive integer, got {workers!r}")
    job = _Job(method, input, params, size, float(halo), int(seed), (tw, th), (nx, ny), bool(periodic))
    counts = np.zeros(len(tiles), np.int64)
    kinds: dict[str, int] = {}
    shapes: dict[str, Any] = {}
    first = [len(tiles)]
    t0 = time.perf_counter()

    def done(t: Tile, arr: Any, ndone: int) -> None:
        arr = _public(job, arr)
        counts[t.index] = len(arr)
        for k, c in arr.counts().items():
            kinds[k] = kinds.get(k, 0) + c
        if len(arr) and (not shapes or t.index < first[0]):  # the lowest tile's: the same whatever the order
            first[0] = t.index
            shapes.clear()
            shapes.update(arr.shapes)
        if sink is not None:
            if periodic and len(arr):
                from ._periodic import canonical

                arr = arr.replace(**dict(zip("xy", canonical(arr.x, arr.y, (0.0, 0.0, *size)))))
            sink(t.index, arr)
        if progress is not None:
            rate = counts.sum() / max(time.perf_counter() - t0, 1e-9)
            progress(ndone, len(tiles), f"{int(counts.sum()):,} elements, {rate:,.0f} el/s")

    dashboard = None
    if workers == 1 and scheduler is None:
        nworkers = 1
        _run_serial(job, tiles, nx, ny, done, should_cancel)
    else:
        client, cluster = _connect(scheduler, int(workers), processes, float(timeout))
        try:
            nworkers = len(client.scheduler_info(n_workers=-1)["workers"]) if scheduler else int(workers)
            dashboard = client.dashboard_link if processes or scheduler else None
            if dashboard and on_dashboard is not None:
                on_dashboard(dashboard)
            with client.as_current():
                _run_dask(client, job, tiles, nx, ny, done, should_cancel)
        finally:
            client.close()
            if cluster is not None:
                cluster.close()
    meta = {
        "generator": f"strew {__version__}",
        "method": method,
        "seed": int(seed),
        "params": _jsonable(checked),
        "world": {"size": list(size), "tile_size": float(tmin) if tile_size is None else float(tile_size),
                  "tile": [tw, th], "periodic": bool(periodic), "halo": float(halo), "grid": [nx, ny],
                  "tiles": len(tiles), "elements": int(counts.sum()), "phases": "2x2 (Wei 2008)",
                  "rng": "SeedSequence(seed, spawn_key=(tile,))"},
    }
    if method == "program":  # tiles independent (strew.program._world)
        meta["world"].update(phases="none: the partitions' field cells run in 2x2 phases inside each tile",
                             rng="field cells from (seed, partition, cell); per-cell values from the cell's geometry")
    return WorldInfo(meta, shapes, counts, time.perf_counter() - t0, nworkers, dashboard, kinds)


def _check_cancel(should_cancel: Callable[[], bool] | None) -> None:
    if should_cancel is not None and should_cancel():
        from ._progress import Cancelled

        raise Cancelled("interrupted")


def _run_serial(job: _Job, tiles: list[Tile], nx: int, ny: int, done: Callable[..., None],
                should_cancel: Callable[[], bool] | None) -> None:
    """Phase by phase in this process; a tile's result is kept until its last dependent ran."""
    deps = {t.index: _deps(job, t, nx, ny) for t in tiles}
    waiting = {t.index: 0 for t in tiles}
    for t in tiles:
        for d in deps[t.index]:
            waiting[d] += 1
    results: dict[int, Any] = {}
    ndone = 0
    for phase in range(4):
        for t in tiles:
            if t.phase != phase:
                continue
            _check_cancel(should_cancel)
            arr = run_tile(job, t, *[results[d] for d in deps[t.index]])
            for d in deps[t.index]:
                waiting[d] -= 1
                if waiting[d] == 0:
                    del results[d]
            if waiting[t.index]:
                results[t.index] = border_band(arr, t, job.halo)
            ndone += 1
            done(t, arr, ndone)


def _run_dask(client: Any, job: _Job, tiles: list[Tile], nx: int, ny: int, done: Callable[..., None],
              should_cancel: Callable[[], bool] | None) -> None:
    """A task per tile that depends on its lower-phase neighbours' tasks (module docstring).

    The whole graph goes to the scheduler in one message, a task per tile
    (:func:`_dask_tile`): a dependent receives its neighbours' tiles and cuts their
    border bands itself. Before, every tile was submitted on its own and had a second
    task for its band (162 tasks, 162 graph updates for 81 tiles). The client, the
    scheduler and the worker loops (all but the tasks' own CPU) then spent 18 ms a tile,
    now 10.6 (pack, 100 tiles of 30, 12,802 elements, 2 workers, medians of 3 on a loaded
    machine: 141 against 83 us per element); on tiles of 100, 17.0 against 13.8 us per
    element (medians of 2). A tile's inputs are the same, so its result is.

    Memory: a finished tile stays on its worker until its last dependent ran. The
    scheduler runs the graph in dask.order's priorities, a front sweeping the grid: at
    most 62 of 729 tiles (27 x 27) wait for dependents in that order, against 560 bands
    in the phase order the tiles were submitted in before (dask.order.order on the graph).
    """
    from dask.distributed import as_completed

    [job_f] = client.scatter([job], broadcast=True, hash=False)
    run_id = uuid.uuid4().hex[:12]  # keys unique on a shared cluster
    key = {t.index: f"strew-tile-{run_id}-{t.index}" for t in tiles}
    deps = {t.index: _deps(job, t, nx, ny) for t in tiles}
    graph: dict[str, Any] = {job_f.key: job_f}
    for t in tiles:
        graph[key[t.index]] = (_dask_tile, job_f.key, t, [tiles[d] for d in deps[t.index]], *[key[d] for d in deps[t.index]])
    futures = dict(zip((t.index for t in tiles), client.get(graph, [key[t.index] for t in tiles], sync=False)))
    by_key = {futures[t.index].key: t for t in tiles}
    waiting = {t.index: 0 for t in tiles}  # dependents not yet finished
    for ds in deps.values():
        for d in ds:
            waiting[d] += 1
    ndone = 0
    try:
        for fut in as_completed(list(futures.values())):
            _check_cancel(should_cancel)
            t = by_key[fut.key]
            arr = fut.result()
            ndone += 1
            done(t, arr, ndone)
            # a tile is dropped once it and its last dependent finished
            for d in [*deps[t.index], t.index]:
                if d != t.index:
                    waiting[d] -= 1
                if waiting[d] == 0 and d in futures and futures[d].done():
                    futures.pop(d).release()
    finally:
        for f in futures.values():
            f.cancel()
        job_f.release()


def _dask_tile(job: _Job, t: Tile, near: list[Tile], *neighbours: Any) -> Any:
    """:func:`run_tile` on a Dask worker, given its neighbours' whole tiles: their border bands are cut here."""
    return run_tile(job, t, *[border_band(a, n, job.halo) for a, n in zip(neighbours, near)])


def tiled(method: str, input: Any, size: tuple[float, float] | str, *, tile_size: float | None, **kwargs: Any) -> Any:
    """The whole world as one :class:`~strew.Arrangement` (small worlds: tests, previews).

    Takes the arguments of :func:`world` (not ``sink``); ``meta`` holds the world's
    provenance and each element's tile in the column ``tile``.
    """
    from .arrangement import Arrangement, concat
    from .region import Region

    parts: dict[int, Any] = {}
    info = world(method, input, size, tile_size=tile_size, sink=lambda k, a: parts.__setitem__(k, a), **kwargs)
    w, h = info.meta["world"]["size"]
    order = sorted(parts)
    arrs = [parts[k].with_columns(tile=np.full(len(parts[k]), k, np.int32)) for k in order]
    shapes = info.shapes
    arrs = [a for a in arrs if len(a)]
    if not arrs:
        return Arrangement(shapes, [], [], [], region=Region.rectangle(w, h), meta=info.meta)
    return concat(_harmonize(arrs)).replace(region=Region.rectangle(w, h), meta=info.meta)


def periodic(method: str, input: Any, size: Any, *, rng: Any = None, tile_size: float | None = None,
             halo: float | None = None, workers: int = 1, **params: Any) -> Any:
    """A repeat tile (issue 18) made by tiling a torus: any method with ``context``.

    The ``W x H`` tile is cut into an even number of tiles per axis (2 x 2 by default),
    so that the 2 x 2 phases of :func:`world` hold across the wrap; each tile runs
    ``method`` around its finished neighbours, those across the edges moved by +-W or
    +-H. Every contact of the repeat is thus made by one run seeing the other side as
    its context: tiled copies of the result do not overlap (pack's context is an
    obstacle; synth and grow continue their neighbourhoods across it, as far as their
    ``context`` does).

    Parameters
    ----------
    method : str
        A method name of :mod:`strew._method` (``"pack"``, ``"synth"``, ``"grow"``, ...).
    input : object
        The method's input.
    size : (W, H), "WxH" or Region
        The tile; a Region must be an axis-aligned rectangle (its corner is kept).
    rng : int, Generator or None
        The tiles' seed is this int, or one drawn from the Generator; ``meta`` records
        it as the methods do (``seed`` or ``rng_state``).
    tile_size : float, optional
        Side of the tiles the torus is cut into (rounded to even counts) [default: 2 x 2].
    halo : float, optional
        As for :func:`world`.
    workers : int
        As for :func:`world` (1: this process).
    **params
        The method's parameters.

    Returns
    -------
    Arrangement
        Marked with :func:`strew._periodic.mark`: ``meta["periodic"] = [x0, y0, W, H]``,
        canonical positions; ``meta["world"]`` holds the tiling and ``tile`` each
        element's tile.

    Raises
    ------
    InputError
        A region that is not a rectangle; a tile too small for 2 x 2 tiles of at least
        twice the halo.
    """
    from . import _periodic
    from ._method import METHODS, as_region, seed_record, spec, stamp
    from .region import Region

    if method not in METHODS:
        raise InputError(f"method: unknown method {method!r}")
    dom = as_region(size, "size")
    if dom is None:
        raise InputError("size: give the tile to fill, (W, H) or 'WxH'")
    x0, y0, w, h = _periodic.frame_of_region(dom)
    gen, seed_rec = seed_record(rng)
    seed = int(seed_rec["seed"]) if "seed" in seed_rec else int(gen.integers(0, 2**63 - 1))
    arr = tiled(method, input, (w, h), tile_size=tile_size, halo=halo, seed=seed, workers=workers,
                periodic=True, **params)
    if x0 or y0:
        arr = arr.replace(x=arr.x + x0, y=arr.y + y0)
    world_meta = dict(arr.meta["world"], seed=seed)
    checked = spec(method).validate(params)
    region = Region.rectangle(w, h, x0, y0) if (x0 or y0) else Region.rectangle(w, h)
    arr = arr.replace(region=region, meta={"world": world_meta})
    arr = stamp(arr, spec(method), input, checked, seed_rec, region=region)
    return _periodic.mark(arr, (x0, y0, w, h))


def iter_phases(tiles: list[Tile]) -> Iterator[list[Tile]]:
    """The tiles of each phase, phase by phase (Wei's phase groups)."""
    for phase in range(4):
        yield [t for t in tiles if t.phase == phase]
