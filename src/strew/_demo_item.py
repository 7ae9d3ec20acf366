"""One picture of the gallery: what a demo section returns (see :mod:`strew.demo`).

It lives below the method packages, so that their demo sections (``strew.pack._demo``,
...) need not import the app-level :mod:`strew.demo`, which imports io and metrics to
write the gallery (issue 15 point 7: imports point down).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from .arrangement import Arrangement

__all__ = ["DemoItem"]


@dataclass
class DemoItem:
    """One picture of the gallery."""

    name: str
    title: str
    arrangement: Arrangement
    description: str = ""
    svg_options: dict = field(default_factory=dict)
