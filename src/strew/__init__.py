"""strew: fill 2D regions with many small vector elements.

The core is one immutable, column-wise type, :class:`Arrangement`, with its
:class:`Shape` library and an optional :class:`Region`. Every method reads and writes
it, and :func:`load` / :func:`save` move it to and from strew documents, SVG and PNG.
"""

from __future__ import annotations

from ._errors import Cancelled, InputError
from ._version import __version__
from .arrangement import Arrangement, concat
from .io import load, load_region, load_shapes, save
from .region import Region
from .shape import Path, Shape

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
    "save",
]
