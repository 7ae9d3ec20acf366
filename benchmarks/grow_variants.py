"""Issue 14 point 1 on exemplars nobody tuned on: grow (fixed mode; --mode rotate) on untuned variants
of the fidelity suite's classes.

The cases are ``synth_variants.py``'s (``_variants.py``): ``make_exemplar(name,
rng=VARIANT, **variation)`` at the default parameters and other seeds (``--variants``)
and, with ``--varied``, the ``VARIED`` and ``EDGE`` parameter sets. ``grow(exemplar,
region=..., mode=--mode, rng=seed)`` fills a rectangle ``--scale`` times the frame's side
(as ``benchmarks/fidelity.py``); where that gives fewer than ``--times`` (10) x the
exemplar's element count, the rectangle is enlarged once to reach it (the printed ``x``
is the count ratio). ``strew.metrics.fidelity`` judges each output. Printed: one line
per run (verdict, failing metrics as value/tolerance, CPU seconds), the pass count per
class and in all; JSON to ``benchmarks/results/grow_variants.json``. No baseline method:
the figure is the pass rate, compared before/after a change by running this on both.

    python benchmarks/grow_variants.py [--only NAME,...] [--variants 1-3] [--seeds 1-2]
                                       [--varied] [--scale 3.5] [--summary PATH]
                                       [--mode fixed|rotate] [--times 10]
"""

from __future__ import annotations

import math
from typing import Any

from _variants import audit

from strew import Arrangement, Region
from strew.grow import grow


def options(p: Any) -> None:
    p.add_argument("--mode", default="fixed", choices=["fixed", "rotate"], help="grow's mode (JSON: grow_variants.json, grow_variants_rotate.json)")
    p.add_argument("--times", type=float, default=10.0, help="least output count / exemplar count: the region is enlarged once to reach it")


def run(ex: Arrangement, scale: float, seed: int, args: Any) -> tuple[Arrangement, float]:
    x0, y0, x1, y1 = ex.region.bounds
    for _ in range(2):
        out = grow(ex, region=Region.rectangle(scale * (x1 - x0), scale * (y1 - y0)), mode=args.mode, rng=seed)
        if len(out) >= args.times * len(ex):
            break
        scale *= 1.05 * math.sqrt(args.times * len(ex) / max(len(out), 1))
    return out, scale


if __name__ == "__main__":
    audit(lambda a: "grow_variants" if a.mode == "fixed" else f"grow_variants_{a.mode}", lambda a: f"grow:{a.mode}", run, __doc__, options=options)
