"""File access of the studio: only inside the project folder, no path escapes.

Every path the browser names is relative to ``PROJECT_DIR``. It is resolved (symbolic
links included) and refused unless the result lies inside the project folder and has an
allowed extension.
"""

from __future__ import annotations

import os
from pathlib import Path

from .._errors import InputError

__all__ = ["resolve_in_project", "list_project_files", "MAX_PATH_LENGTH"]

MAX_PATH_LENGTH = 255


def resolve_in_project(root: Path, name: object, *, suffixes: tuple[str, ...], must_exist: bool = False) -> Path:
    """The absolute path of ``name`` inside ``root``.

    Parameters
    ----------
    root : Path
        The project folder (already resolved).
    name : str
        A relative path as sent by the browser.
    suffixes : tuple of str
        Allowed extensions (lower case, with the dot).
    must_exist : bool
        Refuse names of missing files.

    Raises
    ------
    InputError
        For anything that is not a plain relative path to an allowed file inside ``root``.
    """
    if not isinstance(name, str) or not name.strip():
        raise InputError("path: must be a non-empty string")
    if len(name) > MAX_PATH_LENGTH:
        raise InputError(f"path: longer than {MAX_PATH_LENGTH} characters")
    if "\x00" in name or "\\" in name:
        raise InputError(f"path {name!r}: invalid character")
    p = Path(name)
    if p.is_absolute() or name.startswith("~") or any(part == ".." for part in p.parts):
        raise InputError(f"path {name!r}: must be relative to the project folder, without '..'")
    if p.suffix.lower() not in suffixes:
        raise InputError(f"path {name!r}: unsupported extension {p.suffix or '(none)'!r}; use {', '.join(suffixes)}")
    full = (root / p).resolve()
    if not full.is_relative_to(root):
        raise InputError(f"path {name!r}: leads outside the project folder")
    if must_exist and not full.is_file():
        raise InputError(f"path {name!r}: no such file in the project folder")
    if not must_exist and not full.parent.is_dir():
        raise InputError(f"path {name!r}: folder {str(p.parent)!r} does not exist in the project folder")
    return full


def list_project_files(root: Path, suffixes: tuple[str, ...] = (".svg", ".json"), limit: int = 500) -> list[str]:
    """Relative paths of the files with ``suffixes`` inside ``root`` (hidden folders skipped)."""
    out: list[str] = []
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames[:] = sorted(d for d in dirnames if not d.startswith("."))
        base = Path(dirpath)
        for f in sorted(filenames):
            if Path(f).suffix.lower() in suffixes and not f.startswith("."):
                full = (base / f).resolve()
                if full.is_relative_to(root):
                    out.append((base / f).relative_to(root).as_posix())
                    if len(out) >= limit:
                        return out
    return out
