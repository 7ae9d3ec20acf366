"""Constants and small helpers shared by the studio session's parts."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from ..arrangement import Arrangement
from ..shape import Shape

PALETTE_FILE = "palette.json"
SCENE_FILE = "scene.json"
TOOLS = ("brush", "spray", "erase", "flow", "boundary", "region")
GROW_MODES = ("fixed", "rotate", "flow")
#: The example exemplar loaded on a project's first start (no palette.json), so that the
#: first stroke paints with no extra click.
PRELOAD_EXAMPLE = "scales.svg"
MAX_HISTORY = 64
#: Elements of the small growth shown at once when a spray stroke starts.
FIRST_SPRAY = 24

Emit = Callable[[dict[str, Any]], None]


def _load_limited(path: Path, should_cancel: Callable[[], bool] | None, max_bytes: int, max_paths: int) -> Arrangement:
    """Read a project file under the studio's size and path-count limits (``max_bytes``,
    ``max_paths``; the process limits of :mod:`strew._limits` apply when lower).

    An SVG import polls ``should_cancel`` once per object and stops with
    :class:`~strew._errors.Cancelled` (JSON documents, bounded by the size limit, load
    in one step).
    """
    from .._limits import get_limit, limits
    from ..io import load

    with limits(file_size=min(get_limit("file_size"), max_bytes), paths=min(get_limit("paths"), max_paths)):
        if Path(path).suffix.lower() == ".svg" and should_cancel is not None:
            return load(path, should_cancel=should_cancel)
        return load(path)



def _r(a: np.ndarray, digits: int = 3) -> list:
    return np.round(np.asarray(a, dtype=float), digits).tolist()



def _empty(shapes: dict[str, Shape]) -> Arrangement:
    return Arrangement(shapes, np.zeros(0, np.int32), [], [])



# The synthesis state's elements as the studio needs them. _element_keys reads two
# private arrays of strew.synth's state (_free_base, _born), here and nowhere else: the
# hooks strew.synth should expose are listed in _state_part's docstring.
def _element_keys(st: Any, idx: np.ndarray) -> np.ndarray:
    """(len(idx),) int64 keys naming synthesis elements across removals: each element's
    free-space block (allocated afresh for every added or re-assigned element) and source."""
    return (st._free_base[idx].astype(np.int64) << 20) | st.src[idx].astype(np.int64)



def _born(st: Any, idx: np.ndarray) -> np.ndarray:
    """(len(idx),) int: the growth iteration in which each synthesis element was added."""
    return st._born[idx]


def _visible(arr: Arrangement) -> np.ndarray:
    from ..metrics import visible

    return visible(arr)



def _state_part(st: Any, idx: np.ndarray) -> Arrangement:
    """Elements ``idx`` of a synthesis state as an arrangement (no columns).

    Hooks wanted from :mod:`strew.synth` so that the studio reads no private state:
    ``SynthState.elements(idx) -> Arrangement`` (this function),
    ``SynthState.element_keys(idx)`` (:func:`_element_keys`), ``SynthState.born`` (the
    iteration each element was added in) and a public ``overlap_free`` on the state.
    """
    prep, src, pos = st.prep, st.src, st.pos
    return Arrangement(prep.shapes, prep.kind[src[idx]].astype(np.int64), pos[idx, 0], pos[idx, 1], prep.rotation[src[idx]], prep.scale[src[idx]])

