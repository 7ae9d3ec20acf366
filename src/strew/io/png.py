"""PNG rendering of arrangements through resvg (resvg-py)."""

from __future__ import annotations

import re

from .._errors import InputError
from ..arrangement import Arrangement

__all__ = ["to_png", "svg_to_png"]


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


def to_png(arr: Arrangement, *, width: int = 1024, background: str | None = "#ffffff") -> bytes:
    """PNG bytes of an arrangement, ``width`` pixels wide."""
    from .svg import to_svg

    return svg_to_png(to_svg(arr), width=width, background=background)
