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
                                       [--harder] [--harder-variants 7,8]

With ``--harder`` the cases are ``HARDER``'s instead (labels ``h0s7``, ``h0s8`` ...,
set ``harder``; variant seeds 7 and 8; ``--varied`` and ``--variants`` are then ignored):
parameter sets no other audit has (size ratios 0.4-0.8, densities, 20-120 elements,
stretched stones, uneven shares of three sizes). JSON: ``grow_variants_harder.json``.
``--harder-variants 9,10`` draws the same sets at other variant seeds (default 7,8:
the rows above; labels then ``h0s9``, ``h0s10`` ...): a held-out check that nobody has
tuned on (helper grw15).

``--varied-variants 9,10`` draws the ``VARIED`` and ``EDGE`` sets at other variant seeds
(default 7,8: the ``--varied`` rows; implies ``--varied``; labels ``p0s9``, ``p0s10`` ...; helper
fresh17). ``benchmarks/fresh17_rows.py`` reruns such rows at more seeds.
"""

from __future__ import annotations

import functools
import math
import sys
from typing import Any

import _variants
from _runner import fidelity_suite
from _variants import audit

from strew import Arrangement, Region
from strew.grow import grow


def options(p: Any) -> None:
    p.add_argument("--mode", default="fixed", choices=["fixed", "rotate"], help="grow's mode (JSON: grow_variants.json, grow_variants_rotate.json)")
    p.add_argument("--times", type=float, default=10.0, help="least output count / exemplar count: the region is enlarged once to reach it")
    p.add_argument("--harder", action="store_true", help="the HARDER parameter sets instead of the audit's (variant seeds 7, 8)")
    p.add_argument("--harder-variants", default="7,8", help="with --harder: the variant seeds each set is drawn at (default 7,8)")


# Cases no audit set has (helper gvar14g, issue 14 point 1): where hidden exemplars of the
# multi-size and stone classes may bite. ``aspect`` (stones only) stretches the stone
# outline (make.py's ``_stone`` draws aspect 0.8).
# Helper gvar14i appended 12 sets (two sizes h8-h12, three sizes h7-h13):
# ``benchmarks/gvar14i_harder_extra.py`` runs them alone.
HARDER: dict[str, list[dict[str, Any]]] = {
    "two_sizes": [
        dict(ratio=0.45, n_large=60, n_small=200),
        dict(ratio=0.5, n_large=50, n_small=150),
        dict(ratio=0.55, n_large=45, n_small=140),
        dict(ratio=0.7, n_large=40, n_small=100),
        dict(ratio=0.8, n_large=50, n_small=80),
        dict(ratio=0.6, n_large=25, n_small=250),  # many pebbles among few stones
        dict(ratio=0.5, size=120.0, n_large=12, n_small=40),  # about 50 elements
        dict(ratio=0.4, n_large=100, n_small=60),  # pebbles a minority
        # (helper gvar14i: kinds of one size level, ratio over 1 / 1.5, few pebbles; and
        # uneven shares)
        dict(ratio=0.75, n_large=60, n_small=40),
        dict(ratio=0.85, n_large=40, n_small=120),
        dict(ratio=0.7, n_large=80, n_small=20),
        dict(ratio=0.65, n_large=30, n_small=150),
        dict(ratio=0.5, n_large=80, n_small=80),
    ],
    "stones": [
        dict(count=20, size=120.0),  # about 20 stones
        dict(count=60),  # sparse
        dict(count=120, spread=0.35),
        dict(radius=8.0, count=300),  # saturated
        dict(aspect=0.45),  # stretched stones
        dict(aspect=0.6, spread=0.3),
        dict(aspect=0.35, count=100),
        dict(gap=3.0, count=200),  # wide gaps
    ],
    "three_sizes": [
        dict(counts=(300, 20, 10)),  # small stones dominate
        dict(counts=(40, 100, 20)),  # medium the majority
        dict(counts=(60, 30, 40)),  # many large
        dict(ratios=(1.0, 1.5, 3.0), counts=(150, 80, 30)),
        dict(ratios=(1.0, 2.5, 4.0), counts=(100, 100, 15)),
        dict(small=3.0, ratios=(1.0, 2.0, 6.0), counts=(200, 40, 6)),
        dict(size=150.0, counts=(80, 20, 30)),  # about 100 elements
        # (helper gvar14i: the medium stones a majority or a minority beside the large
        # ones, and medium and large of one size level)
        dict(counts=(20, 120, 20)),
        dict(counts=(100, 150, 10)),
        dict(counts=(30, 60, 60)),
        dict(ratios=(1.0, 1.8, 2.6), counts=(60, 120, 30)),  # medium and large one level
        dict(ratios=(1.0, 3.0, 4.5), counts=(80, 80, 30)),
        dict(counts=(400, 15, 15)),
        dict(counts=(200, 60, 5)),
    ],
    "clusters": [
        dict(large=10.0, small=5.0, ring_min=3, ring_max=4),  # ring discs half the centre's size
        dict(ring_min=2, ring_max=3, cluster_spacing=44.0),  # sparse rings
    ],
}


def _harder_cases(name: str, variants: list[int], varied: bool, seeds: tuple[int, ...] = (7, 8)) -> list[tuple[str, str, int, dict[str, Any]]]:
    return [(f"h{i}s{s}", "harder", s, kw) for i, kw in enumerate(HARDER.get(name, [])) for s in seeds]


def _harder_variants(argv: list[str]) -> tuple[int, ...]:
    """``--harder-variants`` read before the audit parses its arguments (the cases are chosen first)."""
    for i, a in enumerate(argv):
        if a.startswith("--harder-variants="):
            return tuple(_variants.ints(a.split("=", 1)[1]))
        if a == "--harder-variants" and i + 1 < len(argv):
            return tuple(_variants.ints(argv[i + 1]))
    return (7, 8)


def _harder_suite() -> Any:
    """The fidelity suite's maker whose ``stones`` also takes ``aspect`` (the outline's y/x)."""
    mk = fidelity_suite()
    plain, stone = mk.EXEMPLARS["stones"], mk._stone

    def stones(rng: Any = None, *, aspect: float = 0.8, **kw: Any) -> Any:
        mk._stone = functools.partial(stone, aspect=aspect)
        try:
            return plain(rng, **kw)
        finally:
            mk._stone = stone

    mk.EXEMPLARS["stones"] = stones
    return mk


def run(ex: Arrangement, scale: float, seed: int, args: Any) -> tuple[Arrangement, float]:
    x0, y0, x1, y1 = ex.region.bounds
    for _ in range(2):
        out = grow(ex, region=Region.rectangle(scale * (x1 - x0), scale * (y1 - y0)), mode=args.mode, rng=seed)
        if len(out) >= args.times * len(ex):
            break
        scale *= 1.05 * math.sqrt(args.times * len(ex) / max(len(out), 1))
    return out, scale


if __name__ == "__main__":
    harder = "--harder" in sys.argv
    if harder:  # the audit's own cases and suite stay as they are without the flag
        _variants.cases = functools.partial(_harder_cases, seeds=_harder_variants(sys.argv[1:]))
        _variants.fidelity_suite = _harder_suite
    audit(lambda a: ("grow_variants" if a.mode == "fixed" else f"grow_variants_{a.mode}") + ("_harder" if a.harder else ""), lambda a: f"grow:{a.mode}", run, __doc__, options=options)
