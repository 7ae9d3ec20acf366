"""Helpers of tests/worlds (no conftest.py there): overlaps and border-strip statistics."""

from __future__ import annotations

import numpy as np
import shapely


def overlapping_pairs(arr, tol: float = 1e-9) -> int:
    """Pairs of elements whose areas overlap by more than ``tol``."""
    g = arr.geometry_of("geometry")
    tree = shapely.STRtree(g)
    left, right = tree.query(g, predicate="intersects")
    m = left < right
    if not m.any():
        return 0
    return int((shapely.area(shapely.intersection(g[left[m]], g[right[m]])) > tol).sum())


def border_strips(arr, size, tile_size: float, width: float, margin: float):
    """(strip mask, interior mask, strip area, interior area) of element centres.

    The strips are the bands of half-width ``width`` about the tiles' inner borders; the
    interior is the rest; both leave out the world's own edge band ``margin``.
    """
    w, h = size
    x, y = arr.x, arr.y
    inside = (x >= margin) & (x <= w - margin) & (y >= margin) & (y <= h - margin)
    lines_x = np.arange(tile_size, w - 1e-9, tile_size)
    lines_y = np.arange(tile_size, h - 1e-9, tile_size)
    near = np.zeros(len(arr), bool)
    for lx in lines_x:
        near |= np.abs(x - lx) < width
    for ly in lines_y:
        near |= np.abs(y - ly) < width
    # areas by a fine raster of the same sets
    gx, gy = np.meshgrid(np.linspace(0, w, 1201)[:-1] + w / 2400, np.linspace(0, h, 1201)[:-1] + h / 2400)
    gin = (gx >= margin) & (gx <= w - margin) & (gy >= margin) & (gy <= h - margin)
    gnear = np.zeros_like(gin)
    for lx in lines_x:
        gnear |= np.abs(gx - lx) < width
    for ly in lines_y:
        gnear |= np.abs(gy - ly) < width
    cell = (w / 1200) * (h / 1200)
    return inside & near, inside & ~near, (gin & gnear).sum() * cell, (gin & ~gnear).sum() * cell


def drawn_radii(arr) -> np.ndarray:
    """(n,) float: each element's bounding radius about its centre from its own drawn
    parts (the ``parts`` column: ornament's one-off curves), times its largest |scale|;
    the kind's shape radius where a row has no parts.

    strew.tiles._radii reads the kind's shape, which for ornament is a stand-in (the first
    drawn element of the kind, strew.ornament._render): a vine or leaf may reach twice as
    far as its kind's stand-in.
    """
    from strew.tiles import _radii

    out = np.asarray(_radii(arr), float).copy()
    if "parts" not in arr.columns:
        return out
    scale = np.max(np.abs(np.asarray(arr.scale, float).reshape(len(arr), -1)), axis=1)
    for i, parts in enumerate(arr["parts"]):
        if not parts:
            continue
        pts = [np.asarray(q["points"] if isinstance(q, dict) else q.points, float) for p in parts for q in (p["paths"] if isinstance(p, dict) else p.paths)]
        pts = [q for q in pts if len(q)]
        if pts:
            out[i] = float(np.hypot(*np.vstack(pts).T).max()) * scale[i]
    return out


def overlapping_pairs_across(arr, groups, tol: float = 1e-9) -> int:
    """Pairs of elements of different ``groups`` (e.g. the ``tile`` column) whose areas
    overlap by more than ``tol``."""
    g = arr.geometry_of("geometry")
    groups = np.asarray(groups)
    left, right = shapely.STRtree(g).query(g, predicate="intersects")
    m = (left < right) & (groups[left] != groups[right])
    if not m.any():
        return 0
    return int((shapely.area(shapely.intersection(g[left[m]], g[right[m]])) > tol).sum())


