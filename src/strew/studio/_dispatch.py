"""The studio's messages and history: dispatch, undo/redo, settings, save, load, export."""

from __future__ import annotations

import copy
from pathlib import Path
from typing import Any

from .._errors import InputError
from ..arrangement import Arrangement
from ._common import Emit, GROW_MODES, MAX_HISTORY, PALETTE_FILE, SCENE_FILE
from ._controls import controls_message, read_setting
from ._paths import list_project_files, resolve_in_project
from ._protocol import MESSAGE_TYPES, get_points

__all__ = ["DispatchMixin"]


class DispatchMixin:
    """Dispatch, history and files of :class:`~strew.studio._session.Session`."""


    def handle(self, msg: dict[str, Any], emit: Emit | None = None) -> list[dict[str, Any]]:
        """Apply one message; returns the replies (``emit`` gets streamed partial results).

        Raises
        ------
        InputError
            For a bad field; the server turns it into an ``error`` reply.
        """
        if msg.get("type") not in MESSAGE_TYPES:
            raise InputError(f"message.type: unknown type {str(msg.get('type'))[:40]!r}")
        handler = getattr(self, "_on_" + msg["type"])
        self._emit = emit or (lambda m: None)
        return handler(msg, self._emit)

    def full_state(self) -> list[dict[str, Any]]:
        """Everything the browser needs to draw the studio from scratch."""
        msgs = [self.shapes_message(), self.palette_message(), self.strokes_message(), controls_message(), self.layers_message()]
        scene = self.scene_message(full=True)
        if scene is not None:
            msgs.append(scene)
        msgs.append(self.files_message())
        msgs.append(self.status_message())
        return msgs

    def files_message(self) -> dict[str, Any]:
        from .._resources import examples_dir

        try:
            ex = sorted(p.name for p in (examples_dir() / "exemplars").iterdir() if p.suffix in (".svg", ".json"))
        except FileNotFoundError:
            ex = []
        return {"type": "files", "files": list_project_files(self.root), "examples": ex}

    def _copy_state(self) -> Any:
        if self.state is None:
            return None
        st = self.state
        memo = {id(st.prep): st.prep, id(st.region): st.region}
        return copy.deepcopy(st, memo)

    def _snapshot(self) -> tuple:
        return (
            self.fixed,
            self._copy_state(),
            self.state_version,
            dict(self.palette),
            list(self.selection),
            self.palette_version,
            self.region,
            list(self.flow_strokes),
            list(self.boundary_strokes),
        )

    def _restore(self, snap: tuple) -> None:
        (self.fixed, self.state, self.state_version, self.palette, self.selection, pv, self.region, self.flow_strokes, self.boundary_strokes) = snap
        self._refs.clear()
        self.palette_version = pv
        self._rebuild_flow()
        self._count_outside()
        if self.state is not None and self.state_version == self.palette_version:
            from .. import synth

            sel = [n for n in self.selection if n in self.state.prep.names]
            if sel:
                synth.set_selection(self.state, sel)
            self.state.region = self.region

    def _push_history(self) -> None:
        self.undo_stack.append(self._snapshot())
        del self.undo_stack[:-MAX_HISTORY]
        self.redo_stack.clear()

    def _abandon(self) -> None:
        """Undo the half-done operation whose snapshot is on top of the history."""
        self.stroke = None
        self._op = None
        if self.undo_stack:
            self._restore(self.undo_stack.pop())

    def _all_messages(self, message: str = "") -> list[dict[str, Any]]:
        msgs = [self.shapes_message(), self.palette_message(), self.strokes_message(), self.layers_message()]
        scene = self.scene_message()
        if scene is not None:
            msgs.append(scene)
        msgs.append(self.status_message(message))
        return msgs

    def _on_undo(self, msg: dict, emit: Emit) -> list[dict]:
        if not self.undo_stack:
            return [self.status_message("nothing to undo")]
        self.redo_stack.append(self._snapshot())
        self._restore(self.undo_stack.pop())
        self.fidelity = None
        return self._all_messages("undone")

    def _on_redo(self, msg: dict, emit: Emit) -> list[dict]:
        if not self.redo_stack:
            return [self.status_message("nothing to redo")]
        self.undo_stack.append(self._snapshot())
        self._restore(self.redo_stack.pop())
        self.fidelity = None
        return self._all_messages("redone")

    def _on_hello(self, msg: dict, emit: Emit) -> list[dict]:
        self._sent = None
        self._preload()
        return self.full_state()

    def _preload(self) -> None:
        """Load :attr:`preload` (an example exemplar) into the palette on a project's first
        start, selected and analysed, so that the first stroke paints at once. Not part
        of the history (undo does not unload it)."""
        name, self.preload = self.preload, None
        if name is None or self.palette or (self.root / PALETTE_FILE).exists():
            return
        from .._resources import examples_dir

        path = examples_dir() / "exemplars" / name
        try:
            arr = self._load(path)
        except (InputError, OSError):
            return
        added = self._add_exemplar(Path(name).stem, arr.replace(region=None, meta={}))
        self.selection = [added]
        self._palette_changed()
        self._prepare()

    def _on_ping(self, msg: dict, emit: Emit) -> list[dict]:
        return [{"type": "pong", "t": msg.get("t") if isinstance(msg.get("t"), (int, float)) else None}]

    def _on_list_files(self, msg: dict, emit: Emit) -> list[dict]:
        return [self.files_message()]

    def _on_stop(self, msg: dict, emit: Emit) -> list[dict]:
        self.cancel.set()
        return []

    def _on_settings(self, msg: dict, emit: Emit) -> list[dict]:
        """Spray settings: ``grow_mode`` (Ijiri §5.3) and per-element variation (§3):
        ``jitter_scale`` (relative, below 1) and ``jitter_rotation`` (degrees)."""
        for key in ("grow_mode", "jitter_scale", "jitter_rotation", "brush_density"):
            if key in msg:  # checked by the method's Param (studio/_controls.py); angles in degrees
                setattr(self, key, read_setting(msg, key))
        if "repeat" in msg:
            if not isinstance(msg["repeat"], bool):
                raise InputError(f"repeat: expected true or false, got {str(msg['repeat'])[:40]!r}")
            if msg["repeat"]:
                self._tile()  # refuses a region that is not a rectangle
            was = self.repeat
            self.repeat = msg["repeat"]
            if self.state is not None:
                try:  # the synthesis state follows the view: on the torus of the tile or not
                    self._torus(self.state)
                except InputError:  # a tile too small for the selection's neighbourhoods
                    self.repeat = was
                    raise
        return [self.status_message()]

    def palette_arrangement(self) -> Arrangement:
        """The palette as one strew document (:func:`strew.synth.palette_document`):
        exemplars side by side, tagged by name, with the edited connectivity, the
        selection and the empty exemplars' names."""
        from ..synth import palette_document

        if not any(len(ex) for ex in self.palette.values()):
            raise InputError("save: the palette is empty")
        return palette_document(self.palette, selection=self.selection, method="studio.palette")

    def _meta(self) -> dict[str, Any]:
        from .. import __version__

        return {"generator": f"strew {__version__}", "method": "studio", "seed": self.seed}

    def _on_save(self, msg: dict, emit: Emit) -> list[dict]:
        """Save the project: ``palette.json`` and ``scene.json`` in PROJECT_DIR."""
        from ..io import save

        written = []
        if self.palette:
            save(self.palette_arrangement().with_meta(**self._meta()), self.root / PALETTE_FILE)
            written.append(PALETTE_FILE)
        scene = self.scene().replace(
            meta=self._meta(),
            extra={"studio": {"flow": [s.tolist() for s in self.flow_strokes], "boundary": [s.tolist() for s in self.boundary_strokes], "grow_mode": self.grow_mode, "layers": self.layers, "repeat": self.repeat}},
        )
        save(scene, self.root / SCENE_FILE)
        written.append(SCENE_FILE)
        return [{"type": "saved", "paths": written}, self.files_message(), self.status_message("saved " + ", ".join(written))]

    def _on_load_project(self, msg: dict, emit: Emit) -> list[dict]:
        """Load ``palette.json`` and ``scene.json`` from PROJECT_DIR (either may be missing)."""
        pal_path, scene_path = self.root / PALETTE_FILE, self.root / SCENE_FILE
        if not pal_path.is_file() and not scene_path.is_file():
            raise InputError(f"load_project: no {PALETTE_FILE} or {SCENE_FILE} in the project folder")
        # the same containment check as load_exemplar: a symbolic link out of the folder is refused
        pal = self._load(resolve_in_project(self.root, PALETTE_FILE, suffixes=(".json",), must_exist=True)) if pal_path.is_file() else None
        scene = self._load(resolve_in_project(self.root, SCENE_FILE, suffixes=(".json",), must_exist=True)) if scene_path.is_file() else None
        self._push_history()
        if pal is not None:
            self.palette = {}
            self.selection = []
            if "exemplar" in pal:
                self._split_palette(pal)
            else:
                self._add_exemplar(pal_path.stem, pal.replace(region=None, meta={}, extra={}))
            self._palette_changed()
        if scene is not None:
            studio = scene.extra.get("studio", {}) if isinstance(scene.extra.get("studio"), dict) else {}
            self.flow_strokes = [get_points({"p": s}, "p") for s in studio.get("flow", [])]
            self.boundary_strokes = [get_points({"p": s}, "p") for s in studio.get("boundary", [])]
            if studio.get("grow_mode") in GROW_MODES:
                self.grow_mode = studio["grow_mode"]
            self.repeat = studio.get("repeat") is True
            lay = studio.get("layers")
            if isinstance(lay, dict):
                self.layers = {k: [n for n in lay.get(k, []) if isinstance(n, str)] if isinstance(lay.get(k), list) else [] for k in ("order", "hidden", "locked")}
            if scene.region is not None:
                self.region = scene.region
            self.fixed = self._add_shapes(scene.replace(region=None, meta={}, extra={}), "scene")
            self.state = None
            self._rebuild_flow()
        self.fidelity = None
        self._count_outside()
        return self._all_messages("project loaded")

    def _on_export(self, msg: dict, emit: Emit) -> list[dict]:
        """Export the scene as .svg, .png or .json inside PROJECT_DIR."""
        from ..io import save

        path = resolve_in_project(self.root, msg.get("path"), suffixes=(".svg", ".png", ".json"))
        scene = self.scene().replace(meta=self._meta())
        if self.repeat:  # a repeat tile: its SVG and PNG draw it complete and seamless
            from .. import _periodic

            scene = _periodic.mark(scene, self._tile())
        save(scene, path)
        rel = path.relative_to(self.root).as_posix()
        return [{"type": "exported", "path": rel, "count": len(scene)}, self.files_message(), self.status_message(f"exported {rel}")]
