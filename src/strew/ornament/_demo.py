"""Gallery section: adaptive clip art (Wong et al. 1998), every built-in pattern on two
panels, and the skeletal strokes of Fig. 17 on one spiral design."""

from __future__ import annotations

import numpy as np
import shapely

from .._demo_item import DemoItem
from ..region import Region
from . import grow_elements


def _panels() -> list[tuple[str, str, Region]]:
    arch = shapely.Polygon(
        np.vstack([[[0, 70], [0, 30]], np.c_[30 + 30 * np.cos(np.linspace(np.pi, 0, 40)), 30 - 30 * np.sin(np.linspace(np.pi, 0, 40))], [[60, 70]]])
    )
    ring = Region(shapely.Point(35, 35).buffer(35, quad_segs=32).difference(shapely.Point(35, 35).buffer(12, quad_segs=16)))
    return [
        ("rect", "a 90 x 60 rectangle", Region.rectangle(90, 60)),
        ("arch", "an arched panel", Region(arch)),
        ("ring", "a ring (a panel with a hole)", ring),
    ]


# (pattern, style, panels, seed points per panel or None for the default)
_ITEMS = [
    ("dots", "order", ("rect", "ring"), {"rect": [(6, 54)], "ring": [(35, 5)]}),
    ("flowers", "ink", ("rect", "arch"), {}),
    ("spirals", "vine", ("rect", "arch"), {}),
    ("hierarchy", "color", ("rect", "ring"), {"ring": [(35, 4)]}),
    ("vase", "vase", ("rect", "arch"), {}),
    ("willow", "morris", ("rect", "ring"), {"ring": [(35, 4)]}),
]
# Fig. 17: one design, four skeletal strokes
_STROKES = ("skeletal", "skeletal-leafy", "skeletal-beads", "skeletal-ribbon")


def items(rng: np.random.Generator) -> list[DemoItem]:
    """Each pattern grown in two differently shaped panels from the same rule file."""
    panels = {key: (text, region) for key, text, region in _panels()}
    out = []
    for name, style, keys, seeds in _ITEMS:
        for key in keys:
            text, region = panels[key]
            orn = grow_elements(name, region, seeds=seeds.get(key), rng=int(rng.integers(2**31)))
            out.append(
                DemoItem(
                    name=f"ornament-{name}-{key}",
                    title=f"Ornament: {name} in {text}",
                    arrangement=orn.render(style),
                    description=f"{orn.pattern.description} Style '{style}'.",  # the caption gives the count
                )
            )
    text, region = panels["rect"]
    orn = grow_elements("spirals", region, rng=int(rng.integers(2**31)))
    for style in _STROKES:
        out.append(
            DemoItem(
                name=f"ornament-spirals-{style}",
                title=f"Ornament: spirals with {style} strokes",
                arrangement=orn.render(style),
                description=f"Fig. 17: the same spiral design rendered with a skeletal stroke (style '{style}').",
            )
        )
    return out
