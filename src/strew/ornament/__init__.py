"""Adaptive clip art: rule-driven floral ornament that fills any panel.

Implements Wong, Zongker and Salesin, *Computer-Generated Floral Ornament*, SIGGRAPH
1998. A pattern (the paper's rule file, here plain Python) declares element types with
proxies (§3.2, §4.2) and growth rules; the framework (§4.1) repeatedly finds the largest
empty circle adjacent to the ornament and asks nearby elements' rules to grow into it.
The geometry is then rendered in a named style (§4, Fig. 17).

Entry points: :func:`grow_ornament` (Arrangement out) and :func:`grow_elements`
(elements and proxies out, render later with :meth:`Ornament.render`).

Examples
--------
>>> from strew import Region
>>> from strew.ornament import grow_ornament
>>> arr = grow_ornament("dots", Region.rectangle(40, 30), rng=1)
>>> bool(set(arr["type"]) == {"dot"})
True
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from .._method import MethodSpec, Param
from ..arrangement import Arrangement
from ..region import Region
from ._engine import Goal, Ornament, RuleContext, default_seed, grow_elements
from ._pattern import BUILTIN_PATTERNS, FAILURE, SUCCESS, Element, ElementType, Pattern, Phase, Rule, load_pattern
from ._proxies import (
    Arc,
    Bezier,
    Circle,
    LineSegment,
    Point,
    Polygon,
    Proxy,
    Segment,
    angle_of,
    distance,
    offset,
    polar,
    unit,
    vec,
)
from ._render import GENERIC_STYLES, Mark, RenderContext, available_styles, render_ornament, skeletal_stroke, tapered_stroke

__all__ = [
    "SPEC",
    "grow_ornament",
    "grow_elements",
    "render_ornament",
    "Ornament",
    "Pattern",
    "Phase",
    "ElementType",
    "Element",
    "Rule",
    "Goal",
    "RuleContext",
    "SUCCESS",
    "FAILURE",
    "BUILTIN_PATTERNS",
    "load_pattern",
    "default_seed",
    "Proxy",
    "Point",
    "Circle",
    "Arc",
    "Segment",
    "LineSegment",
    "Bezier",
    "Polygon",
    "vec",
    "angle_of",
    "polar",
    "offset",
    "distance",
    "unit",
    "Mark",
    "RenderContext",
    "GENERIC_STYLES",
    "available_styles",
    "tapered_stroke",
    "skeletal_stroke",
]


SPEC = MethodSpec(
    name="ornament",
    command="ornament",
    entry="strew.ornament:grow_ornament",
    paper="Wong, Zongker, Salesin, Computer-Generated Floral Ornament, SIGGRAPH 1998",
    summary="Grow rule-driven floral ornament into a panel (adaptive clip art).",
    progress_message="ornament",
    renamed={"resolution": "cells"},
    input=Param("pattern", "any", help="A Pattern, a built-in name or the path of a Python rule file.", section="§3, App. A",
                parse="text", metavar="PATTERN_OR_RULE_FILE"),
    params=(
        Param("seeds", "points", None, unit="document units", help="Seed points [default: the centre of the largest inscribed circle].",
              flag="--seed-point", cli="multiple", parse="points", metavar="X,Y",
              cli_help="Seed position (repeatable); default: the centre of the largest inscribed circle.", section="§4.2"),
        Param("cells", "int", None, low=1, unit="cells",
              help="Raster cells along the panel's longer side [default: cells of half the minimum radius, 256 to 2048].", section="§4.1"),
        Param("min_radius", "float", None, low=0, low_open=True, unit="document units",
              help="Stop when no empty circle is this large [default: the pattern's].", section="§4.1"),
        Param("delta", "float", None, low=0, unit="document units",
              help="Elements within delta of the empty circle are tried [default: two cells or a tenth of its radius].", cli=False,
              section="§4.1"),
        Param("epsilon", "float", None, low=0, unit="document units",
              help="Exclude-list points this near a success are dropped [default: its diameter].", cli=False, section="§4.1"),
        Param("max_elements", "int", None, low=1, help="Stop after this many elements (seeds included).", metavar="N"),
        Param("style", "str", "outline", help="Rendering style: outline, tapered, filigree, skeletal (-leafy, -beads, -ribbon), or the pattern's.",
              section="§4, Fig. 17"),
        Param("line_width", "float", None, low=0, low_open=True, unit="document units",
              help="Base line width [default: a fifth of the minimum radius].", cli=False),
        Param("draw_seeds", "bool", False, help="Draw the seeds too.", cli=False),
        Param("periodic", "bool", False, cli="flag",
              help="Grow a repeat tile of the rectangular region: growth wraps around its edges (issue 18)."),
    ),
)


def grow_ornament(
    pattern: Pattern | str,
    region: Region | Any = None,
    *,
    context: Arrangement | None = None,
    rng: int | np.random.Generator | None = None,
    progress: Callable[[int, int | None, str], None] | None = None,
    should_cancel: Callable[[], bool] | None = None,
    _tiled: bool = False,
    _open: Any = None,
    **params: Any,
) -> Arrangement:
    """Grow adaptive clip art in a region and render it (Wong et al. 1998).

    Parameters
    ----------
    pattern : Pattern or str
        A :class:`Pattern`, a built-in name (``dots``, ``flowers``, ``spirals``,
        ``hierarchy``, ``vase``, ``willow``) or the path of a Python rule file.
    region : Region, shapely polygon, ``"WxH"`` or (W, H)
        The panel: any polygon, holes included. Required.
    context : Arrangement, optional
        Fixed elements to grow around (issue 15): the panel less their footprint, so
        the ornament never overlaps them.
    seeds : (k, 2) float, optional
        Seed points (§4.2); default: the centre of the largest inscribed circle.
    rng : int, Generator or None
        Source of every random choice rules make (``ctx.rng``); recorded in ``meta``.
    cells : int, optional
        Cells of the raster buffer along the longer side of the region (§4.1); default:
        cells of half the minimum radius, between 256 and 2048. (Called ``resolution``
        before issue 15, where pack's ``resolution`` is a pixel side; the old keyword is
        accepted for one release with a DeprecationWarning.)
    min_radius : float, optional
        Stop when no eligible empty circle is at least this large (default: the pattern's).
    delta : float, optional
        Elements within ``delta`` of the empty circle C are tried (default: the larger of
        two cells and a tenth of C's radius).
    epsilon : float, optional
        After a success, exclude-list points within ``epsilon`` of C's centre are removed
        (default: C's diameter).
    max_elements : int, optional
        Stop after this many elements (seeds included).
    style : str
        Rendering style (``outline``, ``tapered``, ``filigree``, the skeletal strokes of
        Fig. 17 ``skeletal``, ``skeletal-leafy``, ``skeletal-beads``, ``skeletal-ribbon``,
        or one of the pattern's).
    progress, should_cancel : callable, optional
        Progress report and cancellation check.
    line_width : float, optional
        Passed to :func:`render_ornament`, as ``draw_seeds`` (its ``seeds``).
    periodic : bool
        Grow a repeat tile: the region must be a rectangle, the tile of a torus; empty
        circles, distances and collisions wrap around its edges, so that rules grow
        across an edge into the opposite side. Elements are kept once, at canonical
        positions, and ``meta["periodic"]`` records the tile (see :mod:`strew._periodic`).

    The parameters from ``seeds`` on are keyword only, checked against :data:`SPEC`.
    ``_tiled`` is :mod:`strew.tiles`' (a world's tile, issue 19.4): context rows that
    carry their proxies (:mod:`strew.ornament._context`) are grown on from as elements,
    and the result carries its own.

    Returns
    -------
    Arrangement
        One row per drawn element, of kind ``type`` (one kind per element type); columns
        ``element``, ``type``, ``parent``, ``phase`` and ``parts`` (the element's own
        marks, see :class:`~strew.Arrangement`); ``meta["ornament"]`` holds the run's
        statistics.
    """
    from .._errors import InputError
    from .._method import as_region, check_context, empty_result, free_region, is_empty, seed_record, stamp
    from ._render import available_styles as _styles

    prm = SPEC.validate(params)
    gen, seed = seed_record(rng)
    dom = as_region(region)
    if dom is None:
        raise InputError("region: give the panel (a Region, a polygon, 'WxH' or (W, H))")
    ctx = check_context(context)
    pat = load_pattern(pattern)
    if prm["style"] not in _styles(pat):
        raise InputError(f"style: unknown style {prm['style']!r} for pattern {pat.name!r} (have: {', '.join(_styles(pat))})")
    tile = None
    if prm["periodic"]:
        from .._periodic import frame_of_region

        tile = frame_of_region(dom)
        if ctx is not None:
            raise InputError("periodic: a repeat tile cannot grow around context elements (--around)")
    parents = None
    thin = ctx is not None
    if _tiled and ctx is not None and len(ctx):
        parents, ctx_rest = _context_parents(ctx, pat)
        free = free_region(dom, ctx_rest)
        thin = ctx_rest is not None
    else:
        free = free_region(dom, ctx)
    record = {"pattern": pattern if isinstance(pattern, str) else pat.name, **prm}
    if is_empty(free):
        arr = empty_result({}, dom, "the region is empty" if ctx is None else "the context covers the region")
    else:
        seeds = prm["seeds"]
        if parents and seeds is None and not _SEED_WITH_CONTEXT and _can_parent(parents, pat):
            seeds = np.zeros((0, 2))
        elif parents and seeds is None:
            # a seed clear of the context elements too (they are no longer cut out of the panel)
            from .._method import is_empty as _empty

            clear = free_region(free, ctx)
            seeds = default_seed(clear if not _empty(clear) else free)
        orn = grow_elements(
            pat,
            free,
            seeds=seeds,
            rng=gen,
            resolution=prm["cells"],
            min_radius=prm["min_radius"],
            delta=prm["delta"],
            epsilon=prm["epsilon"],
            max_elements=prm["max_elements"],
            progress=progress,
            should_cancel=should_cancel,
            periodic=prm["periodic"],
            _thin_boundary=thin,  # the context's thin footprints (issue 19.4)
            _context=parents,
            _holes=ctx.meta.get("ornament_holes") if _tiled and ctx is not None else None,  # strew.tiles._ornament_holes
            _open=_open if _tiled else None,  # the halo edges facing a later tile (strew.tiles._open_edges)
        )
        if _tiled:
            from ._render import render_ornament

            arr = render_ornament(orn, prm["style"], line_width=prm["line_width"], seeds=prm["draw_seeds"], _proxies=True)
        else:
            arr = orn.render(prm["style"], line_width=prm["line_width"], seeds=prm["draw_seeds"])
        if free is not dom or tile is not None:
            arr = arr.replace(region=dom)
        if tile is not None:
            from .._periodic import mark

            arr = mark(arr, tile)
        # the engine's resolved values (default seeds, resolution, min_radius) replace the Nones
        resolved = arr.meta.get("params", {})
        resolved = {**resolved, "cells": resolved.get("resolution")}  # the engine's name
        record.update({k: resolved[k] for k in prm if record.get(k) is None and resolved.get(k) is not None})
    return stamp(arr, SPEC, pattern if isinstance(pattern, str) else pat.name, record, seed, region=dom, context=ctx)



# A tiled world's later tile starts no growth of its own where its finished neighbours'
# elements can parent growth: it goes on from them, as one run grows the whole panel from
# its seeds (§4.1). With a seed of its own as well (True) a second front met theirs:
# flowers 480 x 480, tiles 120 (benchmarks/worlds_strips.py --methods ornament): +-2 s
# strips 0.984x the interior's density, +-1 s 0.946x (leaves 0.869x, flowers 1.073x),
# against 0.997x and 0.966x (0.909x, 1.018x) without, and 8 % more CPU.
_SEED_WITH_CONTEXT = False


def _context_parents(ctx: Arrangement, pat: Pattern) -> tuple[list[Element], Arrangement | None]:
    """The context rows that carry their proxies, rebuilt as elements, and the other rows
    (only an obstacle: cut out of the panel)."""
    from ._context import PROXIES_COLUMN, elements_from

    if PROXIES_COLUMN not in ctx.columns:
        return [], ctx
    col = ctx[PROXIES_COLUMN]
    has = np.array([bool(r) for r in col], bool)
    els = elements_from(col[has], pat)
    rest = ctx.select(~has) if (~has).any() else None
    return els, rest


def _can_parent(els: list[Element], pat: Pattern) -> bool:
    """Whether a rule of ``pat`` may grow from one of ``els`` (else a tile seeds itself)."""
    parents = {r.parent for r in pat.rules}
    return any(not e.sterile and e.type in parents for e in els)
