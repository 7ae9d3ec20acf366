"""Gallery section: example-based growth (Ijiri et al. 2008), the paper's Fig. 8 classes
(regular, near-regular, irregular), a flow-field example (Fig. 9e-f) and the spray and
boundary tools (Fig. 1)."""

from __future__ import annotations

import numpy as np

from .._resources import example_path
from .._demo_item import DemoItem
from ..fields import flow_field
from ..io import load
from ..region import Region
from . import grow
from ._tools import load_strokes


def items(rng: np.random.Generator) -> list[DemoItem]:
    """Six pictures, a few seconds in all."""
    out: list[DemoItem] = []
    region = Region.rectangle(320, 220)
    classes = [
        ("regular", "scales.svg", "Regular: a hexagonal lattice of scales grows into a lattice.", {}),
        ("near-regular", "tiles.svg", "Near-regular: tiles with small random scale, rotation and colour noise (§3).",
         {"jitter_scale": 0.04, "jitter_rotation": np.radians(3), "jitter_color": 0.08}),
        ("irregular", "stones.svg", "Irregular uniform: stones keep their neighbourhoods, in rotate mode (§5.3).", {"mode": "rotate"}),
    ]
    for name, file, text, kw in classes:
        ex = load(example_path("exemplars", file))
        arr = grow(ex, region=region, rng=rng, **kw)
        out.append(DemoItem(f"grow-{name}", f"grow: {name} ({file})", arr, text))
    strokes = load_strokes(example_path("grow", "flow_strokes.json"))
    scales = load(example_path("exemplars", "scales.svg"))
    arr = grow(scales, region=Region.rectangle(300, 220), mode="flow", flow=flow_field(strokes), rng=rng)
    arr = arr.replace(extra={**arr.extra, "guides": _guides(strokes)})  # drawn over the picture
    out.append(DemoItem("grow-flow", "grow: scales following strokes", arr,
                        "Flow mode (§5.3): two wavy strokes, interpolated by radial basis functions, turn the scales."))
    spray = load_strokes(example_path("grow", "spray_path.json"))[0]
    arr = grow(load(example_path("exemplars", "leaves.svg")), spray=spray, spray_radius=30, rng=rng, mode="rotate")
    arr = arr.replace(extra={**arr.extra, "guides": _guides([spray])})
    out.append(DemoItem("grow-spray", "grow: spray tool", arr, "Only seeds within 30 units of a zigzag path grow (Fig. 1c)."))
    walls = load_strokes(example_path("grow", "boundary_stroke.json"))
    arr = grow(load(example_path("grow", "tiles_near_regular.json")), region=Region.rectangle(300, 220),
               boundary=walls, rng=rng)
    arr = arr.replace(extra={**arr.extra, "guides": _guides(walls)})
    out.append(DemoItem("grow-boundary", "grow: boundary strokes", arr, "Two strokes stop the growth (Fig. 1f)."))
    return out


def _guides(strokes) -> list:
    """Tool strokes as plain lists for ``extra["guides"]`` (drawn dashed over the picture)."""
    return [np.asarray(s, dtype=float).reshape(-1, 2).tolist() for s in strokes]
