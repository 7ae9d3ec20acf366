"""Say when a result is not what was asked (issue 22 point 3).

A method that makes far fewer elements than asked, or only a handful because its shapes
are large against the region, must not end with exit 0 and no word. These checks run
after a method and warn with :class:`ResultWarning`, whose message says why and what to
change; the CLI prints it as ``strew: warning: ...`` on stderr.

Checks that can decide *before* the work that it cannot succeed (a shape wider than the
region, an exemplar whose copies would all collide) live with each method and raise
:class:`~strew.InputError` or warn up front.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Mapping
from typing import Any

__all__ = ["ResultWarning", "warn_shortfall", "warn_large_shapes", "large_shapes_advice", "suggested_scale"]

# A result this far below the request is worth a word (90%: growth that stops a few
# elements short at a region's edge is normal and stays quiet).
SHORTFALL = 0.9
# Fewer elements than this, with shapes this large against the region, reads as "the
# shapes do not fit", not as a texture.
FEW = 10
LARGE = 0.2  # largest element's area over the region's area


class ResultWarning(UserWarning):
    """The result is far from what was asked; the message says why and how to fix it."""


def warn_shortfall(method: str, made: int, requested: int | None, reason: str, *, stacklevel: int = 3) -> bool:
    """Warn when ``made`` is below 90% of ``requested``; returns whether it warned.

    Parameters
    ----------
    method : str
        The method's name, first in the message.
    made, requested : int
        Elements made and asked for (``requested=None``: nothing was asked, no warning).
    reason : str
        Why it stopped and what to change, in the user's terms.
    """
    if requested is None or made >= SHORTFALL * requested:
        return False
    warnings.warn(f"{method}: made {made} of the {requested} elements asked for: {reason}", ResultWarning, stacklevel=stacklevel)
    return True


def suggested_scale(element_area: float, region_area: float, target: int = 200, fill: float = 0.5) -> float:
    """A scale factor at which about ``target`` elements cover ``fill`` of the region.

    Rounded down to two significant digits, so that the message reads naturally.
    """
    if element_area <= 0 or region_area <= 0:
        return 1.0
    s = math.sqrt(fill * region_area / (target * element_area))
    digits = -int(math.floor(math.log10(s))) + 1
    return math.floor(s * 10**digits) / 10**digits


def large_shapes_advice(areas: Mapping[str, float], region: Any) -> str | None:
    """Why few elements fit and what to change, when the shapes are large against the region.

    Parameters
    ----------
    areas : mapping of str to float
        Each kind's area as placed (shape area times scale squared).
    region : Region or None

    Returns
    -------
    str or None
        ``None`` when the largest kind takes less than a fifth of the region.
    """
    if region is None or not areas:
        return None
    region_area = float(region.area) if hasattr(region, "area") else 0.0
    if region_area <= 0:
        return None
    kind, largest = max(areas.items(), key=lambda kv: kv[1])
    ratio = largest / region_area
    if ratio < LARGE:
        return None
    x0, y0, x1, y1 = region.bounds
    share = f"takes {ratio:.0%} of" if ratio < 10 else f"is {ratio:.3g} times the area of"
    s = suggested_scale(largest, region_area)
    return (f"the shapes are large against the region ({kind!r} {share} a {x1 - x0:.4g} x {y1 - y0:.4g} region); "
            f"scale them down (scale {s:g} fits about 200) or give a larger region")


def warn_large_shapes(
    method: str,
    made: int,
    areas: Mapping[str, float],
    region: Any,
    *,
    stacklevel: int = 3,
) -> bool:
    """Warn when only a few elements (1 to 9) fit because the shapes are large.

    With no element at all the method fails instead, and gives
    :func:`large_shapes_advice` in its error.

    Returns
    -------
    bool
        Whether it warned.
    """
    if made < 1 or made >= FEW:
        return False
    advice = large_shapes_advice(areas, region)
    if advice is None:
        return False
    warnings.warn(f"{method}: only {made} element{'s' if made != 1 else ''}: {advice}", ResultWarning, stacklevel=stacklevel)
    return True
