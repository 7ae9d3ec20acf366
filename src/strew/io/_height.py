"""16-bit height maps of 2D arrangements (Sakurai & Miyata §5.3, Fig. 16; issue 20 point 6).

``strew.save(arr, "relief.height.png")`` renders any arrangement as a greyscale 16-bit
PNG for displacement and game engines. Each kind has a height profile:

``"dome"``
    round top: ``h = a * sqrt(1 - (1 - t)**2)``, ``t`` the distance to the element's
    outline divided by its largest inside distance (a crista).
``"plateau"``
    flat top with a bevel over the outer 30% of that distance.
``"groove"``
    a V-shaped channel of depth ``a`` along the element's outline, half-width 20% of
    that distance (at least 1.5 pixels): a sulcus. Placing a groove kind at the same
    positions as dome kinds, but larger, gives Fig. 16's sulci around the cristae.

Raised profiles combine by their maximum, grooves by their minimum (deepest), and the
height is their sum clipped to [-1, 1]; pixel = round((h + 1) / 2 * 65535), so flat
ground is 32768, the top of a full-height element 65535 and the bottom of a full-depth
groove 0. The picture covers the region's bounds, or without a region the elements'
bounds with a 2% margin (as the SVG and PNG outputs); row 0 is the top (smallest y).
A repeat tile (``meta["periodic"]``, issue 18) covers exactly its tile, and elements that
cross its edges are drawn again at the opposite edges: the map tiles without a seam.

On the command line, ``--height-profile KIND=PROFILE[:HEIGHT]`` (repeatable; ``*`` for
the kinds not named) sets ``meta["height_profiles"]``, which this writer reads.
"""

from __future__ import annotations

import struct
import zlib
from collections.abc import Mapping
from typing import Any

import numpy as np
import shapely

from .._errors import InputError
from ..arrangement import Arrangement

__all__ = ["PROFILES", "height_map", "to_height_png", "png16"]

PROFILES = ("dome", "plateau", "groove")


def _profiles(arr: Arrangement, profiles: Mapping[str, Any] | None) -> dict[str, tuple[str, float]]:
    spec = profiles if profiles is not None else arr.meta.get("height_profiles", {})
    if not isinstance(spec, Mapping):
        raise InputError("profiles: expected a mapping kind -> 'dome' | 'plateau' | 'groove'")
    unknown = set(spec) - set(arr.kinds) - {"*"}
    if unknown:
        raise InputError(f"profiles: unknown kind {sorted(unknown)[0]!r} (known: {', '.join(arr.kinds)})")
    out: dict[str, tuple[str, float]] = {}
    for kind in arr.kinds:
        v = spec.get(kind, spec.get("*", "dome"))
        if isinstance(v, Mapping):
            name, amp = v.get("profile", "dome"), v.get("height", 1.0)
        else:
            name, amp = v, 1.0
        if name not in PROFILES:
            raise InputError(f"profiles.{kind}: expected one of {', '.join(PROFILES)}, got {name!r}")
        if isinstance(amp, bool) or not isinstance(amp, (int, float)) or not 0 < amp <= 1:
            raise InputError(f"profiles.{kind}.height: expected a number in (0, 1], got {amp!r}")
        out[kind] = (str(name), float(amp))
    return out