def strip_units(arr, size, tile_size: float, width: float, margin: float) -> dict:
    """Border-strip counts per tile (the units of a bootstrap).

    A centre is in a *strip* when it lies within ``width`` of an inner tile border (the
    lines ``x = k T``, ``y = k T`` inside the world), else in the *interior*; centres in
    the world's own edge band ``margin`` count in neither. Per tile (row-major, the tile
    holding the centre): ``strip``, ``inner`` (counts), ``strip_area``, ``inner_area``
    (exact areas of the two sets in the tile, ``width`` under half a tile) and
    ``strip_kind``, ``inner_kind`` ((tiles, kinds) counts by kind index) and ``phase``
    (the tile's phase in strew.tiles' 2 x 2 colouring).
    """
    w, h = size
    t = float(tile_size)
    nx, ny = max(1, int(np.ceil(w / t - 1e-9))), max(1, int(np.ceil(h / t - 1e-9)))
    x, y = np.asarray(arr.x, float), np.asarray(arr.y, float)
    kind = np.asarray(arr.kind, np.int64)
    nk = len(arr.kinds)
    inside = (x >= margin) & (x <= w - margin) & (y >= margin) & (y <= h - margin)
    lx, ly = np.arange(1, nx) * t, np.arange(1, ny) * t
    dx = np.min(np.abs(x[:, None] - lx[None, :]), axis=1) if len(lx) else np.full(len(x), np.inf)
    dy = np.min(np.abs(y[:, None] - ly[None, :]), axis=1) if len(ly) else np.full(len(y), np.inf)
    near = (dx < width) | (dy < width)
    i = np.clip(np.floor(x / t), 0, nx - 1).astype(np.int64)
    j = np.clip(np.floor(y / t), 0, ny - 1).astype(np.int64)
    unit = j * nx + i
    n = nx * ny
    out = {
        "strip": np.bincount(unit[inside & near], minlength=n).astype(float),
        "inner": np.bincount(unit[inside & ~near], minlength=n).astype(float),
        "strip_kind": np.zeros((n, nk)),
        "inner_kind": np.zeros((n, nk)),
    }
    np.add.at(out["strip_kind"], (unit[inside & near], kind[inside & near]), 1)
    np.add.at(out["inner_kind"], (unit[inside & ~near], kind[inside & ~near]), 1)
    sa, ia = np.zeros(n), np.zeros(n)

    def span(a0, a1, lo_inner, hi_inner, hi_world):
        c0, c1 = max(a0, margin), min(a1, hi_world - margin)  # the tile less the edge band
        e0, e1 = max(a0 + (width if lo_inner else 0.0), margin), min(a1 - (width if hi_inner else 0.0), hi_world - margin)
        return max(c1 - c0, 0.0), max(e1 - e0, 0.0)

    for jj in range(ny):
        for ii in range(nx):
            x0, x1 = ii * t, min(w, (ii + 1) * t)
            y0, y1 = jj * t, min(h, (jj + 1) * t)
            fx, ex = span(x0, x1, ii > 0, ii < nx - 1, w)
            fy, ey = span(y0, y1, jj > 0, jj < ny - 1, h)
            ia[jj * nx + ii] = ex * ey
            sa[jj * nx + ii] = fx * fy - ex * ey
    out["strip_area"], out["inner_area"] = sa, ia
    jj, ii = np.divmod(np.arange(n), nx)
    out["phase"] = ((jj % 2) * 2 + ii % 2).astype(float)  # strew.tiles' 2 x 2 phases
    return out


def bootstrap_ratio(arrays, fn, boot: int, rng) -> dict:
    """``fn(*arrays)`` and the 95 % percentile interval of ``boot`` resamples of the
    units (the rows shared by ``arrays``): ``{"value", "ci"}``."""
    n = len(arrays[0])
    value = float(fn(*arrays))
    draws = np.empty(boot)
    for b in range(boot):
        pick = rng.integers(0, n, n)
        draws[b] = fn(*[a[pick] for a in arrays])
    return {"value": value, "ci": [float(v) for v in np.nanpercentile(draws, [2.5, 97.5])]}


def strip_ratios_against_control(tiled: dict, control: dict, boot: int, rng) -> dict:
    """Strip against interior, tiled against its untiled control on the same lines.

    ``tiled`` and ``control``: :func:`strip_units` dicts of two worlds measured on the same
    tile lines (or the rows of several such worlds concatenated in the same order), row k of
    one the same unit as row k of the other. A strip-to-interior ratio of one world mixes
    the seams with what the lines themselves see where no border exists: a world that is
    not stationary at the tile's scale (hierarchy grown from its first-phase tiles' seed
    points; issue 19.4, helper w60d: at tiles of 32-48 the interior >= 3 s from every
    border is only each tile's centre) has a strip ratio off 1 untiled too. The double
    ratio (tiled ratio / control ratio) keeps only what the tiles add: 1 for a world
    without seams whatever the lines' bias. Returns ``{"density": {"tiled", "control",
    "tiled_over_control"}, "kind_share": [{...} per kind]}``, each ``{"value", "ci"}``: the
    ratios of the summed counts and their 95 % percentile intervals over ``boot`` paired
    resamples of the rows (a draw takes a row's tiled and control counts together).
    """
    n = len(tiled["strip"])
    if len(control["strip"]) != n:
        raise ValueError("tiled and control must have the same units")
    nk = tiled["strip_kind"].shape[1]

    def ratios(u, rows):
        s, i = u["strip"][rows].sum(), u["inner"][rows].sum()
        sa, ia = u["strip_area"][rows].sum(), u["inner_area"][rows].sum()
        sk, ik = u["strip_kind"][rows].sum(0), u["inner_kind"][rows].sum(0)
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.concatenate([[(s / sa) / (i / ia)], (sk / s) / (ik / i)])

    every = np.arange(n)
    rt, rc = ratios(tiled, every), ratios(control, every)
    draws = np.empty((boot, 3, nk + 1))
    for b in range(boot):
        pick = rng.integers(0, n, n)
        t, c = ratios(tiled, pick), ratios(control, pick)
        with np.errstate(divide="ignore", invalid="ignore"):
            draws[b] = (t, c, t / c)
    lo, hi = np.nanpercentile(draws, [2.5, 97.5], axis=0)
    with np.errstate(divide="ignore", invalid="ignore"):
        point = (rt, rc, rt / rc)

    def entry(j):
        return {name: {"value": float(point[m][j]), "ci": [float(lo[m, j]), float(hi[m, j])]}
                for m, name in enumerate(("tiled", "control", "tiled_over_control"))}

    return {"density": entry(0), "kind_share": [entry(k + 1) for k in range(nk)]}


