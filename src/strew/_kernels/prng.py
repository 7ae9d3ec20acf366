"""The one compiled random stream, seeded from the caller's Generator (issue 15 point 5).

Compiled loops draw several numbers per trial (a pose, a candidate point, an annulus
sample), and a call back into numpy's generator costs more than the rest of a rejected
trial, so the loops carry their own stream: xoshiro256+ (Blackman & Vigna), whose
(4,) uint64 state is drawn from the caller's ``numpy.random.Generator`` by
:func:`seed_state`. The same Generator state gives the same stream, so results stay
determined by ``rng`` / ``--seed``, and no global random state is touched.

Every compiled loop draws from this one stream: pack's draw loop and its Poisson-disk
sampler (``strew.pack._poisson``), which drew from a SplitMix64 stream of its own until
issue 15 point 5. That switch changed every Poisson-disk point set for a seed, and with
them pack's fill-gap Step 1 and program's uniform partitions (new bytes for a seed, the
same distribution).
"""

from __future__ import annotations

import numba
import numpy as np

__all__ = ["seed_state", "uniform", "uniforms"]

_INV53 = 1.0 / 9007199254740992.0


def seed_state(gen: np.random.Generator) -> np.ndarray:
    """(4,) uint64 state of :func:`uniform`, drawn from ``gen`` (never all zero: each
    word lies in ``[1, 2**63)``); the same ``gen`` state gives the same stream."""
    return gen.integers(1, 2**63, size=4, dtype=np.uint64)


@numba.njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def uniform(state):  # pragma: no cover - numba
    """Uniform double in [0, 1) from xoshiro256+ (``state``: (4,) uint64, not all zero;
    advanced in place). Small helpers like this one are plain kernels, not
    ``inline="always"``: LLVM inlines them just the same, while numba's own inlining
    retypes each call site (issue 16: first-run compile of pack about 15% shorter)."""
    s0, s1, s2, s3 = state[0], state[1], state[2], state[3]
    out = s0 + s3
    t = s1 << np.uint64(17)
    s2 ^= s0
    s3 ^= s1
    s1 ^= s2
    s0 ^= s3
    s2 ^= t
    s3 = (s3 << np.uint64(45)) | (s3 >> np.uint64(19))
    state[0], state[1], state[2], state[3] = s0, s1, s2, s3
    return float(out >> np.uint64(11)) * _INV53


@numba.njit(cache=True)
def uniforms(state, n):  # pragma: no cover - numba
    """(n,) uniform doubles in [0, 1) from :func:`uniform` (advances ``state``)."""
    out = np.empty(n)
    for i in range(n):
        out[i] = uniform(state)
    return out