def height_map(
    arr: Arrangement,
    *,
    width: int = 1024,
    profiles: Mapping[str, Any] | None = None,
) -> tuple[np.ndarray, tuple[float, float, float]]:
    """Heights in [-1, 1] of an arrangement on a pixel grid.

    Parameters
    ----------
    arr : Arrangement
    width : int
        Pixels across; the height follows the frame's aspect ratio.
    profiles : mapping of kind -> profile, optional
        ``"dome"``, ``"plateau"``, ``"groove"`` or ``{"profile": ..., "height": a}`` with
        ``0 < a <= 1``; the key ``"*"`` covers kinds not named. Default: the document's
        ``meta["height_profiles"]``, else ``"dome"`` for every kind.

    Returns
    -------
    heights : (h, w) float
    frame : (x0, y0, pixel_size)
        World coordinates of the top-left corner and the size of a pixel.
    """
    from scipy.ndimage import distance_transform_edt

    if isinstance(width, bool) or not isinstance(width, (int, np.integer)) or not 1 <= width <= 16384:
        raise InputError(f"width: expected an integer in 1..16384, got {width!r}")
    prof = _profiles(arr, profiles)
    from .._periodic import frame as periodic_frame

    tile = periodic_frame(arr)
    if tile is not None:
        # a repeat tile (issue 18): the picture is the tile, mapped to whole pixels, and
        # elements crossing its edges are drawn again on the opposite side, so the map's
        # left/right and top/bottom edges continue each other (seamless displacement)
        x0, y0, w_world, h_world = (float(v) for v in tile)
        x1, y1 = x0 + w_world, y0 + h_world
    elif arr.region is not None:
        x0, y0, x1, y1 = arr.region.bounds
    else:
        x0, y0, x1, y1 = arr.bounds
        pad = 0.02 * max(x1 - x0, y1 - y0)
        x0, y0, x1, y1 = x0 - pad, y0 - pad, x1 + pad, y1 + pad
    w_world, h_world = x1 - x0, y1 - y0
    if w_world <= 0 or h_world <= 0:
        s = max(w_world, h_world, 1.0)
        x0, y0, w_world, h_world = (x0 + x1 - s) / 2, (y0 + y1 - s) / 2, s, s
    width = int(width)
    px = w_world / width
    hpx = max(1, int(round(h_world / px)))
    # rows are exactly the tile's height for a repeat tile (pixels a hair off square)
    py = h_world / hpx if tile is not None else px
    sampling = (py / px, 1.0)  # distances in x-pixels
    shifts = [(0, 0)] if tile is None else [(i, j) for j in (-1, 0, 1) for i in (-1, 0, 1)]
    raised = np.zeros((hpx, width))
    grooves = np.zeros((hpx, width))
    geoms = arr.geometry_of("geometry") if len(arr) else np.zeros(0, dtype=object)
    names = arr.kind_names
    for i in range(len(arr)):
        g = geoms[i]
        if g is None or g.is_empty:
            continue
        if g.area <= 0:
            g = g.buffer(0.75 * px)  # strokes: a line a pixel and a half wide
        name, amp = prof[str(names[i])]
        gx0, gy0, gx1, gy1 = g.bounds
        size = max(gx1 - gx0, gy1 - gy0)
        w_groove = max(1.5, 0.2 * 0.5 * size / px)  # pixels, refined below from the real inside distance
        padp = int(np.ceil(w_groove)) + 2 if name == "groove" else 1
        # the element's whole window (not cut at the picture's edge, so that its inside
        # distances, and a tile's copies across the edges, are those of the whole element)
        c0 = int(np.floor((gx0 - x0) / px)) - padp
        c1 = int(np.ceil((gx1 - x0) / px)) + padp
        r0 = int(np.floor((gy0 - y0) / py)) - padp
        r1 = int(np.ceil((gy1 - y0) / py)) + padp
        places = [(r0 + j * hpx, c0 + k * width) for k, j in shifts
                  if c0 + k * width < width and c1 + k * width > 0 and r0 + j * hpx < hpx and r1 + j * hpx > 0]
        if not places:
            continue
        xs = x0 + (np.arange(c0, c1) + 0.5) * px
        ys = y0 + (np.arange(r0, r1) + 0.5) * py
        X, Y = np.meshgrid(xs, ys)
        inside = shapely.contains_xy(g, X, Y)
        if not inside.any() and name != "groove":
            continue
        d_in = distance_transform_edt(np.pad(inside, 1), sampling=sampling)[1:-1, 1:-1]
        dmax = float(d_in.max())
        if name == "groove":
            d_out = distance_transform_edt(np.pad(~inside, 1, constant_values=True), sampling=sampling)[1:-1, 1:-1]
            half = max(1.5, 0.2 * dmax)
            signed = np.where(inside, d_in - 0.5, d_out - 0.5)  # pixel-centre distance to the outline
            h = -amp * np.clip(1.0 - np.abs(signed) / half, 0.0, 1.0)
            target, op = grooves, np.minimum
        else:
            t = np.clip(d_in / max(dmax, 1e-12), 0.0, 1.0)
            if name == "dome":
                h = amp * np.sqrt(np.clip(1.0 - (1.0 - t) ** 2, 0.0, 1.0))
            else:  # plateau
                h = amp * np.clip(t / 0.3, 0.0, 1.0)
            h = np.where(inside, h, 0.0)
            target, op = raised, np.maximum
        for pr, pc in places:
            a0, a1 = max(pr, 0), min(pr + h.shape[0], hpx)
            b0, b1 = max(pc, 0), min(pc + h.shape[1], width)
            view = target[a0:a1, b0:b1]
            op(view, h[a0 - pr:a1 - pr, b0 - pc:b1 - pc], out=view)
    return np.clip(raised + grooves, -1.0, 1.0), (float(x0), float(y0), float(px))


def png16(values: np.ndarray) -> bytes:
    """A 16-bit greyscale PNG of ``values`` ((h, w) uint16), written with zlib only."""
    v = np.asarray(values, dtype=">u2")
    h, w = v.shape
    raw = b"".join(b"\x00" + row.tobytes() for row in v)

    def chunk(tag: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)

    ihdr = struct.pack(">IIBBBBB", w, h, 16, 0, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b"")


def to_height_png(
    arr: Arrangement,
    *,
    width: int = 1024,
    profiles: Mapping[str, Any] | None = None,
    background: Any = None,
) -> bytes:
    """PNG bytes (16-bit greyscale) of :func:`height_map`.

    ``background`` is accepted and ignored, so the options of the colour PNG writer
    pass through :func:`strew.io.save_many`.

    Examples
    --------
    >>> from strew import Arrangement, Shape
    >>> a = Arrangement({"dot": Shape.circle(5)}, ["dot"], [10], [10])
    >>> to_height_png(a, width=32)[:8] == b"\\x89PNG\\r\\n\\x1a\\n"
    True
    """
    heights, _ = height_map(arr, width=width, profiles=profiles)
    return png16(np.round((heights + 1.0) * 0.5 * 65535.0).astype(np.uint16))