def folded_profile(arr, size, tile_size: float, spacing: float) -> dict:
    """The centres' density across the tile borders folded modulo the tile size.

    Bins of about half a ``spacing`` over ``[0, T)`` of ``x mod T`` (centres with
    ``T <= x < W - T``: the inner columns only, so that the world's own edges, at
    multiples of ``T`` too, do not fold onto the borders) and of ``y mod T`` likewise,
    pooled; every bin then sees the same area (``exposure``). ``near_bins``: the bins
    within one ``spacing`` of a border.
    """
    w, h = size
    t = float(tile_size)
    nb = max(8, int(round(t / (0.5 * spacing))))
    edges = np.linspace(0.0, t, nb + 1)
    x, y = np.asarray(arr.x, float), np.asarray(arr.y, float)
    counts = np.zeros(nb, np.int64)
    exposure = np.zeros(nb)
    for v, span in ((x, w), (y, h)):
        n_inner = int(np.floor(span / t + 1e-9)) - 2  # whole inner tiles along this axis
        if n_inner < 1:
            continue
        sel = (v >= t) & (v < t * (n_inner + 1))
        counts += np.histogram(np.mod(v[sel], t), edges)[0]
        exposure += n_inner * np.diff(edges) * (h if span is w else w)
    centre = 0.5 * (edges[:-1] + edges[1:])
    near = (centre < spacing) | (centre > t - spacing)
    return {"counts": counts, "exposure": exposure / max(exposure.sum(), 1e-300), "near_bins": near}


def profile_test(counts, exposure, near) -> dict:
    """Chi-square of folded ``counts`` against flat (expected in proportion to
    ``exposure``) and the density of the ``near`` bins against the others, with a 95 %
    interval taking the counts as Poisson (conservative for packings, whose counts vary
    less)."""
    from scipy import stats

    counts = np.asarray(counts, float)
    e = counts.sum() * np.asarray(exposure, float)
    chi2 = float(((counts - e) ** 2 / e).sum())
    dof = len(counts) - 1
    cn, cf = counts[near].sum(), counts[~near].sum()
    en, ef = e[near].sum(), e[~near].sum()
    r = (cn / en) / (cf / ef)
    se = np.sqrt(1 / cn + 1 / cf)
    return {"bins": int(len(counts)), "chi2_dof": chi2 / dof, "p": float(stats.chi2.sf(chi2, dof)),
            "near_ratio": {"value": float(r), "ci": [float(r * np.exp(-1.96 * se)), float(r * np.exp(1.96 * se))]},
            "counts": [int(v) for v in counts]}


def border_window_scores(local: dict, tile_size: float) -> dict:
    """The local fidelity map's windows split by the tile borders.

    ``border``: a border line ``k T`` (k >= 1) crosses the window's middle half (both
    sides in view); ``interior``: the window lies inside one tile. Each: ``score`` and
    ``unit`` (an id of the tile holding the window's centre).
    """
    score = np.asarray(local["score"], float)
    t = float(tile_size)
    out = {c: {"score": [], "unit": []} for c in ("border", "interior")}
    if score.size:
        sd = float(local["window"])
        for r in range(score.shape[0]):
            for c in range(score.shape[1]):
                v = score[r, c]
                if not np.isfinite(v):
                    continue
                wx, wy = local["x0"] + c * local["step"], local["y0"] + r * local["step"]
                cross = False
                for a in (wx, wy):
                    k0, k1 = np.ceil((a + sd / 4) / t), np.floor((a + 3 * sd / 4) / t)
                    cross |= bool(k1 >= max(k0, 1))
                whole = (np.floor(wx / t) == np.floor((wx + sd) / t - 1e-9)) and (np.floor(wy / t) == np.floor((wy + sd) / t - 1e-9))
                cls = "border" if cross else ("interior" if whole else None)
                if cls:
                    out[cls]["score"].append(v)
                    out[cls]["unit"].append(int(np.floor((wx + sd / 2) / t)) + 100_000 * int(np.floor((wy + sd / 2) / t)))
    return {c: {"score": np.asarray(d["score"], float), "unit": np.asarray(d["unit"], np.int64)} for c, d in out.items()}


