"""SVG import (``.svg`` and gzip-compressed ``.svgz``) and export of arrangements, shapes and regions."""

from __future__ import annotations

from ._svg_export import path_data, to_svg
from ._svg_curves import read_svg_curves
from ._svg_import import SVGImportWarning, read_svg, read_svg_region, read_svg_shapes

__all__ = ["to_svg", "path_data", "read_svg", "read_svg_shapes", "read_svg_region", "read_svg_curves", "SVGImportWarning"]
