"""Gallery section: region-growing synthesis (Davison et al.) from the benchmark exemplars
and a two-scale scene painted from a palette."""

from __future__ import annotations

import numpy as np

from .._demo_item import DemoItem
from ..region import Region
from ._api import new_state, set_selection, synthesize
from ._exemplars import EXEMPLARS, stones
from ._grow import fill
from ._palette import Palette


def items(rng: np.random.Generator) -> list[DemoItem]:
    """One output per benchmark exemplar, shown beside its exemplar, and a two-scale scene."""
    out: list[DemoItem] = []
    region = Region.rectangle(260, 200)
    for name, make in EXEMPLARS.items():
        ex = make()
        seed = int(rng.integers(2**31))
        arr = synthesize(ex, region, rng=seed)
        d = arr.meta["synth"]["average_neighborhood_distance"]
        out.append(DemoItem(name=f"synth-exemplar-{name}", title=f"Exemplar: {name}", arrangement=ex.with_meta(), description=f"{len(ex)} elements" + (f", {int(ex['void'].sum())} of them void elements (§5.6), invisible when drawn" if "void" in ex else "") + "."))
        out.append(
            DemoItem(
                name=f"synth-{name}",
                title=f"Region growing: {name}",
                arrangement=arr,
                description=f"Filled from the centre with horizon optimisation; average neighbourhood distance {d:.3g}." + (" Void elements steered growth and are hidden." if name == "apples" else ""),
            )
        )
    # Two scales from one palette (§4.1, Fig. 3): stones first, then pebbles in the gaps.
    pal = Palette({"stones": stones(1.0), "pebbles": stones(0.25, size=60)})
    scene = Region.rectangle(220, 160)
    st = new_state(pal, scene, selection="stones", rng=int(rng.integers(2**31)))
    fill(st)
    set_selection(st, "pebbles")
    probe = np.mgrid[4:220:4, 4:160:4].reshape(2, -1).T.astype(float)
    for _ in range(6):  # the filler, clicked into the largest remaining gaps
        d = np.min(np.hypot(*(probe[:, None, :] - st.pos[None, :, :]).transpose(2, 0, 1)), axis=1)
        if d.max() < 6.0:
            break
        fill(st, tuple(probe[np.argmax(d)]))
    arr = st.to_arrangement()
    out.append(
        DemoItem(
            name="synth-two-scales",
            title="Two scales from one palette",
            arrangement=arr,
            description=f"{arr.counts().get('stone', 0)} stones, then {arr.counts().get('pebble', 0)} pebbles filled into the gaps; each element keeps its exemplar's radii.",
        )
    )
    out.append(DemoItem(name="synth-palette", title="The palette", arrangement=pal.to_arrangement(), description="stones and pebbles side by side (a saved palette document)."))
    return out


__all__ = ["items"]
