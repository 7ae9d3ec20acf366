"""The strew document: JSON with ``"format": "strew.arrangement"``, ``"version": 1``
(``2`` for elements on surfaces, see :mod:`._document3d`).

See DESIGN.md. Loading validates the document and raises :class:`strew.InputError`
with a message that names the offending field.
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from .._errors import InputError
from ..arrangement import CORE_COLUMNS, Arrangement
from ..region import Region
from ..shape import Shape
from ._document3d import VERSIONS, check_surface_columns, document_version

__all__ = ["FORMAT", "VERSION", "to_document", "from_document", "dumps", "loads"]

FORMAT = "strew.arrangement"
VERSION = 1
_KNOWN = {"format", "version", "shapes", "elements", "region", "meta"}


def _jsonable(obj: Any) -> Any:
    if isinstance(obj, np.ndarray):
        return obj.tolist()
    if isinstance(obj, np.generic):
        return obj.item()
    if isinstance(obj, (set, frozenset, tuple)):
        return list(obj)
    raise TypeError(f"{type(obj).__name__} is not JSON serialisable")


def to_document(arr: Arrangement) -> dict[str, Any]:
    """The JSON-ready strew document of an arrangement."""
    elements: dict[str, Any] = {
        "kind": arr.kind_names.tolist(),
        "x": arr.x.tolist(),
        "y": arr.y.tolist(),
        "rotation": arr.rotation.tolist(),
        "scale": arr.scale.tolist(),
    }
    for name, col in arr.columns.items():
        if col.dtype.kind == "f" and not np.all(np.isfinite(col)):
            # JSON has no NaN: missing values (e.g. after concat) are written as null.
            obj = col.astype(object)
            obj[~np.isfinite(col)] = None
            elements[name] = obj.tolist()
        else:
            elements[name] = col.tolist()
    doc: dict[str, Any] = {
        "format": FORMAT,
        "version": max(VERSION, document_version(arr.columns)),
        "shapes": {name: sh.to_dict() for name, sh in arr.shapes.items()},
        "elements": elements,
    }
    if arr.region is not None:
        doc["region"] = arr.region.to_dict()
    doc["meta"] = arr.meta
    for k, v in arr.extra.items():
        doc.setdefault(k, v)
    return doc


def from_document(doc: Any) -> Arrangement:
    """Validate a parsed strew document and build the :class:`Arrangement`."""
    if not isinstance(doc, Mapping):
        raise InputError("document: must be a JSON object")
    if doc.get("format") != FORMAT:
        raise InputError(f"format: expected {FORMAT!r}, got {doc.get('format')!r}")
    if "version" not in doc:
        raise InputError("version: missing")
    version = doc["version"]
    if version not in VERSIONS or isinstance(version, bool):
        raise InputError(f"version: unsupported version {version!r} (this strew reads versions {', '.join(map(str, VERSIONS))})")
    shapes_doc = doc.get("shapes")
    if not isinstance(shapes_doc, Mapping):
        raise InputError("shapes: missing or not an object")
    shapes = {str(k): Shape.from_dict(v, f"shapes.{k}") for k, v in shapes_doc.items()}
    elements = doc.get("elements")
    if not isinstance(elements, Mapping):
        raise InputError("elements: missing or not an object")
    for name in ("kind", "x", "y"):
        if name not in elements:
            raise InputError(f"elements.{name}: missing column")
    for name, col in elements.items():
        if not isinstance(col, list):
            raise InputError(f"elements.{name}: must be a list")
    n = len(elements["kind"])
    for name, col in elements.items():
        if len(col) != n:
            raise InputError(f"elements.{name}: length {len(col)} does not match elements.kind length {n}")
    for i, k in enumerate(elements["kind"]):
        if not isinstance(k, str):
            raise InputError(f"elements.kind[{i}]: must be a kind name (string), got {k!r}")
    for name in ("x", "y", "rotation", "scale"):
        col = elements.get(name)
        if col is None:
            continue
        for i, v in enumerate(col):
            if isinstance(v, bool) or not isinstance(v, (int, float)):
                raise InputError(f"elements.{name}[{i}]: must be a number, got {v!r}")
            if not math.isfinite(v):
                raise InputError(f"elements.{name}[{i}]: NaN or inf coordinate")
    check_surface_columns(elements, version)
    columns = {k: v for k, v in elements.items() if k not in CORE_COLUMNS}
    region = None
    if doc.get("region") is not None:
        region = Region.from_dict(doc["region"])
    meta = doc.get("meta") or {}
    if not isinstance(meta, Mapping):
        raise InputError("meta: must be an object")
    extra = {k: v for k, v in doc.items() if k not in _KNOWN}
    return Arrangement(
        shapes,
        elements["kind"],
        elements["x"],
        elements["y"],
        elements.get("rotation"),
        elements.get("scale"),
        columns=columns,
        region=region,
        meta=meta,
        extra=extra,
    )


def dumps(arr: Arrangement) -> str:
    """Serialise to JSON text (deterministic: same arrangement, same bytes)."""
    return json.dumps(to_document(arr), default=_jsonable, separators=(",", ":"), allow_nan=False) + "\n"


def loads(text: str | bytes) -> Arrangement:
    """Parse JSON text into an :class:`Arrangement`."""
    try:
        doc = json.loads(text, parse_constant=_reject_constant)
    except json.JSONDecodeError as exc:
        raise InputError(f"malformed JSON: {exc.msg} at line {exc.lineno} column {exc.colno}") from None
    except RecursionError:
        raise InputError("malformed JSON: nested too deeply") from None
    return from_document(doc)


def _reject_constant(name: str) -> float:
    # NaN / Infinity literals are not JSON; keep them as floats so that validation names the field.
    return float(name.replace("Infinity", "inf"))
