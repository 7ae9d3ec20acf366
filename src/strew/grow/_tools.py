"""Reading the strokes of the interaction tools (Ijiri et al. 2008, §3, Fig. 1).

Flow-field strokes, boundary strokes and spray paths are polylines in world space, read
by the one stroke reader, :func:`strew.io.strokes.read_strokes` (shared with synth's
brush): an SVG (every drawn path, transforms applied), JSON points or paths, or a strew
document whose elements' world geometry (holes' rings included) gives the strokes.
"""

from __future__ import annotations

import os

import numpy as np

from ..io.strokes import read_strokes, strokes_of_geometry

__all__ = ["load_strokes", "strokes_of_geometry"]


def load_strokes(path: str | os.PathLike[str], what: str = "strokes") -> list[np.ndarray]:
    """Polylines from an SVG or JSON file; ``what`` names the option in messages.

    The reader is :func:`strew.io.strokes.read_strokes` (shared with synth's brush).

    Returns
    -------
    list of (k, 2) float
    """
    return read_strokes(path, what)
