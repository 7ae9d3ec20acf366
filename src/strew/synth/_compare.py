"""Average neighbourhood distance against time for several methods (§6.4, Fig. 17)."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import numpy as np

from ..region import Region

__all__ = ["compare_methods", "plot_traces"]

VARIANTS = (
    ("region growing, horizon optimisation", {"init": "grow", "optimize": "horizon"}),
    ("region growing, no optimisation", {"init": "grow", "optimize": "none"}),
    ("region growing, global optimisation", {"init": "grow", "optimize": "global"}),
    ("patch initialisation + global optimisation", {"init": "patch"}),
)


def compare_methods(exemplars: Any, region: Region, *, selection: Any = None, rng: int = 0, global_opt: bool = True, **params: Any) -> dict[str, list[tuple[float, int, float]]]:
    """Traces ``(seconds, elements, Eq. 5)`` of the variants of §6.4 on one region.

    Patch initialisation gets as much time as the longest region-growing variant, as
    in the paper.
    """
    from ._api import synthesize

    traces: dict[str, list[tuple[float, int, float]]] = {}
    longest = 0.0
    for label, v in VARIANTS:
        if v["init"] == "patch":
            continue
        if v["optimize"] == "global" and not global_opt:
            continue
        tr: list[tuple[float, int, float]] = []
        synthesize(exemplars, region, selection=selection, rng=rng, trace=tr, measure=False, **v, **params)
        traces[label] = tr
        longest = max(longest, tr[-1][0] if tr else 0.0)
    tr = []
    synthesize(exemplars, region, selection=selection, rng=rng, trace=tr, init="patch", time_budget=max(longest, 1e-3), measure=False, **params)
    traces[VARIANTS[-1][0]] = tr
    return traces


def plot_traces(traces: dict[str, list[tuple[float, int, float]]], path: str | os.PathLike[str], title: str = "") -> Path:
    """Draw average neighbourhood distance against time (Fig. 17) into a PNG, atomically."""
    import io

    import matplotlib

    matplotlib.use("Agg", force=False)
    from matplotlib.figure import Figure

    from ..io import atomic_write

    fig = Figure(figsize=(7, 4.2), dpi=110)
    ax = fig.add_subplot(1, 1, 1)
    for label, tr in traces.items():
        if not tr:
            continue
        a = np.asarray(tr, float)
        ax.plot(a[:, 0], a[:, 2], marker=".", label=f"{label} ({int(a[-1, 1])} el.)")
    ax.set_xlabel("time (s)")
    ax.set_ylabel("average neighbourhood distance (Eq. 5)")
    ax.set_title(title or "Davison et al. §6.4: lower is better")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    buf = io.BytesIO()
    fig.savefig(buf, format="png")
    return atomic_write(path, buf.getvalue())