def signed_profile(arr, size, tile_size: float, spacing: float, reach: float = 3.0) -> dict:
    """Centres by signed distance to the nearest inner border, positive into the tile of
    the later phase (``strew.tiles``: phase ``(j % 2) * 2 + i % 2``), in bins of half a
    ``spacing`` out to ``reach`` spacings; the inner tiles' part of each border only
    (both tiles off the world's edge). ``counts``: (kinds + 1, bins), all kinds first;
    ``edges`` in spacings."""
    w, h = size
    t = float(tile_size)
    nx, ny = int(round(w / t)), int(round(h / t))
    x, y = np.asarray(arr.x, float), np.asarray(arr.y, float)
    kind = np.asarray(arr.kind, np.int64)
    edges = np.arange(-2 * reach, 2 * reach + 0.5) * 0.5 * spacing
    counts = np.zeros((len(arr.kinds) + 1, len(edges) - 1), np.int64)
    for v, o, n_along, n_other in ((x, y, nx, ny), (y, x, ny, nx)):
        k = np.round(v / t)
        d = v - k * t
        oi = np.floor(o / t).astype(np.int64)
        ok = (k >= 1) & (k <= n_along - 1) & (np.abs(d) < edges[-1]) & (oi >= 1) & (oi <= n_other - 2)
        lo, hi = (k - 1).astype(np.int64), k.astype(np.int64)
        p_lo = (oi % 2) * 2 + lo % 2 if v is x else (lo % 2) * 2 + oi % 2
        p_hi = (oi % 2) * 2 + hi % 2 if v is x else (hi % 2) * 2 + oi % 2
        sd = np.where(p_hi > p_lo, d, -d)
        counts[0] += np.histogram(sd[ok], edges)[0]
        for q in range(len(arr.kinds)):
            counts[q + 1] += np.histogram(sd[ok & (kind == q)], edges)[0]
    return {"counts": counts, "edges": edges / spacing}


def overview_profile(arr, size, tile_size: float, spacing: float, max_side: int = 2048) -> dict:
    """The overview PNG's ink (non-white pixels) folded modulo the tile, as the eye sees
    a grid: the world drawn by :class:`strew.io._overview.Overview`; the pixel columns
    (and rows) of the inner tiles folded onto one tile; ``near``: the share of ink within
    one ``spacing`` of a border, ``far``: elsewhere (``ratio`` near / far), and per
    folded pixel the ink share (``profile``)."""
    from strew.io._overview import Overview

    ov = Overview(size, max_side, kinds=list(arr.kinds))
    ov.add(arr)
    ink = (np.asarray(ov.image.convert("L"), float) < 250).astype(float)  # (rows, cols), row 0 at the top
    px = ov.px
    tp = tile_size * px
    prof, weight = None, None
    for axis_ink, n_px in ((ink.mean(axis=0), ink.shape[1]), (ink[::-1].mean(axis=1), ink.shape[0])):
        pos = (np.arange(n_px) + 0.5) / px  # world coordinate of each pixel column / row
        inner = (pos >= tile_size) & (pos < tile_size * (np.floor(n_px / tp + 1e-9) - 1))
        b = np.floor(np.mod(pos[inner], tile_size) * px).astype(np.int64)
        nb = int(round(tp))
        s = np.bincount(b, axis_ink[inner], minlength=nb)[:nb]
        c = np.bincount(b, minlength=nb)[:nb].astype(float)
        prof = s if prof is None else prof + s
        weight = c if weight is None else weight + c
    prof = prof / np.maximum(weight, 1)
    u = (np.arange(len(prof)) + 0.5) / px
    near = (u < spacing) | (u > tile_size - spacing)
    return {"near": float(prof[near].mean()), "far": float(prof[~near].mean()),
            "ratio": float(prof[near].mean() / prof[~near].mean()), "profile": prof, "pixels_per_unit": px}
