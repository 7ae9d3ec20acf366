"""Issue 13 point 1 on exemplars nobody tuned on: synth on untuned variants of the
fidelity suite's classes.

Each case draws an exemplar with ``make_exemplar(name, rng=VARIANT, **variation)``
(``examples/fidelity/make.py``): the default parameters at other seeds (``--variants``),
and, with ``--varied``, other sizes, ratios, densities and counts (``VARIED`` and the
audit's ``EDGE`` sets in ``_variants.py``). Each fills a rectangle ``--scale`` times the
frame's side (default 3.5: about 12x the area, as ``benchmarks/fidelity.py``) for every
seed, and ``strew.metrics.fidelity`` judges it. Printed: one line per run (verdict,
failing metrics as value/tolerance, CPU seconds), then the pass count per class and in
all. There is no baseline method: the figure is the pass rate, compared before/after a
change by running this script on both. Sticks (synth takes about 40 s each) only with
``--only``.

    python benchmarks/synth_variants.py [--only NAME,...] [--variants 1-3] [--seeds 1-2]
                                        [--varied] [--scale 3.5] [--summary PATH]
"""

from __future__ import annotations

from typing import Any

from _variants import audit

from strew import Arrangement, Region
from strew.synth import synthesize


def run(ex: Arrangement, scale: float, seed: int, args: Any) -> tuple[Arrangement, float]:
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(scale * (x1 - x0), scale * (y1 - y0))
    return synthesize(ex, region, rng=seed, measure=False), scale


if __name__ == "__main__":
    audit("synth_variants", "synth", run, __doc__, default_skip=("sticks",))
