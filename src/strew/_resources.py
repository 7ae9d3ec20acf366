"""Locate the example files shipped with strew (``examples/`` in the source tree).

A wheel carries them as ``strew/_examples``; an editable install reads the source
tree's ``examples/`` folder.
"""

from __future__ import annotations

from pathlib import Path

__all__ = ["examples_dir", "example_path"]


def examples_dir() -> Path:
    """The folder holding strew's example exemplars, shapes, regions and scripts."""
    here = Path(__file__).resolve().parent
    packaged = here / "_examples"
    if packaged.is_dir():
        return packaged
    source = here.parent.parent / "examples"
    if source.is_dir():
        return source
    raise FileNotFoundError("strew's examples folder is missing from this installation")


def example_path(*parts: str) -> Path:
    """Path of one example file, e.g. ``example_path("exemplars", "stones.svg")``."""
    p = examples_dir().joinpath(*parts)
    if not p.exists():
        raise FileNotFoundError(f"no example {'/'.join(parts)!r} in {examples_dir()}")
    return p
