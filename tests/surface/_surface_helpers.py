"""Helpers shared by the surface tests."""

from __future__ import annotations

import numpy as np


def positions(arr) -> np.ndarray:
    """(n, 3) element positions of a surface arrangement."""
    return np.column_stack([arr.x, arr.y, arr["z"]])
