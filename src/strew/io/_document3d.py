"""Version 2 of the strew document: elements on surfaces (issue 20, point 5).

Version 2 adds the 3D columns ``z nx ny nz tx ty tz`` (position's z, unit normal, unit
tangent) to ``elements``; everything else is version 1. Arrangements without them are
still written as version 1, byte for byte as before, and both versions load.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from .._errors import InputError

__all__ = ["SURFACE_COLUMNS", "VERSIONS", "document_version", "check_surface_columns"]

SURFACE_COLUMNS = ("z", "nx", "ny", "nz", "tx", "ty", "tz")
VERSIONS = (1, 2)


def document_version(columns: Mapping[str, Any]) -> int:
    """2 when every 3D column is present, else 1."""
    return 2 if all(c in columns for c in SURFACE_COLUMNS) else 1


def check_surface_columns(elements: Mapping[str, Any], version: int) -> None:
    """Validate the 3D columns of a version 2 document (the message names the field).

    Raises
    ------
    InputError
        A missing or non-numeric column, or normals / tangents that are not unit vectors
        orthogonal to each other (tolerance 1e-6).
    """
    if version != 2:
        return
    for name in SURFACE_COLUMNS:
        if name not in elements:
            raise InputError(f"elements.{name}: missing column (version 2 documents carry {' '.join(SURFACE_COLUMNS)})")
        for i, v in enumerate(elements[name]):
            if isinstance(v, bool) or not isinstance(v, (int, float)):
                raise InputError(f"elements.{name}[{i}]: must be a number, got {v!r}")
            if not math.isfinite(v):
                raise InputError(f"elements.{name}[{i}]: NaN or inf coordinate")
    n = np.array([elements[c] for c in ("nx", "ny", "nz")], dtype=float).T.reshape(-1, 3)
    t = np.array([elements[c] for c in ("tx", "ty", "tz")], dtype=float).T.reshape(-1, 3)
    for name, vec in (("nx", n), ("tx", t)):
        bad = np.flatnonzero(np.abs(np.linalg.norm(vec, axis=1) - 1.0) > 1e-6)
        if len(bad):
            what = "normal" if name == "nx" else "tangent"
            raise InputError(f"elements.{name}[{bad[0]}]: the {what} ({name[0]}x, {name[0]}y, {name[0]}z) must be a unit vector")
    bad = np.flatnonzero(np.abs(np.einsum("ij,ij->i", n, t)) > 1e-6)
    if len(bad):
        raise InputError(f"elements.tx[{bad[0]}]: the tangent must be orthogonal to the normal")
