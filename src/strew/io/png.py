"""PNG rendering of arrangements through resvg (resvg-py)."""

from __future__ import annotations

from .._errors import InputError
from ..arrangement import Arrangement

__all__ = ["to_png", "svg_to_png"]


def svg_to_png(svg: str, *, width: int = 1024, background: str | None = "#ffffff") -> bytes:
    """Rasterise SVG text to PNG bytes at ``width`` pixels."""
    import resvg_py

    if width <= 0:
        raise InputError(f"width: must be positive, got {width}")
    try:
        return bytes(resvg_py.svg_to_bytes(svg_string=svg, width=int(width), background=background, skip_system_fonts=True))
    except ValueError as exc:
        raise InputError(f"cannot render SVG: {exc}") from None


def to_png(arr: Arrangement, *, width: int = 1024, background: str | None = "#ffffff") -> bytes:
    """PNG bytes of an arrangement, ``width`` pixels wide."""
    from .svg import to_svg

    return svg_to_png(to_svg(arr), width=width, background=background)
