"""PNG overviews and tile pyramids of worlds, drawn tile by tile (issue 19 point 3).

Every element is drawn as its outline polygon filled with its kind's colour (the
shape's ``fill`` style when it names a ``#rrggbb`` colour, else a fixed palette in the
order of the world's shape library; an element with its own geometry, ``parts``, in
its parts' own fill and stroke where they name them), on a canvas at most ``max_side`` pixels on its
longer side. Elements smaller than a pixel become single pixels. Memory is the canvas
plus one tile.

:func:`write_pyramid` renders a Parquet world as a z/x/y pyramid of 256-pixel PNGs (the
"XYZ" layout of web map viewers, y counted from the top): the deepest level window by
window, each window's elements read with a filter on ``x`` and ``y`` (pyarrow skips
the files and row groups whose statistics lie outside it), the levels above by
halving four children.
"""

from __future__ import annotations

import io
import os
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

__all__ = ["Overview", "write_pyramid", "render_dataset_png"]

_PALETTE = ["#3b6ea5", "#c8553d", "#6a994e", "#f2a541", "#7b4b94", "#2a9d8f", "#8d6e63", "#e76f51"]


def _rgb(text: str) -> tuple[int, int, int]:
    return (int(text[1:3], 16), int(text[3:5], 16), int(text[5:7], 16))


def _paint(style: Any, key: str, default: tuple[int, int, int]) -> tuple[int, int, int] | None:
    """The colour of a part's ``fill`` or ``stroke``: None for ``none``, the kind's colour
    ``default`` when the style names no ``#rrggbb`` colour. ``fill_opacity`` /
    ``stroke_opacity`` and ``opacity`` blend it with the white canvas once, opaque: the
    pieces of one face in neighbouring tiles share their border pixels, which a
    translucent fill would darken into a visible tile grid."""
    val = str(style.get(key, "")).strip().lower()
    if val == "none":
        return None
    rgb = _rgb(val) if len(val) == 7 and val.startswith("#") else default
    a = 1.0
    for k in (f"{key}_opacity", "opacity"):
        try:
            a *= float(style.get(k, 1.0))
        except (TypeError, ValueError):
            pass
    a = max(0.0, min(1.0, a))
    return tuple(round(a * v + (1.0 - a) * 255) for v in rgb)  # type: ignore[return-value]


