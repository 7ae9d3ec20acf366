"""PNG rendering of arrangements through resvg (resvg-py)."""

from __future__ import annotations

import re

from .._errors import InputError
from ..arrangement import Arrangement

__all__ = ["to_png", "svg_to_png", "tile_pixels"]


_UNIT_PX = {"px": 1.0, "": 1.0, "mm": 96 / 25.4, "cm": 96 / 2.54, "in": 96.0, "pt": 96 / 72, "pc": 16.0}
_ROOT = re.compile(r"<svg\b[^>]*>", re.S)
_SIZE = re.compile(r"""\b(width|height)\s*=\s*(["'])\s*([0-9.eE+-]+)\s*([a-z%]*)\s*\2""")


def _px_size(svg: str) -> str:
    """Rewrite the root's width/height in mm, cm, in, pt or pc as px (96 dpi), and drop
    percentages: resvg-py refuses such sizes ("invalid size"), Inkscape writes mm."""
    m = _ROOT.search(svg)
    if m is None:
        return svg

    def fix(a: re.Match[str]) -> str:
        unit = a.group(4).lower()
        if unit == "%":
            return ""
        if unit not in _UNIT_PX:
            return a.group(0)
        try:
            value = float(a.group(3)) * _UNIT_PX[unit]
        except ValueError:
            return a.group(0)
        return f'{a.group(1)}="{value:.6g}"'

    tag = _SIZE.sub(fix, m.group(0))
    return svg[: m.start()] + tag + svg[m.end() :]


def svg_to_png(svg: str, *, width: int = 1024, background: str | None = "#ffffff") -> bytes:
    """Rasterise SVG text to PNG bytes at ``width`` pixels."""
    import resvg_py

    if width <= 0:
        raise InputError(f"width: must be positive, got {width}")
    try:
        return bytes(resvg_py.svg_to_bytes(svg_string=_px_size(svg), width=int(width), background=background, skip_system_fonts=True))
    except ValueError as exc:
        raise InputError(f"cannot render SVG: {exc}") from None


def tile_pixels(tile: tuple[float, float, float, float], width: int, repeat: tuple[int, int] = (1, 1)) -> tuple[int, int]:
    """Whole pixels of one tile for a PNG about ``width`` pixels wide holding ``repeat``
    copies across: ``(round(width / n), round(that * H / W))``, each at least 1.

    The pixels are square to within half a pixel over the tile's height.
    """
    _, _, w, h = tile
    tpx = max(1, int(round(width / repeat[0])))
    return tpx, max(1, int(round(tpx * h / w)))


def to_png(arr: Arrangement, *, width: int = 1024, background: str | None = "#ffffff", repeat: object = None) -> bytes:
    """PNG bytes of an arrangement, ``width`` pixels wide.

    A periodic arrangement (``meta["periodic"]``, issue 18) gives a seamless tile: the
    tile maps to whole pixels (:func:`tile_pixels`; the width is rounded to a multiple of
    the tile's) and is drawn through an SVG ``<pattern>``, so its left and right, top and
    bottom edges continue each other pixel for pixel. ``repeat=(n, m)`` (or ``"NxM"``)
    shows ``n x m`` copies, e.g. a 3 x 3 preview; it needs a periodic arrangement.
    """
    from .._periodic import frame
    from ._svg_export import _repeat_counts
    from .svg import to_svg

    if width <= 0:
        raise InputError(f"width: must be positive, got {width}")
    tile = frame(arr)
    counts = None if repeat is None else _repeat_counts(repeat)
    if tile is None:
        if counts is not None:
            raise InputError("repeat: the arrangement is not periodic (no meta.periodic); make it with periodic=True")
        return svg_to_png(to_svg(arr), width=width, background=background)
    counts = counts or (1, 1)
    px = tile_pixels(tile, width, counts)
    svg = to_svg(arr, repeat=counts, tile_pixels=px)
    return svg_to_png(svg, width=px[0] * counts[0], background=background)
