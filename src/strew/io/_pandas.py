"""Arrangements as data frames: pandas, and GeoPandas with shapely geometries.

One row per element: ``kind`` (categorical, the kind names), ``x``, ``y``, ``rotation``,
``scale``, then every extra column. What a table cannot hold per row (the shape library,
the region, meta and other document entries) travels in ``DataFrame.attrs["strew"]`` as
the strew document's JSON-able entries, so ``from_pandas(to_pandas(a))`` gives ``a`` back.

pandas and geopandas are optional: ``pip install '.[data]'`` from a clone.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from .._errors import InputError
from ..arrangement import CORE_COLUMNS, Arrangement

__all__ = ["to_pandas", "from_pandas", "to_geopandas"]

_ATTRS = "strew"


def _require(module: str) -> Any:
    import importlib

    try:
        return importlib.import_module(module)
    except ImportError:
        raise InputError(f"{module} is not installed; from a clone of strew: pip install '.[data]'") from None


def to_pandas(arr: Arrangement) -> Any:
    """A ``pandas.DataFrame`` with one row per element.

    Parameters
    ----------
    arr : Arrangement

    Returns
    -------
    pandas.DataFrame
        Columns ``kind`` (categorical), ``x``, ``y``, ``rotation``, ``scale`` and every extra
        column (a column of shape ``(n, k)`` becomes ``k``-element arrays per row).
        ``attrs["strew"]`` holds the shapes, region, meta and extra document entries.

    Examples
    --------
    >>> from strew import Arrangement, Shape
    >>> a = Arrangement({"dot": Shape.circle(1)}, ["dot", "dot"], [0, 5], [0, 0])
    >>> df = to_pandas(a)  # doctest: +SKIP
    >>> list(df.columns)  # doctest: +SKIP
    ['kind', 'x', 'y', 'rotation', 'scale']
    """
    pd = _require("pandas")
    from .document import to_document

    data: dict[str, Any] = {"kind": pd.Categorical.from_codes(arr.kind, categories=list(arr.kinds))}
    for name in ("x", "y", "rotation", "scale"):
        data[name] = np.array(getattr(arr, name))
    for name, values in arr.columns.items():
        data[name] = list(np.array(values)) if values.ndim > 1 else np.array(values)
    df = pd.DataFrame(data)
    doc = to_document(arr)
    doc.pop("elements", None)
    df.attrs[_ATTRS] = doc
    return df


def from_pandas(
    df: Any,
    shapes: Mapping[str, Any] | None = None,
    *,
    region: Any = None,
    meta: Mapping[str, Any] | None = None,
) -> Arrangement:
    """An :class:`~strew.Arrangement` from a data frame made by :func:`to_pandas`, or by hand.

    Parameters
    ----------
    df : pandas.DataFrame
        Needs ``kind``, ``x`` and ``y`` columns; ``rotation`` and ``scale`` are optional;
        every other column becomes an extra column (a ``geometry`` column is dropped).
    shapes : mapping of str to Shape, optional
        The shape library. Default: the one in ``df.attrs["strew"]``.
    region, meta : optional
        Override what ``df.attrs["strew"]`` holds.

    Raises
    ------
    InputError
        A missing column, an unknown kind, or non-finite coordinates (named).
    """
    from .document import from_document

    if not hasattr(df, "columns") or not hasattr(df, "attrs"):
        raise InputError(f"from_pandas: expected a pandas DataFrame, got {type(df).__name__}")
    for need in ("kind", "x", "y"):
        if need not in df.columns:
            raise InputError(f"from_pandas: column {need!r} is missing (have: {', '.join(map(str, df.columns))})")
    doc = dict(df.attrs.get(_ATTRS) or {})
    doc.setdefault("format", "strew.arrangement")
    doc.setdefault("version", 1)
    doc.setdefault("shapes", {})
    doc["elements"] = {"kind": [], "x": [], "y": []}  # validated below with the real columns
    base = from_document(doc)
    library = dict(shapes) if shapes is not None else base.shapes
    if not library:
        raise InputError("from_pandas: no shape library (pass shapes=, or a frame made by to_pandas)")
    pd = _require("pandas")
    kind = df["kind"]
    kind = kind.to_numpy() if pd.api.types.is_integer_dtype(kind.dtype) else kind.astype(object).to_numpy()
    core = {name: df[name].to_numpy(dtype=float) for name in CORE_COLUMNS if name in df.columns and name != "kind"}
    columns = {}
    for name in df.columns:
        if name in CORE_COLUMNS or name == "geometry":
            continue
        values = df[name].to_numpy()
        if values.dtype == object and len(values) and isinstance(values[0], (list, tuple, np.ndarray)):
            values = np.stack([np.asarray(v) for v in values])
        columns[str(name)] = values
    return Arrangement(
        library,
        kind,
        core["x"],
        core["y"],
        core.get("rotation"),
        core.get("scale"),
        columns=columns,
        region=base.region if region is None else region,
        meta=base.meta if meta is None else meta,
        extra=base.extra,
    )


def to_geopandas(arr: Arrangement) -> Any:
    """A ``geopandas.GeoDataFrame``: :func:`to_pandas` plus each element's world geometry.

    The geometry column holds shapely geometries in the arrangement's (SVG, y-down) units;
    no coordinate reference system is set.
    """
    gpd = _require("geopandas")
    df = to_pandas(arr)
    gdf = gpd.GeoDataFrame(df, geometry=list(arr.geometry))
    gdf.attrs[_ATTRS] = df.attrs[_ATTRS]
    return gdf
