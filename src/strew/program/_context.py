"""Evaluation contexts: seeds and deterministic randomness (Loi et al. §6.1).

Stationarity asks that a mapper "does not depend on a particular execution order" and
"does not depend on global coordinates". Here every random value is a pure function of
a seed and of *what* is being drawn, never of a global counter:

- ``random(cell, lo, hi, n)`` hashes (root seed, the cell's own geometry, ``n``);
- each mapper call runs in a child context whose seed hashes (parent seed, mapper name,
  the cell's geometry), so plain ``random(lo, hi)`` and partitions called inside a
  mapper (sub-scale arrangements, Fig. 3) draw from a stream of their own cell;
- each partition draws from a stream hashed from (context seed, its parameters).

So the same seed gives the same result whatever order cells are visited in, and a cell
gets the same values in any map that contains it.
"""

from __future__ import annotations

import hashlib
import struct
from collections.abc import Iterator
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass, field

import numpy as np

__all__ = [
    "Context",
    "current",
    "top",
    "evaluation",
    "script_context",
    "derive_seed",
    "unit_random",
    "Periodic",
    "periodic",
    "periodic_evaluation",
    "Field",
    "field",
    "field_evaluation",
]


def derive_seed(seed: int, *parts: object) -> int:
    """A 64-bit seed hashed from ``seed`` and ``parts`` (bytes or their ``repr``)."""
    h = hashlib.blake2b(digest_size=8)
    h.update(struct.pack("<Q", int(seed) & 0xFFFFFFFFFFFFFFFF))
    for p in parts:
        b = p if isinstance(p, bytes) else repr(p).encode()
        h.update(struct.pack("<I", len(b)))
        h.update(b)
    return int.from_bytes(h.digest(), "little")


def unit_random(seed: int, *parts: object) -> float:
    """A float in [0, 1) that is a pure function of ``seed`` and ``parts``."""
    return (derive_seed(seed, *parts) >> 11) / float(1 << 53)


@dataclass
class Context:
    """Where an evaluation is: the run's root seed and this level's seed.

    Attributes
    ----------
    root : int
        The seed of the run (``--seed``); per-cell random values hash it.
    seed : int
        This level's seed: the root at top level, a per-cell seed inside a mapper.
    """

    root: int
    seed: int
    _stream: np.random.Generator | None = field(default=None, repr=False)

    @property
    def stream(self) -> np.random.Generator:
        """The generator behind plain ``random(lo, hi)`` at this level."""
        if self._stream is None:
            self._stream = np.random.default_rng(derive_seed(self.seed, "stream"))
        return self._stream

    def rng(self, *parts: object) -> np.random.Generator:
        """A generator seeded from this level's seed and ``parts``."""
        return np.random.default_rng(derive_seed(self.seed, *parts))

    def child(self, *parts: object) -> Context:
        """The context of one mapper call."""
        return Context(self.root, derive_seed(self.seed, *parts))


_CURRENT: ContextVar[Context | None] = ContextVar("strew_program_context", default=None)
_TOP: ContextVar[Context | None] = ContextVar("strew_program_top", default=None)


def current() -> Context | None:
    """The context of the evaluation in progress, if any."""
    return _CURRENT.get()


def top() -> Context:
    """The script-level context (outside any evaluation); seed 0 unless a run set one."""
    ctx = _TOP.get()
    if ctx is None:
        ctx = Context(0, 0)
        _TOP.set(ctx)
    return ctx


@contextmanager
def evaluation(ctx: Context) -> Iterator[Context]:
    """Make ``ctx`` the current evaluation context."""
    token = _CURRENT.set(ctx)
    try:
        yield ctx
    finally:
        _CURRENT.reset(token)


@contextmanager
def script_context(seed: int) -> Iterator[Context]:
    """A fresh script-level context with root seed ``seed`` (used by ``strew run``)."""
    ctx = Context(int(seed), int(seed))
    token = _TOP.set(ctx)
    token2 = _CURRENT.set(None)
    try:
        yield ctx
    finally:
        _CURRENT.reset(token2)
        _TOP.reset(token)


# -- periodic domains (issue 18) -------------------------------------------------------------
@dataclass(frozen=True)
class Periodic:
    """A periodic evaluation: the tile, and the padded domain the script is evaluated on.

    Attributes
    ----------
    tile : (4,) float
        ``x0, y0, W, H``: the torus the arrangement repeats on.
    domain : shapely Polygon
        The tile grown by a margin: the region the top-level arrangement is evaluated on,
        so that every cell meeting the tile is whole (§6: mappers see whole faces).
    """

    tile: tuple[float, float, float, float]
    domain: object

    def shift(self, x: float, y: float) -> tuple[float, float]:
        """The whole periods that take ``(x, y)`` into the half-open tile: ``(sx, sy)`` with
        ``(x - sx, y - sy)`` canonical."""
        import math

        x0, y0, w, h = self.tile
        return (math.floor((x - x0) / w) * w, math.floor((y - y0) / h) * h)


_PERIODIC: ContextVar[Periodic | None] = ContextVar("strew_program_periodic", default=None)


def periodic() -> Periodic | None:
    """The periodic evaluation in progress, if any."""
    return _PERIODIC.get()


@contextmanager
def periodic_evaluation(p: Periodic | None) -> Iterator[Periodic | None]:
    """Make ``p`` the periodic evaluation (None: the plane)."""
    token = _PERIODIC.set(p)
    try:
        yield p
    finally:
        _PERIODIC.reset(token)


# -- tiled worlds (issue 19.1) -----------------------------------------------------------------
@dataclass(frozen=True)
class Field:
    """A world evaluation: the top-level partitions do not depend on the region.

    Tiles of a world evaluate the script on overlapping regions; for the cells they share
    to be the same to the bit, the top-level irregular partitions draw their sites from a
    field of cells fixed in the plane (:mod:`strew.program._world`), label them by the
    sites (not by their order), and stripes are polylines with vertices fixed in the plane.

    Attributes
    ----------
    domain : shapely geometry
        The region the top-level arrangement is evaluated on (one tile's, grown).
    """

    domain: object


_FIELD: ContextVar[Field | None] = ContextVar("strew_program_field", default=None)


def field() -> Field | None:
    """The world evaluation in progress, if any."""
    return _FIELD.get()


@contextmanager
def field_evaluation(f: Field | None) -> Iterator[Field | None]:
    """Make ``f`` the world evaluation (None: a plain one)."""
    token = _FIELD.set(f)
    try:
        yield f
    finally:
        _FIELD.reset(token)
