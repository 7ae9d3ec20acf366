"""Limits on input size and on work, checked before any work starts (issue 17).

Every method estimates, from its inputs, how many elements it would make and how much
memory its rasters and grids would take, and refuses with :class:`InputError` what
exceeds a limit, instead of running for hours or exhausting memory. Input files are
checked for size and path count before they are parsed, and coordinates for magnitude
on load.

=============  ===============  =====================  ==========================
limit          default          CLI (before command)   environment variable
=============  ===============  =====================  ==========================
elements       10,000,000       ``--limit-elements``   ``STREW_LIMIT_ELEMENTS``
memory         4 GB             ``--limit-memory``     ``STREW_LIMIT_MEMORY``
file_size      64 MB            ``--limit-file-size``  ``STREW_LIMIT_FILE_SIZE``
paths          50,000           ``--limit-paths``      ``STREW_LIMIT_PATHS``
=============  ===============  =====================  ==========================

From Python, raise a limit for a block with ``with strew.limits(elements=1e8): ...``
(or for the whole process with :func:`set_limits`). Coordinates, positions and scales
must lie within ``MAX_COORD`` (1e12) in absolute value; beyond that the float arithmetic
of the methods (squared distances, areas) overflows or loses all precision.
"""

from __future__ import annotations

import contextlib
import math
import os
from collections.abc import Iterator
from typing import Any

from ._errors import InputError

__all__ = [
    "MAX_COORD",
    "DEFAULTS",
    "get_limit",
    "set_limits",
    "limits",
    "check_elements",
    "check_memory",
    "check_file",
    "check_decompressed",
    "check_paths",
    "check_kinds",
    "MAX_KINDS",
    "check_coordinates",
    "check_work",
    "element_area",
]

MAX_COORD = 1e12
TRIALS_PER_ELEMENT = 10
#: Largest ratio of an exemplar's element radius to its spacing (median nearest neighbour).
MAX_SIZE_TO_SPACING = 1e5

DEFAULTS: dict[str, float] = {
    "elements": 1e7,
    "memory": 4e9,
    "file_size": 64e6,
    "paths": 5e4,
}
_ENV = {name: f"STREW_LIMIT_{name.upper()}" for name in DEFAULTS}
_OPTION = {name: f"--limit-{name.replace('_', '-')}" for name in DEFAULTS}
_overrides: dict[str, float] = {}


def _parse_amount(text: str, name: str) -> float:
    """``"1e8"``, ``"200000"``, ``"8GB"``, ``"512MB"``, ``"64k"`` -> a positive number."""
    t = str(text).strip().lower().replace("_", "")
    mult = 1.0
    for suffix, m in (("gb", 1e9), ("mb", 1e6), ("kb", 1e3), ("g", 1e9), ("m", 1e6), ("k", 1e3), ("b", 1.0)):
        if t.endswith(suffix):
            t, mult = t[: -len(suffix)], m
            break
    try:
        v = float(t) * mult
    except ValueError:
        raise InputError(f"{name}: expected a positive number such as 1e8 or 8GB, got {text!r}") from None
    if not (math.isfinite(v) and v > 0):
        raise InputError(f"{name}: expected a positive number such as 1e8 or 8GB, got {text!r}")
    return v


def get_limit(name: str) -> float:
    """The limit in force: :func:`set_limits` / :func:`limits`, else the environment, else the default."""
    if name not in DEFAULTS:
        raise KeyError(name)
    if name in _overrides:
        return _overrides[name]
    env = os.environ.get(_ENV[name])
    if env:
        return _parse_amount(env, _ENV[name])
    return DEFAULTS[name]


def set_limits(**values: float | str | None) -> dict[str, float]:
    """Set limits for the process (``elements``, ``memory``, ``file_size``, ``paths``).

    ``None`` restores the default (or the environment's value). Returns the previous
    overrides, for :func:`limits` to restore.
    """
    old = dict(_overrides)
    for name, v in values.items():
        if name not in DEFAULTS:
            raise InputError(f"limits: unknown limit {name!r} (have: {', '.join(DEFAULTS)})")
        if v is None:
            _overrides.pop(name, None)
        else:
            _overrides[name] = _parse_amount(str(v), _OPTION[name])
    return old


