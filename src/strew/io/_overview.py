"""A PNG overview of a world of bounded size, drawn tile by tile (issue 19 point 3).

Every element is drawn as its outline polygon filled with its kind's colour (the
shape's ``fill`` style when it names a ``#rrggbb`` colour, else a fixed palette), on a
canvas at most ``max_side`` pixels on its longer side. Elements smaller than a pixel
become single pixels. Memory is the canvas plus one tile.
"""

from __future__ import annotations

import io
from typing import Any

import numpy as np

__all__ = ["Overview"]

_PALETTE = ["#3b6ea5", "#c8553d", "#6a994e", "#f2a541", "#7b4b94", "#2a9d8f", "#8d6e63", "#e76f51"]


def _rgb(text: str) -> tuple[int, int, int]:
    return (int(text[1:3], 16), int(text[3:5], 16), int(text[5:7], 16))


class Overview:
    """A canvas for a ``size = (W, H)`` world; :meth:`add` draws a tile, :meth:`png` encodes.

    Parameters
    ----------
    size : (W, H) float
    max_side : int
        Pixels on the longer side.
    """

    def __init__(self, size: tuple[float, float], max_side: int = 2048) -> None:
        from PIL import Image, ImageDraw

        w, h = float(size[0]), float(size[1])
        self.px = max_side / max(w, h)
        self.shape = (max(1, round(w * self.px)), max(1, round(h * self.px)))
        self.height = h
        self.image = Image.new("RGB", self.shape, (255, 255, 255))
        self.draw = ImageDraw.Draw(self.image)
        self.colours: dict[str, tuple[int, int, int]] = {}

    def _colour(self, name: str, shape: Any) -> tuple[int, int, int]:
        if name not in self.colours:
            fill = str((getattr(shape, "style", None) or {}).get("fill", ""))
            ok = len(fill) == 7 and fill.startswith("#")
            self.colours[name] = _rgb(fill) if ok else _rgb(_PALETTE[len(self.colours) % len(_PALETTE)])
        return self.colours[name]

    def add(self, arr: Any) -> None:
        """Draw the elements of one tile (an Arrangement)."""
        if len(arr) == 0:
            return
        px, h = self.px, self.height
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
                for x, y in zip(arr.x[idx] * px, (h - arr.y[idx]) * px):
                    self.draw.point((float(x), float(y)), fill=colour)
                continue
            # the first path's outline (SVG's y runs down: flip)
            outline = shape.paths[0].points
            c = np.cos(arr.rotation[idx]) * arr.scale[idx]
            s = np.sin(arr.rotation[idx]) * arr.scale[idx]
            wx = arr.x[idx, None] + c[:, None] * outline[None, :, 0] - s[:, None] * outline[None, :, 1]
            wy = arr.y[idx, None] + s[:, None] * outline[None, :, 0] + c[:, None] * outline[None, :, 1]
            xs, ys = wx * px, (h - wy) * px
            for a, b in zip(xs, ys):
                self.draw.polygon(list(zip(a.tolist(), b.tolist())), fill=colour)

    def _add_parts(self, arr: Any) -> None:
        """Draw the elements that carry their own geometry (``parts``: ornament), every
        path of every part, filled when closed, stroked when open."""
        px, h = self.px, self.height
        for i, parts in enumerate(arr.element_parts):
            if parts is None:
                continue
            colour = self._colour(arr.kinds[arr.kind[i]], arr.shapes[arr.kinds[arr.kind[i]]])
            c, s = np.cos(arr.rotation[i]) * arr.scale[i], np.sin(arr.rotation[i]) * arr.scale[i]
            for part in parts:
                if part.radius * arr.scale[i] * px < 1.5:
                    self.draw.point((float(arr.x[i] * px), float((h - arr.y[i]) * px)), fill=colour)
                    continue
                for path in part.paths:
                    q = path.points
                    xs = (arr.x[i] + c * q[:, 0] - s * q[:, 1]) * px
                    ys = (h - (arr.y[i] + s * q[:, 0] + c * q[:, 1])) * px
                    pts = list(zip(xs.tolist(), ys.tolist()))
                    if path.closed and len(pts) >= 3:
                        self.draw.polygon(pts, fill=colour)
                    elif len(pts) >= 2:
                        self.draw.line(pts, fill=colour, width=1)

    def png(self) -> bytes:
        """The canvas as PNG bytes."""
        buf = io.BytesIO()
        self.image.save(buf, format="PNG", optimize=False)
        return buf.getvalue()
