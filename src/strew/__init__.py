"""strew: fill 2D regions with many small vector elements.

The core is one immutable, column-wise type, :class:`Arrangement`, with its
:class:`Shape` library and an optional :class:`Region`. Every method reads and writes
it, and :func:`load` / :func:`save` move it to and from strew documents, SVG and PNG.

Names are imported lazily (PEP 562), so that ``strew --help`` does not pay for numpy,
shapely and scipy.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

from . import _display
from ._errors import Cancelled, InputError
from ._version import __version__

# The core type's writers (Arrangement.to_svg, its notebook pictures, to_pandas) are
# io's: the core only declares their hooks (strew._display), and this facade, which sits
# above every layer, has io fill them on first use, so that imports point down and
# ``import strew`` stays as light as before (issue 15 point 7).
_display.set_provider(lambda: importlib.import_module("strew.io"))

__all__ = [
    "__version__",
    "Arrangement",
    "Cancelled",
    "InputError",
    "Path",
    "Region",
    "Shape",
    "concat",
    "load",
    "load_region",
    "load_shapes",
    "limits",
    "save",
    "set_limits",
]

_LAZY = {
    "Arrangement": "strew.arrangement",
    "concat": "strew.arrangement",
    "Region": "strew.region",
    "Shape": "strew.shape",
    "Path": "strew.shape",
    "load": "strew.io",
    "save": "strew.io",
    "load_shapes": "strew.io",
    "load_region": "strew.io",
    "limits": "strew._limits",
    "set_limits": "strew._limits",
}

if TYPE_CHECKING:  # pragma: no cover
    from .arrangement import Arrangement, concat
    from ._limits import limits, set_limits
    from .io import load, load_region, load_shapes, save
    from .region import Region
    from .shape import Path, Shape


def __getattr__(name: str) -> Any:
    module = _LAZY.get(name)
    if module is None:
        raise AttributeError(f"module 'strew' has no attribute {name!r}")
    value = getattr(importlib.import_module(module), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))