@contextlib.contextmanager
def limits(**values: float | str | None) -> Iterator[None]:
    """Context manager: raise (or lower) limits for a block.

    Examples
    --------
    >>> from strew._limits import get_limit
    >>> with limits(elements=1e8):
    ...     get_limit("elements")
    100000000.0
    """
    old = set_limits(**values)
    try:
        yield
    finally:
        _overrides.clear()
        _overrides.update(old)


def _how_to_raise(name: str) -> str:
    return f"raise it with `strew {_OPTION[name]} N COMMAND ...`, {_ENV[name]}=N or strew.limits({name}=N)"


def _fmt(v: float) -> str:
    return f"{v:,.0f}" if v < 1e9 else f"{v:.3g}"


def check_elements(estimate: float, what: str) -> None:
    """Refuse work expected to make more elements than the ``elements`` limit."""
    lim = get_limit("elements")
    if not math.isfinite(estimate) or estimate > lim:
        est = "too many" if not math.isfinite(estimate) else f"about {_fmt(estimate)}"
        raise InputError(f"{what}: {est} elements expected, over the limit of {_fmt(lim)} ({_how_to_raise('elements')})")


def check_memory(nbytes: float, what: str) -> None:
    """Refuse work expected to take more memory than the ``memory`` limit."""
    lim = get_limit("memory")
    if not math.isfinite(nbytes) or nbytes > lim:
        est = "unbounded" if not math.isfinite(nbytes) else f"about {nbytes / 1e9:.3g} GB"
        raise InputError(f"{what}: needs {est} of memory, over the limit of {lim / 1e9:.3g} GB ({_how_to_raise('memory')})")


def check_file(path: Any, what: str) -> None:
    """Refuse an input file larger than the ``file_size`` limit, before reading it."""
    try:
        size = os.stat(path).st_size
    except OSError:
        return  # the reader reports missing files and folders with its own message
    lim = get_limit("file_size")
    if size > lim:
        raise InputError(f"{what}: file of {_fmt(size)} bytes, over the limit of {_fmt(lim)} bytes ({_how_to_raise('file_size')})")


def check_text(text: str | bytes, what: str) -> None:
    """Refuse text (e.g. SVG given inline) larger than the ``file_size`` limit."""
    lim = get_limit("file_size")
    if len(text) > lim:
        raise InputError(f"{what}: {_fmt(len(text))} bytes, over the limit of {_fmt(lim)} bytes ({_how_to_raise('file_size')})")


def check_decompressed(size: int, what: str) -> None:
    """Refuse compressed input (``.svgz``) that inflates past the ``file_size`` limit."""
    lim = get_limit("file_size")
    if size > lim:
        raise InputError(f"{what}: decompresses to over {_fmt(lim)} bytes, the file size limit ({_how_to_raise('file_size')})")


def check_paths(count: int, what: str) -> None:
    """Refuse a document with more paths (or elements) than the ``paths`` limit."""
    lim = get_limit("paths")
    if count > lim:
        raise InputError(f"{what}: {_fmt(count)} paths, over the limit of {_fmt(lim)} ({_how_to_raise('paths')})")


#: Most kinds an exemplar may have for the measures and preparations that hold one term
#: per pair of kinds (fidelity's kind-pair statistics, synth's type-mismatch table): a 1 MB
#: drawing of 9,174 distinct shapes, each its own kind, ran synth's preparation past 10
#: min and strew compare out of memory. Real exemplars have a handful of kinds.
MAX_KINDS = 1000


def check_kinds(count: int, what: str) -> None:
    """Refuse an exemplar with more than :data:`MAX_KINDS` kinds (one term per kind pair)."""
    if count > MAX_KINDS:
        raise InputError(f"{what}: {_fmt(count)} kinds, over the {_fmt(MAX_KINDS)} that kind-pair measures allow "
                         "(each distinct shape is a kind: draw repeated elements as copies or clones of one shape)")


