"""Reading and writing strew documents, SVG and PNG.

:func:`load` and :func:`save` pick the format from the file extension.
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any

from .._errors import InputError
from ..arrangement import Arrangement
from ..region import Region
from ..shape import Shape
from ._atomic import atomic_write

__all__ = ["load", "save", "load_shapes", "load_region", "atomic_write", "OUTPUT_FORMATS", "check_output_path"]

OUTPUT_FORMATS = (".json", ".svg", ".png")
INPUT_FORMATS = (".json", ".svg")


def _suffix(path: str | os.PathLike[str], allowed: tuple[str, ...], what: str) -> str:
    suffix = Path(path).suffix.lower()
    if suffix not in allowed:
        raise InputError(f"{what} {str(path)!r}: unsupported extension {suffix or '(none)'!r}; use {', '.join(allowed)}")
    return suffix


def check_output_path(path: str | os.PathLike[str]) -> str:
    """Validate an output path before any work is done; returns its extension."""
    suffix = _suffix(path, OUTPUT_FORMATS, "--out")
    parent = Path(path).parent
    if not parent.exists():
        raise InputError(f"--out {str(path)!r}: folder {str(parent)!r} does not exist")
    return suffix


def _read_text(path: str | os.PathLike[str]) -> str:
    try:
        return Path(path).read_text(encoding="utf-8")
    except FileNotFoundError:
        raise InputError(f"{str(path)!r}: no such file") from None
    except IsADirectoryError:
        raise InputError(f"{str(path)!r}: is a folder, expected a file") from None
    except UnicodeDecodeError:
        raise InputError(f"{str(path)!r}: not UTF-8 text") from None


def load(path: str | os.PathLike[str], **kwargs: Any) -> Arrangement:
    """Read an arrangement from a strew document (.json) or an SVG (.svg).

    SVG is read as an exemplar (see :func:`strew.io.svg.read_svg`); ``kwargs`` go there.
    """
    suffix = _suffix(path, INPUT_FORMATS, "input")
    if suffix == ".json":
        from .document import loads

        text = _read_text(path)  # its messages already name the file
        try:
            return loads(text)
        except InputError as exc:
            raise InputError(f"{Path(path).name}: {exc}") from None
    from .svg import read_svg

    return read_svg(path, **kwargs)


def save(arr: Arrangement, path: str | os.PathLike[str], **kwargs: Any) -> Path:
    """Write an arrangement as .json, .svg or .png (atomically: no partial file on failure).

    ``kwargs`` go to the writer (``to_svg`` or ``to_png``).
    """
    suffix = check_output_path(path)
    if suffix == ".json":
        from .document import dumps

        data: str | bytes = dumps(arr)
    elif suffix == ".svg":
        from .svg import to_svg

        data = to_svg(arr, **kwargs)
    else:
        from .png import to_png

        data = to_png(arr, **kwargs)
    return atomic_write(path, data)


def load_shapes(path: str | os.PathLike[str], **kwargs: Any) -> dict[str, Shape]:
    """Shape library from a strew document or from any SVG (one kind per distinct shape)."""
    suffix = _suffix(path, INPUT_FORMATS, "shape file")
    if suffix == ".json":
        shapes = load(path).shapes
    else:
        from .svg import read_svg_shapes

        shapes = read_svg_shapes(path, **kwargs)
    if not shapes:
        raise InputError(f"{Path(path).name}: no shapes found")
    return shapes


def load_region(path: str | os.PathLike[str], **kwargs: Any) -> Region:
    """Region from a strew document's ``region`` entry or from the closed paths of an SVG."""
    suffix = _suffix(path, INPUT_FORMATS, "region file")
    if suffix == ".json":
        text = _read_text(path)
        try:
            doc = json.loads(text)
        except json.JSONDecodeError as exc:
            raise InputError(f"{Path(path).name}: malformed JSON: {exc.msg} at line {exc.lineno}") from None
        if isinstance(doc, dict) and doc.get("format") == "strew.arrangement":
            arr = load(path)
            if arr.region is not None:
                return arr.region
            raise InputError(f"{Path(path).name}: region: the document has no region")
        if isinstance(doc, dict) and "paths" in doc:
            return Region.from_dict(doc)
        raise InputError(f"{Path(path).name}: region: expected a strew document with a region, or {{'paths': [...]}}")
    from .svg import read_svg_region

    return read_svg_region(path, **kwargs)