class Overview:
    """A canvas for a ``size = (W, H)`` world; :meth:`add` draws a tile, :meth:`png` encodes.

    Parameters
    ----------
    size : (W, H) float
    max_side : int
        Pixels on the longer side.
    window : (x0, y0, x1, y1), optional
        Draw only this part of the world (default ``[0, W] x [0, H]``); ``max_side``
        is then the window's longer side.
    kinds : sequence of str, optional
        The world's kind names: kind ``k`` takes palette colour ``k`` whatever the
        order the tiles come in (a pyramid's windows agree).
    """

    def __init__(self, size: tuple[float, float], max_side: int = 2048, *,
                 window: Sequence[float] | None = None, kinds: Sequence[str] | None = None) -> None:
        from PIL import Image, ImageDraw

        x0, y0, x1, y1 = (0.0, 0.0, float(size[0]), float(size[1])) if window is None else map(float, window)
        w, h = x1 - x0, y1 - y0
        self.px = max_side / max(w, h)
        self.shape = (max(1, round(w * self.px)), max(1, round(h * self.px)))
        self.x0, self.top = x0, y1
        self.image = Image.new("RGB", self.shape, (255, 255, 255))
        self.draw = ImageDraw.Draw(self.image)
        self.colours: dict[str, tuple[int, int, int]] = {}
        self.order = {k: i for i, k in enumerate(kinds or ())}

    def _colour(self, name: str, shape: Any) -> tuple[int, int, int]:
        if name not in self.colours:
            fill = str((getattr(shape, "style", None) or {}).get("fill", ""))
            ok = len(fill) == 7 and fill.startswith("#")
            k = self.order.get(name, len(self.order) + len(self.colours))
            self.colours[name] = _rgb(fill) if ok else _rgb(_PALETTE[k % len(_PALETTE)])
        return self.colours[name]

    def add(self, arr: Any) -> None:
        """Draw the elements of one tile (an Arrangement)."""
        if len(arr) == 0:
            return
        px, x0, top = self.px, self.x0, self.top
        if arr.element_parts is not None:
            self._add_parts(arr)
            arr = arr.select(np.array([p is None for p in arr.element_parts], bool))
            if len(arr) == 0:
                return
        for k, name in enumerate(arr.kinds):
            idx = np.flatnonzero(arr.kind == k)
            if len(idx) == 0:
                continue
            shape = arr.shapes[name]
            colour = self._colour(name, shape)
            pts = shape.points
            if shape.radius * px < 1.5 or len(pts) < 3:
                for x, y in zip((arr.x[idx] - x0) * px, (top - arr.y[idx]) * px):
                    self.draw.point((float(x), float(y)), fill=colour)
                continue
            # the first path's outline (SVG's y runs down: flip)
            outline = shape.paths[0].points
            c = np.cos(arr.rotation[idx]) * arr.scale[idx]
            s = np.sin(arr.rotation[idx]) * arr.scale[idx]
            wx = arr.x[idx, None] + c[:, None] * outline[None, :, 0] - s[:, None] * outline[None, :, 1]
            wy = arr.y[idx, None] + s[:, None] * outline[None, :, 0] + c[:, None] * outline[None, :, 1]
            xs, ys = (wx - x0) * px, (top - wy) * px
            for a, b in zip(xs, ys):
                self.draw.polygon(list(zip(a.tolist(), b.tolist())), fill=colour)

    def _add_parts(self, arr: Any) -> None:
        """Draw the elements that carry their own geometry (``parts``: ornament, program
        worlds), every path of every part, filled when closed, stroked when open.

        A part's own style wins where it names them, as in ``strew render``: ``fill``
        (``none``: not filled; ``fill_opacity`` blends it) and, for open paths,
        ``stroke`` and ``stroke_width``; the kind's colour otherwise (:func:`_paint`). Closed paths
        are filled even-odd (a program face's holes stay open)."""
        px, x0, top = self.px, self.x0, self.top
        for i, parts in enumerate(arr.element_parts):
            if parts is None:
                continue
            colour = self._colour(arr.kinds[arr.kind[i]], arr.shapes[arr.kinds[arr.kind[i]]])
            c, s = np.cos(arr.rotation[i]) * arr.scale[i], np.sin(arr.rotation[i]) * arr.scale[i]
            for part in parts:
                style = getattr(part, "style", None) or {}
                fill = _paint(style, "fill", colour)
                stroke = _paint(style, "stroke", colour)
                if part.radius * arr.scale[i] * px < 1.5:
                    dot = fill if any(p.closed for p in part.paths) else stroke
                    if dot is not None:
                        self.draw.point((float((arr.x[i] - x0) * px), float((top - arr.y[i]) * px)), fill=dot)
                    continue
                width = max(1, round(float(style.get("stroke_width", 0.0) or 0.0) * arr.scale[i] * px))
                rings = []
                for path in part.paths:
                    q = path.points
                    xs = (arr.x[i] + c * q[:, 0] - s * q[:, 1] - x0) * px
                    ys = (top - (arr.y[i] + s * q[:, 0] + c * q[:, 1])) * px
                    pts = list(zip(xs.tolist(), ys.tolist()))
                    if path.closed and len(pts) >= 3:
                        rings.append(pts)
                    elif len(pts) >= 2 and stroke is not None:
                        self.draw.line(pts, fill=stroke, width=width)
                if rings and fill is not None:
                    self._fill_evenodd(rings, fill)

    def _fill_evenodd(self, rings: list[list[tuple[float, float]]], fill: tuple[int, int, int]) -> None:
        if len(rings) == 1:
            self.draw.polygon(rings[0], fill=fill)
            return
        from PIL import Image, ImageChops, ImageDraw

        xy = np.concatenate([np.asarray(r) for r in rings])
        bx0, by0 = (max(0, int(v) - 1) for v in xy.min(axis=0))
        bx1, by1 = (min(n, int(v) + 2) for v, n in zip(xy.max(axis=0), self.shape))
        if bx1 <= bx0 or by1 <= by0:
            return
        mask = Image.new("1", (bx1 - bx0, by1 - by0), 0)
        for r in rings:
            one = Image.new("1", mask.size, 0)
            ImageDraw.Draw(one).polygon([(x - bx0, y - by0) for x, y in r], fill=1)
            mask = ImageChops.logical_xor(mask, one)
        self.image.paste(Image.new("RGB", mask.size, fill), (bx0, by0), mask)

    def png(self) -> bytes:
        """The canvas as PNG bytes."""
        buf = io.BytesIO()
        self.image.save(buf, format="PNG", optimize=False)
        return buf.getvalue()


