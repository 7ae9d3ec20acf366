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


def grow_ornament(
    pattern: Pattern | str,
    region: Region,
    *,
    seeds: Sequence[Sequence[float]] | np.ndarray | None = None,
    rng: int | np.random.Generator | None = None,
    resolution: int | None = None,
    min_radius: float | None = None,
    delta: float | None = None,
    epsilon: float | None = None,
    max_elements: int | None = None,
    style: str = "outline",
    progress: Callable[[int, int | None, str], None] | None = None,
    should_cancel: Callable[[], bool] | None = None,
    **render_options: Any,
) -> Arrangement:
    """Grow adaptive clip art in a region and render it (Wong et al. 1998).

    Parameters
    ----------
    pattern : Pattern or str
        A :class:`Pattern`, a built-in name (``dots``, ``flowers``, ``spirals``,
        ``hierarchy``, ``vase``, ``willow``) or the path of a Python rule file.
    region : Region
        The panel: any polygon, holes included.
    seeds : (k, 2) float, optional
        Seed points (§4.2); default: the centre of the largest inscribed circle.
    rng : int, Generator or None
        Source of every random choice rules make (``ctx.rng``).
    resolution : int, optional
        Cells of the raster buffer along the longer side of the region (§4.1); default:
        cells of half the minimum radius, between 256 and 2048.
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
    **render_options
        Passed to :func:`render_ornament` (``line_width``, ``seeds``).

    Returns
    -------
    Arrangement
        One row per drawn mark; columns ``element``, ``type``, ``parent``, ``phase``;
        ``meta["ornament"]`` holds the run's statistics.
    """
    from ._render import available_styles as _styles

    pat = load_pattern(pattern)
    if style not in _styles(pat):
        from .._errors import InputError

        raise InputError(f"--style: unknown style {style!r} for pattern {pat.name!r} (have: {', '.join(_styles(pat))})")
    orn = grow_elements(
        pat,
        region,
        seeds=seeds,
        rng=rng,
        resolution=resolution,
        min_radius=min_radius,
        delta=delta,
        epsilon=epsilon,
        max_elements=max_elements,
        progress=progress,
        should_cancel=should_cancel,
    )
    return orn.render(style, **render_options)
