"""Lazy imports of the optional surface dependencies (the ``strew[surface]`` extra)."""

from __future__ import annotations

import importlib
from types import ModuleType

__all__ = ["require"]

_HINT = "pip install 'strew[surface]'"


def require(name: str) -> ModuleType:
    """Import ``name`` (``"trimesh"`` or ``"potpourri3d"``) or raise ImportError naming the extra.

    Examples
    --------
    >>> require("numpy").__name__
    'numpy'
    """
    try:
        return importlib.import_module(name)
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise ImportError(f"strew.surface needs {name}: {_HINT}") from exc
