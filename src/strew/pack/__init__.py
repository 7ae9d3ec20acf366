"""Dense non-periodic packing of arbitrary shapes (Sakurai & Miyata).

Public entry points:

:func:`pack`
    Naive dart throwing with exclusive regions (§3) or the fill-gap method (§4).
:func:`poisson_disk`
    Bridson-style Poisson-disk sampling in any region (Step 1 of fill-gap, §4.1).
"""

from __future__ import annotations

from ._exclusive import PackWarning
from ._pack import DEFAULTS, METHODS, SPEC, pack
from ._poisson import poisson_disk

__all__ = ["pack", "poisson_disk", "PackWarning", "METHODS", "DEFAULTS", "SPEC"]
