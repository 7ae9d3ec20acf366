"""One studio session: the example palette, the scene and their history.

The session is plain Python, independent of the web server: :meth:`Session.handle`
takes one parsed message and returns the replies; long operations (the filler) also
stream partial results through an ``emit`` callback. It is a thin layer over the
library:

- Davison et al. (§5.4-5.5): the generative brush, the filler and the eraser work on a
  :class:`strew.synth.SynthState` (``strew.synth.brush``, ``fill``, ``erase``); the
  palette is a set of exemplars with a selection (``strew.synth.Palette``).
- Ijiri et al. (§3): the spray, flow-field and boundary tools drive
  :func:`strew.grow.grow`; the flow field is :func:`strew.fields.flow_field`;
  connectivity edges of an exemplar come from :func:`strew.grow.analyze` and are
  flipped with :func:`strew.grow.flip_edge`.

The scene is two parts: ``fixed`` (an :class:`~strew.Arrangement` of elements that the
current synthesis state does not own: sprayed elements, a loaded scene, elements made
with an earlier palette) and ``state`` (the live synthesis output, which the brush
re-optimises). The browser sees their concatenation.

The studio holds no algorithm of its own: what an element may not do is decided by
:mod:`strew.editing` (overlaps, the region and boundary strokes, the eraser's rule,
strokes on a repeat tile) and :func:`strew.region.cut_along`; the parameter controls
come from the methods' specs (``_controls.py``).
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from .._errors import InputError
from ..arrangement import Arrangement
from ..region import Region
from ..shape import Shape
from ._common import (
    FIRST_SPRAY,
    GROW_MODES,
    MAX_HISTORY,
    PALETTE_FILE,
    PRELOAD_EXAMPLE,
    SCENE_FILE,
    TOOLS,
    Emit,
    _empty,
    _load_limited,
)
from ._dispatch import DispatchMixin
from ._palette import PaletteMixin
from ._scene import SceneMixin
from ._surface3d import Surface3DMixin
from ._tools import ToolsMixin

__all__ = ["Session", "PALETTE_FILE", "SCENE_FILE", "TOOLS", "PRELOAD_EXAMPLE", "GROW_MODES", "MAX_HISTORY", "MAX_SCENE",
           "FIRST_SPRAY", "BRUSH_ITERATIONS", "STUDIO_MAX_FILE_BYTES", "STUDIO_MAX_PATHS"]

# The session's tunables: read when used (through the properties below), so that a test
# or a benchmark may set them on this module.
MAX_SCENE = 200_000
#: Files the studio loads (exemplars, palette.json, scene.json) are checked against these
#: before parsing, so that a load answers within seconds (issue 17); the process limits
#: (strew._limits) apply when they are lower.
STUDIO_MAX_FILE_BYTES = 2_000_000
STUDIO_MAX_PATHS = 5_000
#: Region-growing iterations of the generative brush per stroke segment. Growth that is
#: left (the last few elements of a segment, which each cost a whole iteration) goes on
#: with the next segment's horizon and is finished when the stroke ends.
BRUSH_ITERATIONS = 2


class Session(DispatchMixin, ToolsMixin, PaletteMixin, SceneMixin, Surface3DMixin):
    """State of one studio: palette, selection, scene, strokes, region and history.

    Its parts live in one module each: messages, history and files
    (:mod:`._dispatch`), the painting tools (:mod:`._tools`), the palette
    (:mod:`._palette`) and the scene (:mod:`._scene`).

    Parameters
    ----------
    project_dir : path
        Every file the studio reads or writes lies inside it.
    seed : int
        Seed of the session's random generator (each operation draws its own seed from
        it, so that a session replays identically).
    size : (float, float)
        The default region: the rectangle ``[0, W] x [0, H]``.
    preload : str or None
        An example exemplar (a file name under ``examples/exemplars``) loaded into an
        empty palette at the first ``hello`` when the project has no ``palette.json``.
    """

    def __init__(self, project_dir: str | Path, *, seed: int = 0, size: tuple[float, float] = (800.0, 600.0), preload: str | None = None) -> None:
        self.root = Path(project_dir).resolve()
        if not self.root.is_dir():
            raise InputError(f"PROJECT_DIR {str(project_dir)!r}: no such folder")
        self.seed = int(seed)
        self.rng = np.random.default_rng(self.seed)
        self.shapes: dict[str, Shape] = {}
        self.kinds: list[str] = []
        self.palette: dict[str, Arrangement] = {}
        self.selection: list[str] = []
        self.region = Region.rectangle(*size)
        self.fixed = _empty({})
        self.state: Any = None
        self.state_version = -1
        self.palette_version = 0
        self.flow_strokes: list[np.ndarray] = []
        self.boundary_strokes: list[np.ndarray] = []
        self.flow: Any = None
        self.grow_mode = "fixed"
        self.jitter_scale = 0.0
        self.jitter_rotation = 0.0
        self.undo_stack: list[tuple] = []
        self.redo_stack: list[tuple] = []
        self.stroke: dict[str, Any] | None = None
        self.fidelity: dict[str, Any] | None = None  # verdict of the last operation (status bar)
        self.rate: float | None = None  # elements/s of the last operation that added elements
        self.brush_density = 1.0
        self.repeat = False  # the repeat view (issue 18.4): strokes wrap across the tile's edges
        self.layers: dict[str, list[str]] = {"order": [], "hidden": [], "locked": []}
        self.preload = preload
        self.outside = 0  # scene elements outside the region (see _count_outside)
        self._op: dict[str, Any] | None = None  # the fill or brush stroke under way (see _live_hidden)
        self.cancel = threading.Event()
        self._sent: dict[str, np.ndarray] | None = None
        self._emit: Emit = lambda m: None
        self._fixed_cache: tuple[Arrangement, dict[str, np.ndarray]] | None = None
        self._refs: dict[tuple[str, int], Any] = {}
        self._compile_noted: set[str] = set()  # methods whose compile notice was shown

    @property
    def _brush_iterations(self) -> int:
        """:data:`BRUSH_ITERATIONS`, read when used (tests set the module's value)."""
        return BRUSH_ITERATIONS

    @property
    def _max_scene(self) -> int:
        """:data:`MAX_SCENE`, read when used."""
        return MAX_SCENE

    def _load(self, path: Path, should_cancel: Callable[[], bool] | None = None) -> Arrangement:
        """Read a project file under :data:`STUDIO_MAX_FILE_BYTES` and :data:`STUDIO_MAX_PATHS`.

        An SVG import polls ``should_cancel`` once per object and stops with
        :class:`~strew._errors.Cancelled`.
        """
        return _load_limited(path, should_cancel, STUDIO_MAX_FILE_BYTES, STUDIO_MAX_PATHS)
