"""Reading and writing strew documents, SVG and PNG.

:func:`load` and :func:`save` pick the format from the file extension.
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from collections.abc import Sequence
from typing import Any

from .._errors import InputError
from ..arrangement import Arrangement
from ..region import Region
from ..shape import Shape
from .._limits import check_file
from ._atomic import atomic_write, atomic_write_many, probe_writable
from ._pandas import from_pandas, to_geopandas, to_pandas
from .._display import register as _register_hook

__all__ = ["to_pandas", "from_pandas", "to_geopandas", "load", "save", "save_many", "encode", "load_shapes", "load_region", "atomic_write", "OUTPUT_FORMATS", "check_output_path"]

OUTPUT_FORMATS = (".json", ".svg", ".png")
INPUT_FORMATS = (".json", ".svg", ".svgz")


def _suffix(path: str | os.PathLike[str], allowed: tuple[str, ...], what: str) -> str:
    suffix = Path(path).suffix.lower()
    if suffix not in allowed:
        raise InputError(f"{what} {str(path)!r}: unsupported extension {suffix or '(none)'!r}; use {', '.join(allowed)}")
    return suffix


def check_output_path(path: str | os.PathLike[str], what: str = "--out") -> str:
    """Validate an output path before any work is done; returns its extension.

    Checks the extension, that the folder exists, and that the file can be written there
    (by creating and removing the temporary file that the write will use).
    """
    suffix = _suffix(path, OUTPUT_FORMATS, what)
    parent = Path(path).parent
    if not parent.exists():
        raise InputError(f"{what} {str(path)!r}: folder {str(parent)!r} does not exist")
    probe_writable(path, what)
    return suffix


def _read_text(path: str | os.PathLike[str]) -> str:
    check_file(path, Path(path).name)  # before reading: size limit (issue 17)
    try:
        return Path(path).read_text(encoding="utf-8")
    except FileNotFoundError:
        raise InputError(f"{str(path)!r}: no such file") from None
    except IsADirectoryError:
        raise InputError(f"{str(path)!r}: is a folder, expected a file") from None
    except UnicodeDecodeError:
        raise InputError(f"{str(path)!r}: not UTF-8 text") from None
    except OSError as exc:
        raise InputError(f"{str(path)!r}: cannot read ({exc.strerror or type(exc).__name__})") from None


def _json(text: str, name: str) -> Any:
    try:
        return json.loads(text)
    except json.JSONDecodeError as exc:
        raise InputError(f"{name}: malformed JSON: {exc.msg} at line {exc.lineno}") from None
    except RecursionError:
        raise InputError(f"{name}: malformed JSON: nested too deeply") from None


def load(path: str | os.PathLike[str], **kwargs: Any) -> Arrangement:
    """Read an arrangement from a strew document (.json) or an SVG (.svg).

    SVG is read as an exemplar (see :func:`strew.io.svg.read_svg`); ``kwargs`` go there.
    """
    if str(path).lower().endswith(".parquet") and Path(path).is_dir():  # issue 19: a world
        from ._parquet import load_parquet

        return load_parquet(path)
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


def encode(arr: Arrangement, path: str | os.PathLike[str], **kwargs: Any) -> str | bytes:
    """The file contents :func:`save` would write to ``path`` (format from the extension).

    A name ending in ``.height.png`` gives a 16-bit height map (:mod:`._height`).
    """
    suffix = _suffix(path, OUTPUT_FORMATS, "--out")
    if str(path).lower().endswith(".height.png"):
        from ._height import to_height_png

        return to_height_png(arr, **kwargs)
    if suffix == ".json":
        from .document import dumps

        return dumps(arr)
    if suffix == ".svg":
        from .svg import to_svg

        return to_svg(arr, **kwargs)
    from .png import to_png

    return to_png(arr, **kwargs)


def save(arr: Arrangement, path: str | os.PathLike[str], **kwargs: Any) -> Path:
    """Write an arrangement as .json, .svg or .png (atomically: no partial file on failure).

    ``kwargs`` go to the writer (``to_svg`` or ``to_png``).
    """
    check_output_path(path)
    return atomic_write(path, encode(arr, path, **kwargs))


def save_many(arr: Arrangement, paths: Sequence[str | os.PathLike[str]], **png_kwargs: Any) -> list[Path]:
    """Write an arrangement to several files, all or none.

    Every file is encoded first and written to a temporary file; only when all are
    written are they renamed into place, so a failure leaves none of them behind.
    ``png_kwargs`` go to the PNG writer.
    """
    for p in paths:
        check_output_path(p)
    data = [(p, encode(arr, p, **(png_kwargs if Path(p).suffix.lower() == ".png" else {}))) for p in paths]
    return atomic_write_many(data)


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
        doc = _json(_read_text(path), Path(path).name)
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


def _to_svg(arr: Arrangement, **kwargs: Any) -> str:
    from .svg import to_svg

    return to_svg(arr, **kwargs)


def _to_png(arr: Arrangement, **kwargs: Any) -> bytes:
    from .png import to_png

    return to_png(arr, **kwargs)


# The core type's display and data-frame conveniences (Arrangement.to_svg, _repr_svg_,
# _repr_png_, to_pandas ...) call these through strew._display: the core declares the
# hooks, io fills them, and imports keep pointing down (issue 15 point 7). svg and png
# load on first use, as before.
for _name, _func in (("svg", _to_svg), ("png", _to_png), ("to_pandas", to_pandas),
                     ("to_geopandas", to_geopandas), ("from_pandas", from_pandas)):
    _register_hook(_name, _func)
del _name, _func
