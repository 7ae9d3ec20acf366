"""Random-number conventions: every random choice comes from an explicit Generator."""

from __future__ import annotations

import numpy as np

__all__ = ["as_rng", "RngLike"]

RngLike = "int | np.random.Generator | None"


def as_rng(rng: int | np.random.Generator | None) -> np.random.Generator:
    """Normalise ``rng`` (seed, Generator or None) to a ``numpy.random.Generator``.

    Examples
    --------
    >>> as_rng(1).integers(10) == as_rng(1).integers(10)
    True
    """
    if isinstance(rng, np.random.Generator):
        return rng
    if rng is not None and not isinstance(rng, (int, np.integer)):
        raise TypeError(f"rng must be an int, a numpy Generator or None, not {type(rng).__name__}")
    return np.random.default_rng(rng)