def check_coordinates(values: Any, where: str, *, positive: bool = False, index: bool = True) -> None:
    """Refuse NaN, inf and values beyond :data:`MAX_COORD`, naming the first bad index.

    Parameters
    ----------
    values : (n,) or (n, 2) float array
    where : str
        The field name, e.g. ``"elements.x"``.
    positive : bool
        Also refuse values that are not positive (scales).
    index : bool
        Name the first bad index (``elements.x[3]``).
    """
    import numpy as np

    a = np.asarray(values, dtype=float)
    if a.size == 0:
        return
    flat = a.reshape(len(a), -1) if a.ndim > 1 else a.reshape(-1, 1)
    finite = np.isfinite(flat).all(axis=1)
    with np.errstate(invalid="ignore"):
        big = ~(np.abs(flat) <= MAX_COORD).all(axis=1)
        nonpos = ~(flat > 0).all(axis=1) if positive else np.zeros(len(flat), bool)
    bad = np.flatnonzero(~finite | big | nonpos)
    if len(bad):
        i = int(bad[0])
        idx = f"[{i}]" if index else ""
        if not finite[i]:
            why = "NaN or inf coordinate" if not positive else "NaN or inf"
        elif big[i]:
            why = f"magnitude over {MAX_COORD:.0e}"
        else:
            why = f"must be positive, got {float(flat[i][0]):g}"
        raise InputError(f"{where}{idx}: {why}")


def element_area(arr: Any) -> float:
    """The area one element of an exemplar takes, for work estimates of example-based methods.

    Growth and synthesis copy the exemplar's spacing, so the density of their output is
    the exemplar's: the convex hull of the element positions divided by their number, or
    the squared median nearest-neighbour distance when the positions are collinear. With
    fewer than two distinct positions, the median element area (shape area times scale
    squared). Returns ``0.0`` when nothing is known.

    Raises :class:`InputError` when the elements are over ``MAX_SIZE_TO_SPACING`` times
    larger than their spacing (sizes and positions out of all proportion).
    """
    import numpy as np

    n = len(arr)
    if n == 0:
        return 0.0
    pts = np.unique(np.c_[arr.x, arr.y], axis=0)
    if len(pts) >= 2:
        from scipy.spatial import cKDTree

        d, _ = cKDTree(pts).query(pts, k=2)
        nn = float(np.median(d[:, 1]))
        radii = np.array([sh.radius for sh in arr.shapes.values()] or [0.0])[arr.kind] * arr.scale
        ratio = float(np.median(radii)) / nn if nn > 0 else 0.0
        if ratio > MAX_SIZE_TO_SPACING:
            # every neighbourhood would hold the whole exemplar many times over
            raise InputError(
                f"exemplar: elements are {ratio:.3g} times larger than their spacing "
                f"(median radius {float(np.median(radii)):.3g}, spacing {nn:.3g}; at most {MAX_SIZE_TO_SPACING:.0e})"
            )
        spacing = nn**2
        hull = 0.0
        if len(pts) >= 3:
            import shapely

            hull = float(shapely.convex_hull(shapely.multipoints(pts)).area) / n
        return min(hull, spacing) if hull > 0 else spacing
    areas = np.array([max(sh.area, 0.0) for sh in arr.shapes.values()] or [0.0])
    return float(np.median(areas[arr.kind] * arr.scale**2))


def check_work(
    what: str,
    *,
    count: float | None = None,
    region: Any = None,
    per_element: float | None = None,
    cells: float | None = None,
    bytes_per_cell: float = 8.0,
    extra_bytes: float = 0.0,
    trials: float | None = None,
) -> None:
    """Refuse work whose estimated element count or memory exceeds the limits.

    Parameters
    ----------
    what : str
        The option or parameter the estimate follows from (named in the message).
    count : float, optional
        A requested element count; the estimate is at most this.
    region : Region, optional
        The area to fill; with ``per_element`` (the area one element takes) it gives
        an estimate ``region.area / per_element``.
    per_element : float, optional
    cells : float, optional
        Cells of a raster or grid the method would allocate (``bytes_per_cell`` each).
    extra_bytes : float
        Other memory the method would allocate.
    trials : float, optional
        A bound on attempts (e.g. consecutive failures before stopping); at most
        ``TRIALS_PER_ELEMENT`` times the ``elements`` limit.
    """
    if trials is not None:
        lim = TRIALS_PER_ELEMENT * get_limit("elements")
        if not math.isfinite(trials) or trials > lim:
            raise InputError(f"{what}: {_fmt(trials)} attempts, over the limit of {_fmt(lim)} ({TRIALS_PER_ELEMENT} per element of the elements limit; {_how_to_raise('elements')})")
    est = math.inf if count is None else float(count)
    if region is not None and per_element is not None and per_element > 0:
        est = min(est, region.area / per_element)
    if math.isfinite(est) or count is not None:
        check_elements(est, what)
    nbytes = extra_bytes + (cells or 0.0) * bytes_per_cell
    if nbytes:
        check_memory(nbytes, what)
