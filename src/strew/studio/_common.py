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



def _visible(arr: Arrangement) -> np.ndarray:
    from ..metrics import visible

    return visible(arr)


