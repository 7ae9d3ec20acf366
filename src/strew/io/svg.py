"""SVG import (svgelements) and export of arrangements, shapes and regions."""

from __future__ import annotations

from ._svg_export import path_data, to_svg

__all__ = ["to_svg", "path_data"]
