"""Gallery section: seamless repeat tiles (issue 18), each shown as the tile and as 3 x 3 copies."""

from __future__ import annotations

import numpy as np

from .._demo_item import DemoItem
from .._resources import example_path
from ..io import load_shapes
from ..metrics import repeat_report


def _describe(arr, text: str) -> str:
    rep = repeat_report(arr)
    return (
        f"{text} {len(arr)} elements in a {rep['tile'][2]:g} x {rep['tile'][3]:g} tile; "
        f"{rep['overlaps']['across']} overlaps across the wrap, edge-strip coverage "
        f"{rep['coverage']['ratio']:.2f}x the interior's."
    )


def items(rng: np.random.Generator) -> list[DemoItem]:
    """Repeat tiles of pack, grow, synth and ornament, each drawn once and as a 3 x 3 ``<pattern>``."""
    from ..ornament import grow_ornament
    from ..pack import pack

    out = []
    leaf = load_shapes(example_path("pack", "leaf.json"))
    arr = pack(leaf, (160, 120), scale=(0.35, 0.6), periodic=True, rng=rng)
    text = _describe(arr, "Fill-gap on a torus: distances and the distance field wrap;")
    out.append(DemoItem("repeat-leaves", "Repeat tile: leaves (pack --periodic)", arr, text))
    out.append(
        DemoItem("repeat-leaves-3x3", "The leaf tile repeated 3 x 3", arr, "The same tile through an SVG <pattern>: no seam.",
                 svg_options={"repeat": (3, 3)})
    )
    from ..grow import grow
    from ..io import load
    from ..tiles import periodic

    ex = load(example_path("grow", "stones_irregular.json"))
    arr = grow(ex, (200, 200), periodic=True, rng=rng)
    text = _describe(arr, "Growth on a torus: seeds wrap, and the two fronts close the 1-rings where they meet;")
    out.append(DemoItem("repeat-grow-stones", "Repeat tile: grown stones (grow --periodic)", arr, text))
    out.append(DemoItem("repeat-grow-stones-3x3", "The grown stone tile repeated 3 x 3", arr,
                        "The same tile through an SVG <pattern>.", svg_options={"repeat": (3, 3)}))
    ex = load(example_path("synth", "grid.json"))
    arr = periodic("synth", ex, (160, 120), rng=rng)
    text = _describe(arr, "synth on a torus of 2 x 2 tiles, each grown around its neighbours across the edges;")
    out.append(DemoItem("repeat-synth-grid", "Repeat tile: synth grid (synth --periodic)", arr, text))
    out.append(DemoItem("repeat-synth-grid-3x3", "The synth tile repeated 3 x 3", arr,
                        "The same tile through an SVG <pattern>.", svg_options={"repeat": (3, 3)}))
    arr = grow_ornament("dots", (90, 60), periodic=True, rng=rng)
    text = _describe(arr, "Wong's largest empty circle searched on a torus;")
    out.append(DemoItem("repeat-dots", "Repeat tile: ornament dots (ornament --periodic)", arr, text))
    out.append(
        DemoItem("repeat-dots-3x3", "The dots tile repeated 3 x 3", arr, "Rules grow across the tile's edge into the opposite side.",
                 svg_options={"repeat": (3, 3)})
    )
    return out
