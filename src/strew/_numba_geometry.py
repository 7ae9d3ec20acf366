"""Moved: the point-segment distance now lives in :mod:`strew._kernels.geometry`
(issue 15 point 5). This name stays for code that still imports it."""

from __future__ import annotations

from ._kernels.geometry import seg_dist2

__all__ = ["seg_dist2"]
