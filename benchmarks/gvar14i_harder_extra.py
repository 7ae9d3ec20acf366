"""The HARDER sets helper gvar14i appended to ``grow_variants.py`` (issue 14 point 1),
alone: two sizes h8-h12 (kinds of one size level at ratios 0.7-0.85, few pebbles, uneven
shares) and three sizes h7-h13 (medium stones a majority or a minority beside the large
ones; medium and large of one level). Same cases, runs, judge, output lines and JSON
fields as ``python benchmarks/grow_variants.py --harder`` (variant seeds 7 and 8, grow
seeds ``--seeds``); the figure is the pass rate, compared before/after a change by running
this on both trees (``PYTHONPATH=<tree>/src``).

    python benchmarks/gvar14i_harder_extra.py [--seeds 1-2] [--json PATH]

JSON: ``benchmarks/results/gvar14i_harder_extra.json``.
"""

from __future__ import annotations

import sys
from typing import Any

import _variants
import grow_variants as gv
from _variants import audit

#: per class, the first HARDER index appended by gvar14i
FIRST = {"two_sizes": 8, "three_sizes": 7}


def _extra_cases(name: str, variants: list[int], varied: bool) -> list[tuple[str, str, int, dict[str, Any]]]:
    first = FIRST.get(name)
    if first is None:
        return []
    return [(f"h{i}s{s}", "harder", s, kw) for i, kw in enumerate(gv.HARDER.get(name, [])) if i >= first for s in (7, 8)]


if __name__ == "__main__":
    _variants.cases = _extra_cases
    _variants.fidelity_suite = gv._harder_suite
    if "--only" not in sys.argv:
        sys.argv += ["--only", ",".join(FIRST)]
    audit("gvar14i_harder_extra", "grow:fixed", gv.run, __doc__, options=gv.options)
