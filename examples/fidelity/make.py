"""The fidelity suite: twelve hard exemplars, each a function of ``rng`` and its variation.

Each class is drawn as an artist would draw it (polygon stones, rectangular bricks and
tiles, scale shapes, sticks; a colour per kind) with parameters for element size, size
ratios, spacing, count, noise and row angle, so that variants nobody tuned on can be
drawn::

    from make import make_exemplar, NAMES
    ex = make_exemplar("clusters", rng=7, cluster_spacing=70.0)

``rng=None`` gives the default variant (seed 0), the one written by running this script::

    python examples/fidelity/make.py            # writes examples/fidelity/<name>.json

Every exemplar carries a rectangular ``region`` (its frame) and ``meta["exemplar"]``.
Elements never overlap and lie wholly inside the region. The sparse class marks its
gap fillers with the ``void`` column (Davison et al. 2018, §5.6), as
``strew.synth._exemplars.apples`` does: void elements are invisible when drawn.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import shapely

from strew import Arrangement, Region, Shape

__all__ = ["make_exemplar", "NAMES", "EXEMPLARS", "write_all"]

HERE = Path(__file__).resolve().parent

# -- helpers ------------------------------------------------------------------------------


def _rng(rng: Any) -> np.random.Generator:
    if isinstance(rng, np.random.Generator):
        return rng
    return np.random.default_rng(0 if rng is None else rng)


def _rot(p: np.ndarray, t: float) -> np.ndarray:
    c, s = np.cos(t), np.sin(t)
    return np.c_[c * p[:, 0] - s * p[:, 1], s * p[:, 0] + c * p[:, 1]]


def _stone(rng: np.random.Generator, radius: float, vertices: int = 9, roughness: float = 0.18, aspect: float = 0.8) -> np.ndarray:
    """An irregular convex-ish stone outline of about ``radius``: (vertices, 2) float."""
    t = np.sort(rng.uniform(0, 2 * np.pi, vertices))
    t = 0.5 * t + 0.5 * np.linspace(0, 2 * np.pi, vertices, endpoint=False)  # keep angles spread
    r = radius * (1.0 + rng.uniform(-roughness, roughness, vertices))
    p = np.c_[r * np.cos(t), aspect * r * np.sin(t)]
    hull = shapely.convex_hull(shapely.MultiPoint(p))
    return np.asarray(hull.exterior.coords)[:-1]


def _scale_outline(width: float, length: float, n: int = 14) -> np.ndarray:
    """A fish scale pointing along local +x: straight base, round free end."""
    t = np.linspace(-np.pi / 2, np.pi / 2, n)
    round_end = np.c_[0.5 * length * np.cos(t), 0.5 * width * np.sin(t)]
    return np.r_[round_end, [[-0.5 * length, 0.5 * width], [-0.5 * length, -0.5 * width]]]


def _wedge(inner: float, outer: float, half_angle: float) -> np.ndarray:
    """A ring tile: a trapezoid centred at the origin, long side along local x."""
    mid = 0.5 * (inner + outer)
    a, b = inner * np.tan(half_angle), outer * np.tan(half_angle)
    return np.array([[-b, outer - mid], [b, outer - mid], [a, inner - mid], [-a, inner - mid]])


def _dart(
    rng: np.random.Generator,
    box: tuple[float, float, float, float],
    radii: np.ndarray | float,
    count: int,
    *,
    gap: float = 0.0,
    placed: tuple[np.ndarray, np.ndarray] | None = None,
    tries: int = 20000,
    periodic: bool = False,
) -> tuple[np.ndarray, np.ndarray]:
    """Dart throwing of discs (bounding circles) inside ``box``, not overlapping ``placed``.

    ``tries`` counts darts per 170 x 170 of box area, so that a larger box draws the
    same process (the same saturation), not a sparser one. With ``periodic`` the box is a
    torus: centres anywhere in it, distances by the nearest image.

    Returns the new centres (m, 2) and radii (m,), m <= count.
    """
    x0, y0, x1, y1 = box
    tries = int(tries * (x1 - x0) * (y1 - y0) / 170.0**2)
    radii_arr = np.broadcast_to(np.asarray(radii, float), (count,)) if np.ndim(radii) == 0 else np.asarray(radii, float)
    P = np.zeros((0, 2)) if placed is None else np.asarray(placed[0], float).reshape(-1, 2)
    R = np.zeros(0) if placed is None else np.asarray(placed[1], float)
    n0 = len(P)
    m = 0.0 if periodic else float(radii_arr[:count].max()) if count else 0.0
    period = np.array([x1 - x0, y1 - y0])
    k, done = 0, 0
    batch = 512
    while done < tries and k < count:
        # darts in batches: their clearance to the elements placed before the batch at
        # once, then one by one against the batch's own accepted darts
        b = min(batch, tries - done)
        cand = rng.uniform((x0 + m, y0 + m), (x1 - m, y1 - m), (b, 2))
        done += b
        if len(P):
            d = np.abs(cand[:, None, :] - P[None, :, :])
            if periodic:
                d = np.minimum(d, period - d)
            clear = (np.hypot(d[..., 0], d[..., 1]) - R[None, :]).min(axis=1)
        else:
            clear = np.full(b, np.inf)
        new: list[int] = []
        newr: list[float] = []
        rmin = float(radii_arr[k:count].min()) if k < count else 0.0
        for i in np.flatnonzero(clear >= rmin + gap):  # the others cannot fit any dart left
            if k >= count:
                break
            r = float(radii_arr[k])
            if clear[i] < r + gap:
                continue
            if new:
                d = np.abs(cand[new] - cand[i])
                if periodic:
                    d = np.minimum(d, period - d)
                if np.any(np.hypot(d[:, 0], d[:, 1]) < np.asarray(newr) + r + gap):
                    continue
            new.append(i)
            newr.append(r)
            k += 1
        if new:
            P = np.r_[P, cand[new]]
            R = np.r_[R, newr]
    return P[n0:], R[n0:]


def _finish(
    name: str,
    shapes: dict[str, Shape],
    kind: Any,
    xy: np.ndarray,
    rotation: Any = None,
    scale: Any = None,
    *,
    box: tuple[float, float, float, float],
    columns: dict[str, Any] | None = None,
    params: dict[str, Any] | None = None,
    crop: bool = False,
) -> Arrangement:
    """Keep elements wholly inside ``box`` (with ``crop``: whose centre is in it, a
    half-open box), shift the box to the origin, wrap it."""
    xy = np.asarray(xy, float).reshape(-1, 2)
    n = len(xy)
    rotation = np.zeros(n) if rotation is None else np.broadcast_to(np.asarray(rotation, float), (n,))
    scale = np.ones(n) if scale is None else np.broadcast_to(np.asarray(scale, float), (n,))
    kind = np.asarray(kind)
    x0, y0, x1, y1 = box
    arr = Arrangement(shapes, kind, xy[:, 0] - x0, xy[:, 1] - y0, rotation, scale, columns=columns)
    region = Region.rectangle(x1 - x0, y1 - y0)
    if crop:
        inside = (arr.x >= 0) & (arr.x < x1 - x0) & (arr.y >= 0) & (arr.y < y1 - y0)
    else:
        inside = region.contains_geometry(arr.geometry, tolerance=1e-9)
    arr = arr.select(inside)
    meta = {"exemplar": name, "suite": "fidelity", "params": {k: (float(v) if isinstance(v, (int, float)) else v) for k, v in (params or {}).items()}}
    return arr.replace(region=region, meta=meta)


# -- the twelve classes -------------------------------------------------------------------


def _lattice_box(p: np.ndarray, box: tuple[float, float, float, float], angle: float) -> tuple[np.ndarray, tuple[float, float, float, float]]:
    """Turn lattice points by ``angle`` about the box centre."""
    c = np.array([0.5 * (box[0] + box[2]), 0.5 * (box[1] + box[3])])
    return _rot(p - c, angle) + c, box


def hex_lattice(rng: Any = None, *, spacing: float = 12.0, nx: int = 11, ny: int = 12, fill: float = 0.86, angle: float = 0.0) -> Arrangement:
    """A perfect hexagonal lattice of hexagonal tiles (no noise at all).

    ``fill`` is the tile's across-flats width over the lattice spacing; ``angle`` turns
    the lattice (radians). With ``angle = 0`` and ``ny`` even the frame is one period of
    the lattice: copies of the exemplar tile the plane seamlessly. Tiles whose centre is
    in the frame are kept (a crop), so some poke out of it.
    """
    _rng(rng)  # no randomness: the class is perfect by definition
    h = spacing * np.sqrt(3) / 2
    j, i = np.mgrid[-3 : ny + 3, -3 : nx + 3]
    p = np.c_[(i + 0.5 * (j % 2)).ravel() * spacing, j.ravel() * h]
    p, box = _lattice_box(p, (-0.25 * spacing, -0.5 * h, (nx - 0.25) * spacing, (ny - 0.5) * h), angle)
    r = fill * spacing / np.sqrt(3)  # circumradius of a hexagon with that across-flats width
    t = np.arange(6) * np.pi / 3 + np.pi / 6
    tile = Shape.polygon(np.c_[r * np.cos(t), r * np.sin(t)], style={"fill": "#d9a441", "stroke": "#6b4c12"})
    return _finish("hex_lattice", {"hex": tile}, np.zeros(len(p), int), p, angle, box=box, crop=True, params=dict(spacing=spacing, nx=nx, ny=ny, fill=fill, angle=angle))


def rows_noisy(rng: Any = None, *, spacing: float = 11.0, nx: int = 12, ny: int = 11, noise: float = 0.05, tile: float = 0.72, row_angle: float = 0.0) -> Arrangement:
    """Near-regular rows of square tiles with Gaussian positional noise (``noise`` x spacing).

    The noise is clipped at two standard deviations so tiles never touch. The frame is
    one period of the lattice (a crop by centres).
    """
    g = _rng(rng)
    j, i = np.mgrid[-3 : ny + 3, -3 : nx + 3]
    p = np.c_[i.ravel() * spacing, j.ravel() * spacing].astype(float)
    p += np.clip(g.normal(0.0, noise * spacing, p.shape), -2 * noise * spacing, 2 * noise * spacing)
    p, box = _lattice_box(p, (-0.5 * spacing, -0.5 * spacing, (nx - 0.5) * spacing, (ny - 0.5) * spacing), row_angle)
    sq = Shape.rectangle(tile * spacing, tile * spacing, style={"fill": "#4f7fa8", "stroke": "#1d3c57"})
    return _finish("rows_noisy", {"tile": sq}, np.zeros(len(p), int), p, row_angle, box=box, crop=True, params=dict(spacing=spacing, nx=nx, ny=ny, noise=noise, tile=tile, row_angle=row_angle))


def bricks(rng: Any = None, *, length: float = 22.0, height: float = 9.0, mortar: float = 1.6, rows: int = 16, per_row: int = 8, noise: float = 0.15) -> Arrangement:
    """Running-bond bricks, alternating red and ochre along each row.

    Each course is offset by half a brick; ``noise`` (in mortar widths) shifts each brick.
    The colours repeat every four courses; with ``rows`` a multiple of 4 and ``per_row``
    even the frame is one period (a crop by centres).
    """
    g = _rng(rng)
    pts, kind = [], []
    for r in range(-2, rows + 2):
        off = 0.5 * (length + mortar) * (r % 2)
        for c in range(-2, per_row + 2):
            pts.append((c * (length + mortar) + off, r * (height + mortar)))
            kind.append((c + r // 2) % 2)
    p = np.asarray(pts, float)
    p += np.clip(g.normal(0.0, noise * mortar * 0.5, p.shape), -0.45 * mortar, 0.45 * mortar)
    shapes = {
        "brick_red": Shape.rectangle(length, height, style={"fill": "#a8432d", "stroke": "#4a1c12"}),
        "brick_ochre": Shape.rectangle(length, height, style={"fill": "#d8a85a", "stroke": "#6b4c12"}),
    }
    q, hh = length + mortar, height + mortar
    box = (-0.25 * q, -0.5 * hh, (per_row - 0.25) * q, (rows - 0.5) * hh)
    return _finish("bricks", shapes, kind, p, box=box, crop=True, params=dict(length=length, height=height, mortar=mortar, rows=rows, per_row=per_row, noise=noise))


def scales(rng: Any = None, *, width: float = 12.0, length: float = 10.0, gap: float = 1.2, rows: int = 10, per_row: int = 10, row_angle: float = 0.0, noise: float = 0.03) -> Arrangement:
    """Rows of oriented fish scales; every scale points along the row normal.

    Alternate rows are offset by half a scale, as on a fish; ``row_angle`` turns the rows
    and the scales with them. The frame is one period for even ``rows`` (a crop by
    centres).
    """
    g = _rng(rng)
    pts = []
    for r in range(-3, rows + 3):
        off = 0.5 * (width + gap) * (r % 2)
        for c in range(-3, per_row + 3):
            pts.append((c * (width + gap) + off, r * (length + gap)))
    p = np.asarray(pts, float)
    p += np.clip(g.normal(0.0, noise * width, p.shape), -0.3 * gap, 0.3 * gap)
    q, hh = width + gap, length + gap
    p, box = _lattice_box(p, (-0.25 * q, -0.5 * hh, (per_row - 0.25) * q, (rows - 0.5) * hh), row_angle)
    # the scale's local +x points across the rows (down the body): rotation = row_angle + 90 deg
    rot = np.full(len(p), row_angle + np.pi / 2) + np.clip(g.normal(0.0, 0.02, len(p)), -0.04, 0.04)
    shape = Shape.polygon(_scale_outline(width, length), style={"fill": "#3f8f7a", "stroke": "#16372f"})
    return _finish("scales", {"scale": shape}, np.zeros(len(p), int), p, rot, box=box, crop=True, params=dict(width=width, length=length, gap=gap, rows=rows, per_row=per_row, row_angle=row_angle, noise=noise))


def stones(rng: Any = None, *, size: float = 200.0, radius: float = 6.5, spread: float = 0.2, gap: float = 1.2, count: int = 160) -> Arrangement:
    """Irregular stones of one kind: dart-thrown, scales ``1 +- spread``, any rotation."""
    g = _rng(rng)
    shape = Shape.polygon(_stone(g, radius), style={"fill": "#8a8f98", "stroke": "#3c4047"})
    sc = g.uniform(1 - spread, 1 + spread, count)
    p, _ = _dart(g, (0, 0, size, size), shape.radius * sc, count, gap=gap)  # bounding discs of the outline
    sc = sc[: len(p)]
    return _finish("stones", {"stone": shape}, np.zeros(len(p), int), p, g.uniform(0, 2 * np.pi, len(p)), sc, box=(0, 0, size, size), params=dict(size=size, radius=radius, spread=spread, gap=gap, count=count))


def two_sizes(rng: Any = None, *, size: float = 220.0, large: float = 12.0, ratio: float = 0.3, n_large: int = 80, n_small: int = 220, gap: float = 1.2) -> Arrangement:
    """Large stones with pebbles in the gaps (pebbles about 0.73 of the elements).

    Large stones are thrown first; pebbles (``ratio`` x the large radius) fill between.
    """
    g = _rng(rng)
    small = ratio * large
    big_shape = Shape.polygon(_stone(g, large, vertices=10), style={"fill": "#7d848f", "stroke": "#33363b"})
    peb_shape = Shape.polygon(_stone(g, small, vertices=7, roughness=0.12), style={"fill": "#c2b280", "stroke": "#6f6440"})
    sl = g.uniform(0.9, 1.1, n_large)
    pl, rl = _dart(g, (0, 0, size, size), big_shape.radius * sl, n_large, gap=gap)
    ss = g.uniform(0.85, 1.15, n_small)
    ps, _ = _dart(g, (0, 0, size, size), peb_shape.radius * ss, n_small, gap=gap, placed=(pl, rl), tries=60000)
    p = np.r_[pl, ps]
    kind = np.r_[np.zeros(len(pl), int), np.ones(len(ps), int)]
    sc = np.r_[sl[: len(pl)], ss[: len(ps)]]
    return _finish("two_sizes", {"stone": big_shape, "pebble": peb_shape}, kind, p, g.uniform(0, 2 * np.pi, len(p)), sc, box=(0, 0, size, size), params=dict(size=size, large=large, ratio=ratio, n_large=n_large, n_small=n_small, gap=gap))


def clusters(rng: Any = None, *, size: float = 300.0, cluster_spacing: float = 56.0, large: float = 8.0, small: float = 3.0, ring_gap: float = 1.5, ring_min: int = 4, ring_max: int = 6) -> Arrangement:
    """Clusters: each large disc ringed by 4 to 6 small discs, empty space between clusters.

    Cluster centres are dart-thrown on a torus and elements cropped by their centres: the
    frame is one period (copies tile seamlessly) and carries no empty border band.
    """
    g = _rng(rng)
    ring_r = large + small + ring_gap
    centres, _ = _dart(g, (0, 0, size, size), np.full(4000, 0.5 * cluster_spacing), 4000, tries=6000, periodic=True)
    pts, kind = [], []
    shifts = [np.array([dx, dy]) for dx in (-size, 0.0, size) for dy in (-size, 0.0, size)]
    for c0 in centres:
        m = int(g.integers(ring_min, ring_max + 1))
        t = g.uniform(0, 2 * np.pi) + np.arange(m) * 2 * np.pi / m + g.normal(0, 0.08, m)
        rr = ring_r * g.uniform(0.97, 1.05, m)
        for sh in shifts:  # the periodic images; the crop keeps one copy of each element
            c = c0 + sh
            pts.append(c)
            kind.append(0)
            pts.extend(c + np.c_[rr * np.cos(t), rr * np.sin(t)])
            kind += [1] * m
    shapes = {"disc": Shape.circle(large, style={"fill": "#c0504d", "stroke": "#5a1f1d"}), "dot": Shape.circle(small, 16, style={"fill": "#f2c14e", "stroke": "#7a5a10"})}
    p = np.asarray(pts, float)
    return _finish("clusters", shapes, kind, p, box=(0.0, 0.0, size, size), crop=True, params=dict(size=size, cluster_spacing=cluster_spacing, large=large, small=small, ring_gap=ring_gap, ring_min=ring_min, ring_max=ring_max))


def three_sizes(rng: Any = None, *, size: float = 210.0, small: float = 2.6, ratios: tuple[float, float, float] = (1.0, 2.0, 4.0), counts: tuple[int, int, int] = (170, 65, 26), gap: float = 1.2) -> Arrangement:
    """Three sizes of stones in radius ratio 1:2:4, thrown largest first."""
    g = _rng(rng)
    names = ("small", "medium", "large")
    colours = ("#d8c9a3", "#a59a86", "#6f6a62")
    shapes = {nm: Shape.polygon(_stone(g, small * rt, vertices=7 + 2 * i), style={"fill": col, "stroke": "#2f2c28"}) for i, (nm, rt, col) in enumerate(zip(names, ratios, colours))}
    pl, rl = np.zeros((0, 2)), np.zeros(0)
    p_all, k_all, s_all = [], [], []
    for idx in (2, 1, 0):
        sc = g.uniform(0.9, 1.1, counts[idx])
        p, r = _dart(g, (0, 0, size, size), shapes[names[idx]].radius * sc, counts[idx], gap=gap, placed=(pl, rl), tries=40000)
        pl, rl = np.r_[pl, p], np.r_[rl, r]
        p_all.append(p)
        k_all.append(np.full(len(p), idx))
        s_all.append(sc[: len(p)])
    p = np.concatenate(p_all)
    return _finish("three_sizes", shapes, np.concatenate(k_all), p, g.uniform(0, 2 * np.pi, len(p)), np.concatenate(s_all), box=(0, 0, size, size), params=dict(size=size, small=small, ratios=list(ratios), counts=list(counts), gap=gap))


def rings(rng: Any = None, *, radius: float = 15.0, tiles: int = 10, hub: float = 5.0, spacing: float = 40.0, nx: int = 4, ny: int = 4, noise: float = 0.01) -> Arrangement:
    """Rosettes: rings of wedge tiles around round hubs, the hubs on a hexagonal lattice."""
    g = _rng(rng)
    half = np.pi / tiles * 0.78
    wedge = Shape.polygon(_wedge(radius - 3.0, radius + 3.0, half), style={"fill": "#2e8b87", "stroke": "#0f3634"})
    pts, kind, rot = [], [], []
    hh = spacing * np.sqrt(3) / 2
    for j in range(-1, ny + 1):
        for i in range(-1, nx + 1):
            c = np.array([i * spacing + 0.5 * spacing * (j % 2), j * hh])
            c = c + g.normal(0, noise * spacing, 2)
            pts.append(c)
            kind.append(1)
            rot.append(0.0)
            t0 = g.uniform(0, 2 * np.pi)
            t = t0 + np.arange(tiles) * 2 * np.pi / tiles
            pts.extend(c + radius * np.c_[np.cos(t), np.sin(t)])
            kind += [0] * tiles
            rot += list(t - np.pi / 2)  # local +y (the wide side) points out of the ring
    p = np.asarray(pts, float)
    # one period of the hub lattice for even ny (a crop by centres: rings at the frame are cut)
    box = (-0.25 * spacing, -0.5 * hh, (nx - 0.25) * spacing, (ny - 0.5) * hh)
    shapes = {"tile": wedge, "hub": Shape.circle(hub, style={"fill": "#e0a030", "stroke": "#6b4c12"})}
    return _finish("rings", shapes, kind, p, rot, box=box, crop=True, params=dict(radius=radius, tiles=tiles, hub=hub, spacing=spacing, nx=nx, ny=ny, noise=noise))


def stripes(rng: Any = None, *, size: float = 170.0, band: float = 28.0, angle: float = 0.35, dot: float = 3.2, bar: tuple[float, float] = (9.0, 3.0), count: int = 220, gap: float = 2.2) -> Arrangement:
    """Stripes of two kinds: dart-thrown elements whose kind alternates by band.

    Bands are ``band`` wide and run at ``angle`` (radians); bars lie along the bands.
    """
    g = _rng(rng)
    r = max(dot, 0.5 * np.hypot(*bar))
    p, _ = _dart(g, (0, 0, size, size), np.full(count, r), count, gap=gap)
    u = p[:, 0] * np.cos(angle + np.pi / 2) + p[:, 1] * np.sin(angle + np.pi / 2)
    kind = (np.floor(u / band).astype(int)) % 2
    rot = np.where(kind == 1, angle + g.normal(0, 0.12, len(p)), 0.0)
    shapes = {"dot": Shape.circle(dot, 16, style={"fill": "#c0504d", "stroke": "#5a1f1d"}), "bar": Shape.rectangle(*bar, style={"fill": "#4f81bd", "stroke": "#1d3c57"})}
    return _finish("stripes", shapes, kind, p, rot, box=(0, 0, size, size), params=dict(size=size, band=band, angle=angle, dot=dot, bar=list(bar), count=count, gap=gap))


def sparse_voids(rng: Any = None, *, size: float = 200.0, spacing: float = 30.0, apple: float = 5.0, void: float = 4.0, void_spacing: float = 11.0) -> Arrangement:
    """Sparse apples with void elements in the gaps between them (synth's §5.6 convention).

    Void elements carry ``void = True``: invisible when drawn, they stand for the empty
    space that the texture keeps between visible elements.
    """
    g = _rng(rng)
    pa, ra = _dart(g, (0, 0, size, size), np.full(400, 0.5 * spacing), 400, tries=5000)
    pv, _ = _dart(g, (0, 0, size, size), np.full(800, 0.5 * void_spacing), 800, tries=12000, placed=(pa, ra))
    p = np.r_[pa, pv]
    kind = np.r_[np.zeros(len(pa), int), np.ones(len(pv), int)]
    t = np.linspace(0, 2 * np.pi, 24, endpoint=False)
    dimple = 1.0 - 0.12 * np.exp(-(((t - 1.5 * np.pi + np.pi) % (2 * np.pi) - np.pi) ** 2) / 0.08)  # the stalk dimple
    apple_outline = apple * dimple[:, None] * np.c_[np.cos(t), np.sin(t)]
    shapes = {"apple": Shape.polygon(apple_outline, style={"fill": "#b22222", "stroke": "#4c0d0d"}), "void": Shape.circle(void, 12, style={"fill": "#dddddd"})}
    rot = np.where(kind == 0, g.normal(0, 0.3, len(p)), 0.0)
    return _finish("sparse_voids", shapes, kind, p, rot, box=(0, 0, size, size), columns={"void": kind == 1}, params=dict(size=size, spacing=spacing, apple=apple, void=void, void_spacing=void_spacing))


def sticks(rng: Any = None, *, size: float = 170.0, length: float = 24.0, width: float = 2.6, count: int = 120, gap: float = 1.0, tries: int = 6000) -> Arrangement:
    """Elongated sticks at uniformly random angles, random sequential adsorption."""
    g = _rng(rng)
    stick = Shape.rectangle(length, width, style={"fill": "#8b5a2b", "stroke": "#3b240f"})
    base = stick.geometry
    placed: list[shapely.Geometry] = []
    pts, rots = [], []
    m = 0.5 * length
    for _ in range(int(tries * size * size / 170.0**2)):  # tries per 170 x 170, as _dart
        if len(pts) >= count:
            break
        p = g.uniform(m * 0.2, size - m * 0.2, 2)
        t = g.uniform(0, np.pi)
        geom = shapely.affinity.translate(shapely.affinity.rotate(base, t, use_radians=True, origin=(0, 0)), *p)
        if placed and np.any(shapely.dwithin(np.asarray(placed, dtype=object), geom, gap)):
            continue
        placed.append(geom)
        pts.append(p)
        rots.append(t)
    return _finish("sticks", {"stick": stick}, np.zeros(len(pts), int), np.asarray(pts), np.asarray(rots), box=(0, 0, size, size), params=dict(size=size, length=length, width=width, count=count, gap=gap))


EXEMPLARS: dict[str, Callable[..., Arrangement]] = {
    "hex_lattice": hex_lattice,
    "rows_noisy": rows_noisy,
    "bricks": bricks,
    "scales": scales,
    "stones": stones,
    "two_sizes": two_sizes,
    "clusters": clusters,
    "three_sizes": three_sizes,
    "rings": rings,
    "stripes": stripes,
    "sparse_voids": sparse_voids,
    "sticks": sticks,
}
NAMES: tuple[str, ...] = tuple(EXEMPLARS)

# classes whose default variant is lattice-like (fidelity reports their regularity)
LATTICE = ("hex_lattice", "rows_noisy", "bricks", "scales")


def make_exemplar(name: str, rng: Any = None, **variation: Any) -> Arrangement:
    """Draw one exemplar of the suite.

    Parameters
    ----------
    name : str
        One of :data:`NAMES`.
    rng : int, Generator or None
        None gives the default variant (seed 0).
    **variation
        The class's keyword parameters (see each function's signature).

    Returns
    -------
    Arrangement
        With a rectangular ``region`` and ``meta["exemplar"] == name``.
    """
    if name not in EXEMPLARS:
        raise ValueError(f"unknown exemplar {name!r}; use one of {', '.join(NAMES)}")
    return EXEMPLARS[name](rng, **variation)


def write_all(folder: Path = HERE) -> list[Path]:
    """Write the default variant of every class as ``<folder>/<name>.json``."""
    import strew

    out = []
    for name in NAMES:
        path = folder / f"{name}.json"
        strew.save(make_exemplar(name), path)
        out.append(path)
    return out


if __name__ == "__main__":
    for p in write_all(Path(sys.argv[1]) if len(sys.argv) > 1 else HERE):
        print(p)