def _world_size(info: dict[str, Any]) -> tuple[float, float]:
    w = info["meta"].get("world", {}).get("size")
    if w:
        return float(w[0]), float(w[1])
    from .._errors import InputError

    raise InputError("dataset: its meta holds no world size (meta.world.size)")


def render_dataset_png(folder: str | os.PathLike[str], max_side: int) -> bytes:
    """A PNG overview of a Parquet world, read one file at a time (``strew render``)."""
    from ._parquet import iter_parquet_tiles, parquet_info

    info = parquet_info(folder)
    canvas = Overview(_world_size(info), max_side, kinds=list(info["shapes"]))
    for arr in iter_parquet_tiles(folder):
        canvas.add(arr)
    return canvas.png()


def write_pyramid(folder: str | os.PathLike[str], out: str | os.PathLike[str], zoom: int, *,
                  tile_px: int = 256) -> int:
    """Render a Parquet world as an XYZ pyramid ``out/z/x/y.png``, levels 0 to ``zoom``.

    Level ``z`` cuts the world's bounding square (side ``max(W, H)``, its top-left
    corner at ``(0, max(W, H))``) into ``2**z x 2**z`` tiles of ``tile_px`` pixels;
    tiles wholly outside the world are not written.

    Parameters
    ----------
    folder : path
        A dataset of :class:`strew.io._parquet.ParquetWriter`.
    out : path
        The pyramid's folder (made; existing tiles are overwritten).
    zoom : int
        Deepest level (0 to 12).

    Returns
    -------
    int
        Tiles written.
    """
    from PIL import Image

    from .._errors import InputError
    from ._parquet import _pa, parquet_info, table_to_arrangement
    from ..shape import Shape

    if isinstance(zoom, bool) or not isinstance(zoom, (int, np.integer)) or not 0 <= zoom <= 12:
        raise InputError(f"--pyramid-zoom: must be an integer from 0 to 12, got {zoom!r}")
    pa, pq = _pa()
    import pyarrow.compute as pc
    import pyarrow.dataset as pads

    folder = Path(folder)
    info = parquet_info(folder)
    w, h = _world_size(info)
    side = max(w, h)
    # elements reach at most the halo from their centre (tiles.world's halo >= extent)
    reach = float(info["meta"].get("world", {}).get("halo", side / 16))
    shapes = {k: Shape.from_dict(v) for k, v in info["shapes"].items()}
    kinds = list(shapes)
    files = sorted(str(p) for p in folder.glob("part-*.parquet"))
    data = pads.dataset(files, format="parquet") if files else None
    out = Path(out)
    written = 0
    n = 2 ** zoom
    s = side / n
    x, y = pc.field("x"), pc.field("y")
    for tx in range(n):  # the deepest level, window by window (one image in memory)
        for ty in range(n):
            x0, y1 = tx * s, side - ty * s
            x1, y0 = x0 + s, y1 - s
            if x0 >= w or y0 >= h:
                continue  # outside the world (which lies at the square's bottom left)
            canvas = Overview((w, h), tile_px, window=(x0, y0, x1, y1), kinds=kinds)
            if data is not None:
                flt = (x >= x0 - reach) & (x <= x1 + reach) & (y >= y0 - reach) & (y <= y1 + reach)
                t = data.to_table(filter=flt)
                if len(t):
                    canvas.add(table_to_arrangement(t, shapes))
            p = out / str(zoom) / str(tx) / f"{ty}.png"
            p.parent.mkdir(parents=True, exist_ok=True)
            canvas.image.save(p, format="PNG")
            written += 1
    for z in range(zoom - 1, -1, -1):  # each level from the four children below it
        for tx in range(2 ** z):
            for ty in range(2 ** z):
                children = [(dx, dy, out / str(z + 1) / str(2 * tx + dx) / f"{2 * ty + dy}.png")
                            for dx in (0, 1) for dy in (0, 1)]
                if not any(c.is_file() for _, _, c in children):
                    continue
                big = Image.new("RGB", (2 * tile_px, 2 * tile_px), (255, 255, 255))
                for dx, dy, c in children:
                    if c.is_file():
                        with Image.open(c) as child:
                            big.paste(child.convert("RGB"), (dx * tile_px, dy * tile_px))
                p = out / str(z) / str(tx) / f"{ty}.png"
                p.parent.mkdir(parents=True, exist_ok=True)
                big.resize((tile_px, tile_px), Image.BOX).save(p, format="PNG")
                written += 1
    return written
