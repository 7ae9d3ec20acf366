"""Gallery section: the exemplars drawn for strew, imported from Inkscape-style SVG."""

from __future__ import annotations

import numpy as np

from .._resources import examples_dir
from .._demo_item import DemoItem
from ..io import load


def items(rng: np.random.Generator) -> list[DemoItem]:
    """One picture per exemplar in ``examples/exemplars`` (imported, then re-exported)."""
    out = []
    for path in sorted((examples_dir() / "exemplars").glob("*.svg")):
        arr = load(path)
        kinds = ", ".join(f"{k} x{c}" for k, c in arr.counts().items())
        out.append(
            DemoItem(
                name=f"exemplar-{path.stem}",
                title=f"Exemplar: {path.stem}",
                arrangement=arr,
                description=f"{path.name} drawn with clones, imported as {kinds}.",
            )
        )
    return out
