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
                                        [--harder] [--harder-variants 7,8]

With ``--harder`` the cases are ``HARDER``'s instead (labels ``h0s7``, ``h0s8`` ..., set
``harder``; variant seeds 7 and 8; ``--varied`` and ``--variants`` are then ignored):
``grow_variants.py``'s ``HARDER`` sets for the classes the two methods share (two sizes,
stones with ``aspect``, three sizes, clusters; same order, same labels), then sets of
rings, clusters, stripes and sparse voids no audit has (other ring spacings, tile counts
and hub sizes; crowded and far clusters; narrow, wide, turned and dense stripes). Every
set is a valid exemplar at variant seeds 7 and 8 (no overlapping pair). JSON:
``synth_variants_harder.json``.

``--harder-variants 9,10`` draws the same ``HARDER`` sets at other variant seeds (default
7,8: the rows above; implies ``--harder``): fresh held-out exemplars nobody tuned on
(helper syn15, issue 13 point 1). Labels keep the form ``h{set}s{variant seed}``.

``--varied-variants 9,10`` draws the ``VARIED`` and ``EDGE`` sets at other variant seeds
(default 7,8: the ``--varied`` rows; implies ``--varied``; labels ``p0s9``, ``p0s10`` ...; helper
fresh17). ``benchmarks/fresh17_rows.py`` reruns such rows at more seeds.
"""

from __future__ import annotations

import sys
from typing import Any

import _variants
from _variants import audit, ints

from strew import Arrangement, Region
from strew.synth import synthesize


def run(ex: Arrangement, scale: float, seed: int, args: Any) -> tuple[Arrangement, float]:
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(scale * (x1 - x0), scale * (y1 - y0))
    return synthesize(ex, region, rng=seed, measure=False), scale


def options(p: Any) -> None:
    p.add_argument("--harder", action="store_true", help="the HARDER parameter sets instead of the audit's (variant seeds 7, 8)")
    p.add_argument("--harder-variants", default="7,8", help="variant seeds of the HARDER sets (default 7,8; others imply --harder)")


def _harder() -> dict[str, list[dict[str, Any]]]:
    """grow's HARDER sets (labels shared), then synth's own (helper svar13i, issue 13 point 1)."""
    from grow_variants import HARDER as GROW_HARDER

    own: dict[str, list[dict[str, Any]]] = {
        "rings": [
            dict(tiles=12, radius=18.0, hub=7.0, spacing=46.0),  # tight rings of twelve (gap 4 between rings)
            dict(tiles=8, radius=14.0, hub=6.0, spacing=38.0),  # rings nearly touching (gap 4)
            dict(tiles=16, radius=22.0, hub=10.0, spacing=56.0),  # large rings of sixteen, big hubs
            dict(tiles=10, radius=15.0, hub=5.0, spacing=60.0),  # far-apart rings (gap 24)
            dict(tiles=5, radius=10.0, hub=4.5, spacing=30.0),  # small rings of five
            dict(tiles=12, radius=16.0, hub=9.0, spacing=42.0, noise=0.02),  # big hubs, hubs off the lattice
        ],
        "clusters": [
            dict(cluster_spacing=40.0, ring_min=5, ring_max=6, ring_gap=0.8),  # crowded full clusters
            dict(large=5.0, small=2.0, cluster_spacing=30.0, ring_min=4, ring_max=5),  # many small clusters
            dict(large=14.0, small=4.0, cluster_spacing=84.0, ring_min=6, ring_max=8),  # few big clusters
        ],
        "stripes": [
            dict(band=18.0, angle=0.7),  # narrow bands turned 40 degrees
            dict(band=36.0, angle=-0.5, count=140),  # wide sparse bands turned the other way
            dict(dot=2.0, bar=(7.0, 2.0), count=400, gap=1.5),  # small dense elements
            dict(band=22.0, angle=1.1, dot=4.0, bar=(10.0, 4.0), count=160),  # large elements, steep bands
        ],
        "sparse_voids": [
            dict(spacing=36.0, apple=7.0, void=5.0, void_spacing=13.0),  # large sparse apples
            dict(spacing=22.0, apple=4.0, void=2.5, void_spacing=7.0),  # small crowded apples, fine voids
        ],
    }
    out = {n: list(v) for n, v in GROW_HARDER.items()}
    for n, v in own.items():
        out.setdefault(n, []).extend(v)
    return out


HARDER_VARIANTS = (7, 8)


def _harder_cases(name: str, variants: list[int], varied: bool) -> list[tuple[str, str, int, dict[str, Any]]]:
    return [(f"h{i}s{s}", "harder", s, kw) for i, kw in enumerate(_harder().get(name, [])) for s in HARDER_VARIANTS]


def _harder_variants(argv: list[str]) -> tuple[int, ...] | None:
    """The ``--harder-variants`` seeds named on the command line (None when absent)."""
    for i, a in enumerate(argv):
        if a == "--harder-variants" and i + 1 < len(argv):
            return tuple(ints(argv[i + 1]))
        if a.startswith("--harder-variants="):
            return tuple(ints(a.split("=", 1)[1]))
    return None


if __name__ == "__main__":
    hv = _harder_variants(sys.argv)
    if hv is not None:
        HARDER_VARIANTS = hv
        if "--harder" not in sys.argv:
            sys.argv.append("--harder")
    if "--harder" in sys.argv:  # the audit's own cases and suite stay as they are without the flag
        from grow_variants import _harder_suite

        _variants.cases = _harder_cases
        _variants.fidelity_suite = _harder_suite
    audit(lambda a: "synth_variants" + ("_harder" if a.harder else ""), "synth", run, __doc__, options=options, default_skip=("sticks",))
