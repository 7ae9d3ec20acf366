"""Per-element frames of arrangements on surfaces (issue 20, point 4).

A surface arrangement is an ordinary :class:`strew.Arrangement` whose elements carry
the 3D columns ``z``, ``nx ny nz`` (unit normal) and ``tx ty tz`` (unit tangent, the
element's local +x axis), next to the core ``x``, ``y`` and ``scale``. The local +y axis
of a 2D shape maps to ``-b`` with ``b = n x t``, so that a shape drawn in SVG's y-down
coordinates reads the same seen from outside the surface (looking along ``-n``).
The core ``rotation`` holds the tangent's bearing in the x-y plane (the top view).
"""

from __future__ import annotations

import numpy as np

from .._errors import InputError
from ..arrangement import Arrangement

__all__ = ["SURFACE_COLUMNS", "is_surface", "element_frames", "element_matrices", "lift"]

SURFACE_COLUMNS = ("z", "nx", "ny", "nz", "tx", "ty", "tz")


def is_surface(arr: Arrangement) -> bool:
    """Whether ``arr`` carries the 3D columns of :data:`SURFACE_COLUMNS`."""
    return all(c in arr.columns for c in SURFACE_COLUMNS)


def element_frames(arr: Arrangement) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Position, normal, tangent, bitangent and scale of each element.

    Returns
    -------
    p, n, t, b : (m, 3) float
        ``b = n x t``; ``(t, b, n)`` is a right-handed orthonormal frame.
    s : (m,) float

    Raises
    ------
    InputError
        The arrangement lacks a 3D column (the message names it).
    """
    missing = [c for c in SURFACE_COLUMNS if c not in arr.columns]
    if missing:
        raise InputError(f"elements.{missing[0]}: missing column (not a surface arrangement; needs {' '.join(SURFACE_COLUMNS)})")
    c = arr.columns
    p = np.stack([arr.x, arr.y, c["z"]], axis=1).astype(float)
    n = np.stack([c["nx"], c["ny"], c["nz"]], axis=1).astype(float)
    t = np.stack([c["tx"], c["ty"], c["tz"]], axis=1).astype(float)
    b = np.cross(n, t)
    return p, n, t, b, np.asarray(arr.scale, dtype=float)


def element_matrices(arr: Arrangement) -> np.ndarray:
    """(m, 4, 4) float: local -> world for each element (columns ``s t``, ``s b``, ``s n``, ``p``).

    Local coordinates are the kind mesh's: x along the tangent, y along ``b``, z along
    the normal (2D shapes are mirrored in y when they become meshes, see module notes).
    """
    p, n, t, b, s = element_frames(arr)
    m = np.zeros((len(p), 4, 4))
    m[:, :3, 0] = t * s[:, None]
    m[:, :3, 1] = b * s[:, None]
    m[:, :3, 2] = n * s[:, None]
    m[:, :3, 3] = p
    m[:, 3, 3] = 1.0
    return m


def lift(arr: Arrangement, z: float = 0.0) -> Arrangement:
    """A flat arrangement as a surface arrangement on the plane ``z`` (Sakurai Fig. 15).

    Each element keeps its x, y, rotation and scale; its normal is ``(0, 0, -1)`` and its
    tangent ``(cos r, sin r, 0)``, so that the elements' 3D geometry coincides with their
    2D geometry and the scene seen from ``-z`` (x right, y down) reads as the SVG does.
    Kinds can then carry 3D meshes in :func:`strew.surface.save_glb`.

    Examples
    --------
    >>> from strew import Arrangement, Shape
    >>> a = lift(Arrangement({"d": Shape.circle(1)}, ["d"], [3], [4], [0.5]))
    >>> float(a["nz"][0]), round(float(a["tx"][0]), 3)
    (-1.0, 0.878)
    """
    n = len(arr)
    try:
        z = float(z)
    except (TypeError, ValueError):
        raise InputError(f"z: must be a number, got {z!r}") from None
    if not np.isfinite(z):
        raise InputError("z: must be finite")
    c, s = np.cos(arr.rotation), np.sin(arr.rotation)
    zeros = np.zeros(n)
    cols = {"z": np.full(n, z), "nx": zeros, "ny": zeros, "nz": np.full(n, -1.0), "tx": c, "ty": s, "tz": zeros}
    if "radius" not in arr.columns:
        radii = np.array([sh.radius for sh in arr.shapes.values()])
        cols["radius"] = radii[np.asarray(arr.kind)] * arr.scale if n else zeros
    return arr.with_columns(**cols)
