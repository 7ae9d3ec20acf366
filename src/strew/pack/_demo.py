"""Gallery section for ``strew demo``: packings by the fill-gap method (Sakurai & Miyata)."""

from __future__ import annotations

import numpy as np

from .._resources import example_path
from .._demo_item import DemoItem
from ..io import load_region, load_shapes
from ..metrics import coverage
from ._pack import pack


def _describe(arr, text: str) -> str:
    return f"{text} {len(arr)} elements, coverage {100 * coverage(arr):.0f}%, {arr.meta['pack']['trials']} trials."


def items(rng: np.random.Generator) -> list[DemoItem]:
    """Fig. 1(b)-like aggregate of concave kinds in a region with a hole; trees scaled
    0.2-1.0 (Fig. 13(d)); density set by the exclusive region's margin (Fig. 14)."""
    region = load_region(example_path("pack", "blob_with_hole.json"))
    stones = load_shapes(example_path("pack", "stones.json"))
    out = []
    arr = pack(stones, region, scale=(0.55, 0.75), rng=rng)
    out.append(
        DemoItem(
            "pack-stones",
            "Pack: concave kinds around a hole",
            arr,
            _describe(arr, "Fill-gap with a ring (with a hole), a hook and a crescent, placed cyclically;"),
        )
    )
    trees = load_shapes(example_path("pack", "trees.json"))
    arr = pack(trees, (450, 300), scale=(0.2, 1.0), rotation=(-0.15, 0.15), rng=rng)
    out.append(
        DemoItem("pack-trees", "Pack: trees scaled 0.2-1.0", arr, _describe(arr, "Two tree kinds, upright within ±9°;"))
    )
    leaf = load_shapes(example_path("pack", "leaf.json"))
    for margin in (0.0, 6.0):
        arr = pack(leaf, (400, 300), margin=margin, rng=rng)
        out.append(
            DemoItem(
                f"pack-margin-{margin:g}",
                f"Pack: exclusive region grown by {margin:g}",
                arr,
                _describe(arr, f"Elongated leaves, margin {margin:g} (density control, Fig. 14);"),
            )
        )
    return out
