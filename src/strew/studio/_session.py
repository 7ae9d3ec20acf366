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
"""

from __future__ import annotations

import copy
import threading
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import shapely

from .._errors import Cancelled, InputError
from ..arrangement import Arrangement, concat
from ..region import Region
from ..shape import Shape
from ..editing import Bounds, overlap_drops, overlapping, wrap_stroke
from ..region import cut_along
from ._controls import controls_message, read_setting
from ._paths import list_project_files, resolve_in_project
from ._protocol import MESSAGE_TYPES, get_int, get_names, get_number, get_points, get_str

__all__ = ["Session", "PALETTE_FILE", "SCENE_FILE", "TOOLS"]

PALETTE_FILE = "palette.json"
SCENE_FILE = "scene.json"
TOOLS = ("brush", "spray", "erase", "flow", "boundary", "region")
GROW_MODES = ("fixed", "rotate", "flow")
#: The example exemplar loaded on a project's first start (no palette.json), so that the
#: first stroke paints with no extra click.
PRELOAD_EXAMPLE = "scales.svg"
MAX_HISTORY = 64
MAX_SCENE = 200_000
#: Files the studio loads (exemplars, palette.json, scene.json) are checked against these
#: before parsing, so that a load answers within seconds (issue 17); the process limits
#: (strew._limits) apply when they are lower.
STUDIO_MAX_FILE_BYTES = 2_000_000
STUDIO_MAX_PATHS = 5_000


def _load_limited(path: Path, should_cancel: Callable[[], bool] | None = None) -> Arrangement:
    """Read a project file under the studio's size and path-count limits.

    An SVG import polls ``should_cancel`` once per object and stops with
    :class:`~strew._errors.Cancelled` (JSON documents, bounded by the size limit, load
    in one step).
    """
    from .._limits import get_limit, limits
    from ..io import load

    with limits(file_size=min(get_limit("file_size"), STUDIO_MAX_FILE_BYTES), paths=min(get_limit("paths"), STUDIO_MAX_PATHS)):
        if Path(path).suffix.lower() == ".svg" and should_cancel is not None:
            return load(path, should_cancel=should_cancel)
        return load(path)
#: Elements of the small growth shown at once when a spray stroke starts.
FIRST_SPRAY = 24
#: Region-growing iterations of the generative brush per stroke segment. Growth that is
#: left (the last few elements of a segment, which each cost a whole iteration) goes on
#: with the next segment's horizon and is finished when the stroke ends.
BRUSH_ITERATIONS = 2

Emit = Callable[[dict[str, Any]], None]


def _r(a: np.ndarray, digits: int = 3) -> list:
    return np.round(np.asarray(a, dtype=float), digits).tolist()


def _empty(shapes: dict[str, Shape]) -> Arrangement:
    return Arrangement(shapes, np.zeros(0, np.int32), [], [])


class Session:
    """State of one studio: palette, selection, scene, strokes, region and history.

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

    # ------------------------------------------------------------------ dispatch
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

    # ------------------------------------------------------------------ library
    def _add_shapes(self, arr: Arrangement, prefix: str) -> Arrangement:
        """Merge an arrangement's kinds into the session library (renaming clashes)."""
        rename: dict[str, str] = {}
        for name, sh in arr.shapes.items():
            if name in self.shapes and self.shapes[name] != sh:
                new = f"{prefix}.{name}"
                i = 2
                while new in self.shapes and self.shapes[new] != sh:
                    new = f"{prefix}.{name}{i}"
                    i += 1
                rename[name] = new
        if rename:
            arr = arr.replace(shapes={rename.get(k, k): v for k, v in arr.shapes.items()}, kind=arr.kind)
        for name, sh in arr.shapes.items():
            if name not in self.shapes:
                self.shapes[name] = sh
                self.kinds.append(name)
        return arr

    def shapes_message(self) -> dict[str, Any]:
        out = {}
        for name in self.kinds:
            sh = self.shapes[name]
            out[name] = {
                "paths": [{"points": _r(p.points, 4), "closed": bool(p.closed)} for p in sh.paths],
                "style": {k: v for k, v in sh.style.items() if isinstance(v, (str, int, float))},
                "radius": float(sh.radius),
            }
        return {"type": "shapes", "kinds": list(self.kinds), "shapes": out}

    # ------------------------------------------------------------------ scene
    def scene(self) -> Arrangement:
        """The scene as one arrangement (fixed elements, then the synthesis output)."""
        parts = [self.fixed]
        if self.state is not None and self.state.n:
            parts.append(self.state.to_arrangement(clip=False))
        arr = concat(parts) if len(parts) > 1 else self.fixed
        return arr.replace(region=self.region)

    def _columns_of(self, arr: Arrangement) -> dict[str, np.ndarray]:
        """Columns of the visible elements of ``arr`` (:func:`strew.metrics.visible`)."""
        from ..metrics import visible

        if len(arr) and ("void" in arr or any(arr.shapes[k].is_empty for k in arr.kinds)):
            arr = arr.select(visible(arr))
        lookup = np.array([self.kinds.index(k) for k in arr.kinds], dtype=np.int64) if arr.kinds else np.zeros(0, np.int64)
        return {
            "k": lookup[arr.kind] if len(arr) else np.zeros(0, np.int64),
            "x": np.round(arr.x, 3),
            "y": np.round(arr.y, 3),
            "r": np.round(arr.rotation, 4),
            "s": np.round(arr.scale, 4),
        }

    def _arrays(self) -> dict[str, np.ndarray]:
        """Columns of :meth:`scene` as the browser gets them (kind as a library index).

        Equal to ``_columns_of(self.scene())``, but read straight from the synthesis state
        (the fixed part is cached), since it runs after every stroke segment.
        """
        if self._fixed_cache is None or self._fixed_cache[0] is not self.fixed:
            self._fixed_cache = (self.fixed, self._columns_of(self.fixed))
        fixed = self._fixed_cache[1]
        st = self.state
        if st is None or st.n == 0:
            return fixed
        prep = st.prep
        src = st.src
        # the same state, operation and region give the same columns (this runs several
        # times per stroke segment: status, scene message, counts)
        op = self._op
        key = (st.n, st.iterations, float(st.pos.sum()), int(src.sum()), len(self.boundary_strokes),
               None if op is None else (op["n0"], op.get("it0"), len(op.get("dropped", ()))))
        refs = (st, prep, self.fixed, self.region)  # held by the cache, so compared by identity
        cached = self.__dict__.get("_arrays_cache")
        if cached is not None and cached[0] == key and all(a is b for a, b in zip(cached[2], refs)):
            return cached[1]
        show = ~np.asarray(prep.void, bool)[src]  # void elements are hidden (§5.6)
        if self._op is not None and st.n > self._op["n0"]:
            show[self._op["n0"]:] &= ~self._live_hidden(self._op["n0"], thinned=True)
        src = src[show]
        lookup = np.array([self.kinds.index(k) for k in prep.shapes], dtype=np.int64)
        pos = st.pos[show]
        live = {
            "k": lookup[prep.kind[src]],
            "x": np.round(pos[:, 0], 3),
            "y": np.round(pos[:, 1], 3),
            "r": np.round(prep.rotation[src], 4),
            "s": np.round(prep.scale[src], 4),
        }
        out = {c: np.concatenate([fixed[c], live[c]]) for c in fixed}
        self._arrays_cache = (key, out, refs)
        return out

    def scene_message(self, *, full: bool = False) -> dict[str, Any] | None:
        """The change of the scene since the last message: ``replace`` or ``patch``.

        A ``patch`` updates elements ``update.index`` in place and appends ``append``;
        ``None`` when nothing changed.
        """
        new = self._arrays()
        old = self._sent
        self._sent = new
        n1 = len(new["k"])
        if full or old is None or n1 < len(old["k"]):
            return {"type": "scene", "op": "replace", "n": n1, **{c: v.tolist() for c, v in new.items()}}
        n0 = len(old["k"])
        changed = np.zeros(n0, bool)
        for c in new:
            changed |= old[c] != new[c][:n0]
        if 2 * changed.sum() > n0 + 1:
            return {"type": "scene", "op": "replace", "n": n1, **{c: v.tolist() for c, v in new.items()}}
        if n1 == n0 and not changed.any():
            return None
        idx = np.flatnonzero(changed)
        return {
            "type": "scene",
            "op": "patch",
            "n": n1,
            "update": {"index": idx.tolist(), **{c: v[idx].tolist() for c, v in new.items()}},
            "append": {c: v[n0:].tolist() for c, v in new.items()},
        }

    def _scene_count(self) -> int:
        """Elements the scene shows: the one count (:func:`strew.metrics.visible_count` of
        the scene as saved), equal to what the browser draws."""
        return len(self._arrays()["k"])

    # ------------------------------------------------------------------ bounds
    def _out_of_bounds(self, arr: Arrangement) -> np.ndarray:
        """(n,) bool: elements not wholly inside the region, or crossing a boundary stroke
        (:meth:`strew.editing.Bounds.outside`)."""
        return self._bounds().outside(arr)

    def _bounds(self) -> Bounds:
        """The region and boundary strokes as a :class:`strew.editing.Bounds` (cached
        while both stay the same objects)."""
        key = (self.region, len(self.boundary_strokes), self.boundary_strokes[-1] if self.boundary_strokes else None)
        old = self.__dict__.get("_bounds_cache")
        if old is None or len(old[0]) != len(key) or not all(a is b for a, b in zip(old[0], key)):  # held, so compared by identity
            old = (key, Bounds(self.region, self.boundary_strokes))
            self._bounds_cache = old
        return old[1]

    def _live_hidden(self, n0: int, *, thinned: bool) -> np.ndarray:
        """(st.n - n0,) bool: synthesis elements from index ``n0`` on that the operation
        under way will remove: out of bounds (:meth:`_out_of_bounds`) and, with
        ``thinned``, those not yet kept or left out by the brush density
        (:meth:`_thin`). They are hidden while the operation streams, so that the count
        never goes back."""
        st = self.state
        idx = np.arange(n0, st.n)
        hide = self._out_of_bounds(_state_part(st, idx))
        op = self._op
        if thinned and op is not None and (op.get("density", 1.0) < 1.0 or op.get("pen")):
            hide |= (st._born[idx] >= op["it0"]) | np.isin(_element_keys(st, idx), op["dropped"])
        return hide

    def _thin(self) -> None:
        """Brush density: keep each element the last segment added with probability
        ``density``, drawn from the session's generator.

        An extension of Davison §5.4 (the paper synthesises at the exemplar's density
        only; §7 names adapting density as a limitation). Elements born since the last
        call (``born >= it0``, index from the stroke's first) are new; they stay hidden
        until this decision, so none blinks. Those left out stay in the state, hidden,
        until the stroke ends (:meth:`_settle`): they hold their room, so that growth
        along the stroke does not fill the gaps again.
        """
        op, st = self._op, self.state
        if op is None or st is None or not (op.get("density", 1.0) < 1.0 or op.get("pen")):
            return
        # a pen's pressure scales the density of what its segment grew
        keep = op["density"] * (self.stroke.get("pressure", 1.0) if self.stroke is not None else 1.0)
        idx = np.arange(op["n0"], st.n)
        new = idx[st._born[idx] >= op["it0"]]
        drop = self.rng.random(len(new)) >= keep
        op["dropped"] = np.union1d(op["dropped"], _element_keys(st, new[drop]))
        op["it0"] = st.iterations + 1  # growth iterations count up before they add

    def _settle(self, n0: int, *, thinned: bool) -> np.ndarray:
        """Remove what :meth:`_live_hidden` hides (from index ``n0`` on); returns the
        (n,) mask of removed elements over the state as it was."""
        st = self.state
        if st is None or st.n <= n0:
            return np.zeros(0 if st is None else st.n, bool)
        mask = np.zeros(st.n, bool)
        mask[n0:] = self._live_hidden(n0, thinned=thinned)
        if mask.any():
            st.remove(mask)
        return mask

    # ------------------------------------------------------------------ palette
    def _usable(self) -> dict[str, Arrangement]:
        """Exemplars that synthesis can use (Davison §4.1 needs two distinct positions)."""
        from ..synth import element_parameters

        out = {}
        for name, ex in self.palette.items():
            try:
                element_parameters(ex, name=name)
            except InputError:
                continue
            out[name] = ex
        return out

    def _selection(self) -> list[str]:
        usable = self._usable()
        sel = [n for n in self.selection if n in usable]
        if not self.palette:
            raise InputError("palette: empty; load an exemplar first")
        if not sel:
            raise InputError("selection: empty; select at least one exemplar with two or more elements")
        return sel

    def _palette_changed(self) -> None:
        self.palette_version += 1
        self._refs.clear()

    def _prepare(self) -> None:
        """Analyse the selection now (Davison §5.1 precomputation), so that the next
        stroke starts without that delay; a palette that cannot be used yet is left be."""
        try:
            self._ensure_state()
        except InputError:
            pass

    def _ensure_state(self) -> Any:
        """The synthesis state for the current palette and selection (Davison §5.5).

        When the palette changed since the state was made, its elements move to the fixed
        part of the scene and a new state starts from the new palette.
        """
        from .. import synth

        sel = self._selection()
        if self.state is not None and self.state_version != self.palette_version:
            self.fixed = self.scene().replace(region=None)
            self.state = None
        if self.state is None:
            from ..synth import Palette

            self.state = synth.new_state(Palette(self._usable()), self.region, selection=sel, rng=int(self.rng.integers(2**31)))
            self.state_version = self.palette_version
        else:
            synth.set_selection(self.state, sel)
            self.state.region = self.region
        return self.state

    def _reference(self, name: str) -> Any:
        """Ijiri §4 analysis of exemplar ``name`` (cached per palette version)."""
        from ..grow import analyze

        key = (name, self.palette_version)
        if key not in self._refs:
            self._refs[key] = analyze(self.palette[name])
        return self._refs[key]

    def _edges(self, name: str) -> tuple[list, str]:
        try:
            return self._reference(name).edges.tolist(), ""
        except InputError as exc:
            return [], str(exc)

    def palette_message(self) -> dict[str, Any]:
        from ..synth import element_parameters

        items = []
        for name, ex in self.palette.items():
            lookup = np.array([self.kinds.index(k) for k in ex.kinds], dtype=np.int64) if ex.kinds else np.zeros(0, np.int64)
            try:
                r, rbar = element_parameters(ex, name=name)
                note = ""
            except InputError as exc:
                r = ex.radii
                rbar = np.full(len(ex), np.nan)
                note = str(exc)
            edges, enote = self._edges(name)
            items.append(
                {
                    "name": name,
                    "n": len(ex),
                    "selected": name in self.selection,
                    "k": lookup[ex.kind].tolist() if len(ex) else [],
                    "x": _r(ex.x),
                    "y": _r(ex.y),
                    "r": _r(ex.rotation, 4),
                    "s": _r(ex.scale, 4),
                    "radius": [None if not np.isfinite(v) else round(float(v), 3) for v in r],
                    "nradius": [None if not np.isfinite(v) else round(float(v), 3) for v in rbar],
                    "edges": edges,
                    "note": note or enote,
                }
            )
        return {"type": "palette", "exemplars": items, "selection": list(self.selection)}

    # ------------------------------------------------------------------ strokes, field, status
    def strokes_message(self) -> dict[str, Any]:
        arrows: list[list[float]] = []
        if self.flow is not None:
            x0, y0, x1, y1 = self.region.bounds
            step = max(x1 - x0, y1 - y0) / 24.0
            gx, gy = np.meshgrid(np.arange(x0 + step / 2, x1, step), np.arange(y0 + step / 2, y1, step))
            pts = np.c_[gx.ravel(), gy.ravel()]
            pts = pts[self.region.contains(pts)]
            if len(pts):
                ang = self.flow.angle(pts)
                arrows = np.round(np.c_[pts, ang], 4).tolist()
        return {
            "type": "strokes",
            "flow": [_r(s) for s in self.flow_strokes],
            "boundary": [_r(s) for s in self.boundary_strokes],
            "arrows": arrows,
            "arrow_length": float(max(self.region.bounds[2] - self.region.bounds[0], self.region.bounds[3] - self.region.bounds[1]) / 30.0),
            "region": [_r(np.asarray(ring.coords)) for poly in shapely.get_parts(self.region.geometry) for ring in [poly.exterior, *poly.interiors]],
        }

    def status_message(self, message: str = "") -> dict[str, Any]:
        rate = None
        if self.stroke is not None and self.stroke.get("compute", 0) > 0:
            rate = self.stroke["added"] / self.stroke["compute"]
        return {
            "type": "status",
            "count": self._scene_count(),
            "synth_rate": rate,
            "rate": None if self.rate is None else round(self.rate, 1),
            "fidelity": self.fidelity,
            "outside": self.outside,
            "undo": len(self.undo_stack),
            "redo": len(self.redo_stack),
            "grow_mode": self.grow_mode,
            "repeat": self._repeat_tile(),
            "message": message,
        }

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

    def _judge(self, area: Any) -> None:
        """The fidelity verdict of the last operation (:func:`strew.metrics.fidelity`).

        The scene's elements inside ``area`` (the filled face, or the stroke's discs
        within the region) are compared with the one selected exemplar. With several
        exemplars selected, or an area too small to hold an interior, there is no
        verdict (``None``): the status bar then says nothing.
        """
        import warnings

        from ..metrics import fidelity

        self.fidelity = None
        sel = [n for n in self.selection if n in self.palette]
        if len(sel) != 1 or area is None:
            return
        geom = area.geometry if isinstance(area, Region) else area
        if geom is None or geom.is_empty or geom.area <= 0:
            return
        scene = self.scene()
        if len(scene) < 2:
            return
        result = scene.select(shapely.contains_xy(geom, scene.x, scene.y)).replace(region=None)
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")  # a readout: a small area's warnings are not the user's business
                rep = fidelity(self.palette[sel[0]], result, Region(geom), eq5=False, local=False)
        except (InputError, ValueError):
            return
        self.fidelity = {"exemplar": sel[0], "faithful": bool(rep.faithful), "failures": [str(f) for f in rep.failures], "count": len(result)}

    def _outside_parts(self) -> tuple[np.ndarray, np.ndarray]:
        """Elements not wholly inside the region or crossing a boundary stroke (drawn
        before them), in unlocked layers: what ``clip`` removes. Returns (len(fixed),)
        and (state.n,) bool masks."""
        fixed = self.fixed
        out_f = self._out_of_bounds(fixed) & ~self._locked(fixed) & _visible(fixed) if len(fixed) else np.zeros(0, bool)
        st = self.state
        if st is None or st.n == 0:
            return out_f, np.zeros(0, bool)
        part = _state_part(st, np.arange(st.n))
        out_s = self._out_of_bounds(part) & ~self._locked(part) & ~np.asarray(st.prep.void, bool)[st.src]
        return out_f, out_s

    def _count_outside(self) -> None:
        """Update :attr:`outside` (the status bar offers to clip them); run after the
        region, the strokes or the scene changed other than by a tool that keeps inside."""
        out_f, out_s = self._outside_parts()
        self.outside = int(out_f.sum() + out_s.sum())

    def _on_clip(self, msg: dict, emit: Emit) -> list[dict]:
        """Remove the scene elements outside the region (offered once a region is drawn
        over a filled scene); locked layers are kept."""
        out_f, out_s = self._outside_parts()
        n = int(out_f.sum() + out_s.sum())
        if n == 0:
            self.outside = 0
            return [self.status_message("clip: no element outside the region")]
        self._push_history()
        if out_f.any():
            self.fixed = self.fixed.select(~out_f)
        if out_s.any():
            self.state.remove(out_s)
        self._count_outside()
        self.fidelity = None
        out = []
        m = self.scene_message()
        if m is not None:
            out.append(m)
        return out + [self.layers_message(), self.status_message(f"clipped: {n} elements outside the region removed")]

    def _locked(self, arr: Arrangement) -> np.ndarray:
        """(n,) bool: elements of a locked layer (kind)."""
        locked = set(self.layers["locked"])
        if not locked or len(arr) == 0:
            return np.zeros(len(arr), bool)
        return np.isin(arr.kind_names, list(locked))

    # ------------------------------------------------------------------ history
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

    # ------------------------------------------------------------------ simple messages
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
            arr = _load_limited(path)
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
            self.repeat = msg["repeat"]
        return [self.status_message()]

    # ------------------------------------------------------------------ repeat view
    def _repeat_tile(self) -> list[float] | None:
        """The tile shown by the repeat view, or None (off, or the region is no longer a rectangle)."""
        if self.repeat:
            try:
                return list(self._tile())
            except InputError:
                self.repeat = False
        return None

    def _tile(self) -> tuple[float, float, float, float]:
        """The repeat tile: the region, which must be a rectangle."""
        from .. import _periodic

        try:
            return _periodic.frame_of_region(self.region)
        except InputError:
            raise InputError("repeat: the repeat view needs a rectangular region (draw none, or set a size)") from None

    def _wrap_runs(self, seg: np.ndarray, radius: float = 0.0) -> list[np.ndarray]:
        """A stroke segment on the torus of the tile, as runs inside the tile.

        :func:`strew.editing.wrap_stroke` with the repeat view on; ``[seg]`` with it off.
        """
        if not self.repeat or len(seg) == 0:
            return [seg]
        return wrap_stroke(seg, self._tile(), radius)

    def layers_message(self) -> dict[str, Any]:
        """The layers panel: one layer per kind, in drawing order (first drawn first)."""
        order = [k for k in self.layers["order"] if k in self.shapes]
        order += [k for k in self.kinds if k not in order]
        counts: dict[str, int] = dict.fromkeys(order, 0)
        cols = self._arrays()
        if len(cols["k"]):
            for i, c in enumerate(np.bincount(cols["k"], minlength=len(self.kinds)).tolist()):
                counts[self.kinds[i]] = c
        return {
            "type": "layers",
            "layers": [{"name": k, "count": counts.get(k, 0), "hidden": k in self.layers["hidden"], "locked": k in self.layers["locked"]} for k in order],
        }

    def _on_layers(self, msg: dict, emit: Emit) -> list[dict]:
        """Set the layers (one per kind): ``order`` (drawing order, first drawn first),
        ``hidden`` and ``locked`` (names). Hidden layers are not drawn and not exported;
        locked layers are kept by the eraser and by ``clip``. Hiding is a view setting: hidden
        layers are still counted, saved and exported."""
        new = {}
        for key in ("order", "hidden", "locked"):
            if key in msg:
                names = get_names(msg, key)
                bad = [n for n in names if n not in self.shapes]
                if bad:
                    raise InputError(f"{key}: no layer {bad[0][:60]!r}")
                new[key] = list(dict.fromkeys(names))
        self.layers.update(new)
        if "locked" in new:
            self._count_outside()
        return [self.layers_message(), self.status_message()]

    # ------------------------------------------------------------------ palette messages
    def _on_load_exemplar(self, msg: dict, emit: Emit) -> list[dict]:
        """Load an exemplar (SVG or JSON) from PROJECT_DIR, or one of strew's examples."""
        if "example" in msg:
            from .._resources import examples_dir

            name = get_str(msg, "example")
            allowed = {p.name: p for p in (examples_dir() / "exemplars").iterdir()}
            if name not in allowed:
                raise InputError(f"example: no example exemplar {name[:60]!r}")
            path = allowed[name]
        else:
            path = resolve_in_project(self.root, msg.get("path"), suffixes=(".svg", ".json"), must_exist=True)
        # Runs in the server's worker thread; "stop" (or the page closing) sets self.cancel
        # and the import stops at its next object, leaving the palette as it was.
        self.cancel.clear()
        emit(self.status_message(f"loading {path.name}"))
        try:
            arr = _load_limited(path, self.cancel.is_set)
        except Cancelled:
            return [self.status_message(f"loading {path.name} stopped")]
        if len(arr) == 0:
            raise InputError(f"{path.name}: no elements in this exemplar")
        self._push_history()
        base = Path(path).stem
        # a saved palette document holds several exemplars (an "exemplar" column)
        if "exemplar" in arr and "palette" in arr.extra:
            added = self._split_palette(arr)
        else:
            added = [self._add_exemplar(base, arr.replace(region=None, meta={}))]
        if not any(n in self.selection for n in self.palette):
            self.selection = [n for n in added if len(self.palette[n]) >= 2][:1]
        self._palette_changed()
        self._prepare()
        return self._all_messages(f"loaded {', '.join(added)}")

    def _add_exemplar(self, base: str, arr: Arrangement) -> str:
        name = base
        i = 2
        while name in self.palette:
            name = f"{base}{i}"
            i += 1
        arr = self._add_shapes(arr, name)
        for col in ("radius", "neighborhood_radius"):
            if col in arr:
                arr = arr.with_columns(**{col: np.asarray(arr[col], dtype=float)})
        self.palette[name] = arr
        return name

    def _split_palette(self, arr: Arrangement) -> list[str]:
        tags = np.asarray(arr["exemplar"]).astype(str)
        info = arr.extra.get("palette", {}) if isinstance(arr.extra.get("palette"), dict) else {}
        offsets = info.get("offsets", {}) if isinstance(info.get("offsets"), dict) else {}
        conn = info.get("connectivity", {}) if isinstance(info.get("connectivity"), dict) else {}
        added = []
        for tag in dict.fromkeys(tags.tolist()):
            sub = arr.select(tags == tag).without_columns("exemplar")
            off = offsets.get(tag, (0.0, 0.0))
            try:
                dx, dy = float(off[0]), float(off[1])
            except (TypeError, ValueError, IndexError):
                raise InputError(f"palette.offsets.{tag}: must be [dx, dy]") from None
            extra = {"connectivity": {"edges": conn[tag]}} if tag in conn else {}
            sub = sub.replace(x=sub.x - dx, y=sub.y - dy, region=None, meta={}, extra=extra)
            added.append(self._add_exemplar(tag, sub))
        sel = info.get("selection")
        if isinstance(sel, list):
            self.selection = [s for s in sel if isinstance(s, str) and s in self.palette]
        return added

    def _exemplar(self, msg: dict) -> str:
        name = get_str(msg, "exemplar")
        if name not in self.palette:
            raise InputError(f"exemplar: no exemplar {name[:60]!r} in the palette")
        return name

    def _on_select(self, msg: dict, emit: Emit) -> list[dict]:
        names = get_names(msg)
        for n in names:
            if n not in self.palette:
                raise InputError(f"select: no exemplar {n[:60]!r} in the palette")
        self._push_history()
        self.selection = list(dict.fromkeys(names))
        self._prepare()
        return [self.palette_message(), self.status_message()]

    def _on_palette_new(self, msg: dict, emit: Emit) -> list[dict]:
        base = get_str(msg, "name", default="exemplar")
        self._push_history()
        name = self._add_exemplar(base, _empty(dict(self.shapes)))
        self._palette_changed()
        return [self.palette_message(), self.status_message(f"new exemplar {name}")]

    def _on_palette_remove(self, msg: dict, emit: Emit) -> list[dict]:
        name = self._exemplar(msg)
        self._push_history()
        del self.palette[name]
        self.selection = [n for n in self.selection if n != name]
        self._palette_changed()
        return [self.palette_message(), self.status_message(f"removed {name}")]

    def _on_palette_edit(self, msg: dict, emit: Emit) -> list[dict]:
        """Edit an exemplar by hand: place, move, delete an element, or set its radii (§5.5)."""
        name = self._exemplar(msg)
        ex = self.palette[name]
        op = get_str(msg, "op", choices=("place", "move", "delete", "radius"))
        n = len(ex)
        if op == "place":
            kind = get_str(msg, "kind")
            if kind not in self.shapes:
                raise InputError(f"kind: unknown kind {kind[:60]!r}")
            x, y = get_number(msg, "x", lo=-1e7, hi=1e7), get_number(msg, "y", lo=-1e7, hi=1e7)
            same = ex.kind_names == kind if n else np.zeros(0, bool)
            scale = float(np.median(ex.scale[same])) if np.any(same) else 1.0
            new = Arrangement({kind: self.shapes[kind]}, [kind], [x], [y], [0.0], [scale])
            out = concat([ex.replace(extra={}), new])
        else:
            i = get_int(msg, "index", lo=0, hi=max(n - 1, 0))
            if n == 0:
                raise InputError(f"index: exemplar {name!r} has no elements")
            if op == "move":
                x, y = get_number(msg, "x", lo=-1e7, hi=1e7), get_number(msg, "y", lo=-1e7, hi=1e7)
                xs, ys = ex.x.copy(), ex.y.copy()
                xs[i], ys[i] = x, y
                out = ex.replace(x=xs, y=ys, extra={})
            elif op == "delete":
                keep = np.ones(n, bool)
                keep[i] = False
                out = ex.select(keep).replace(extra={})
            else:
                field = get_str(msg, "field", choices=("radius", "neighborhood_radius"), default="radius")
                value = get_number(msg, "value", lo=1e-6, hi=1e7)
                col = np.asarray(ex[field], dtype=float).copy() if field in ex else np.full(n, np.nan)
                col[i] = value
                out = ex.with_columns(**{field: col})
        self._push_history()
        self.palette[name] = out
        self._palette_changed()
        return [self.palette_message(), self.status_message(f"{op} in {name}")]

    def _on_palette_flip(self, msg: dict, emit: Emit) -> list[dict]:
        """Flip a connectivity edge of an exemplar (Ijiri §4, Fig. 3); kept as its edge list."""
        from ..grow import flip_edge

        name = self._exemplar(msg)
        n = len(self.palette[name])
        i, j = get_int(msg, "i", hi=max(n - 1, 0)), get_int(msg, "j", hi=max(n - 1, 0))
        ref = flip_edge(self._reference(name), i, j)
        self._push_history()
        self.palette[name] = self.palette[name].replace(extra={"connectivity": {"edges": ref.edges.tolist()}})
        self._palette_changed()
        return [self.palette_message(), self.status_message(f"flipped edge {i},{j} of {name}")]

    def _on_palette_from_scene(self, msg: dict, emit: Emit) -> list[dict]:
        """A new exemplar from the scene elements inside a lasso (painting back, Davison §5.5)."""
        base = get_str(msg, "name", default="painted")
        scene = self.scene()
        if "points" in msg:
            poly = get_points(msg, min_points=3)
            try:
                area = Region(shapely.Polygon(poly))
            except (InputError, ValueError) as exc:
                raise InputError(f"points: not a usable lasso ({exc})") from None
            scene = scene.select(area.contains(scene.xy)) if len(scene) else scene
        if len(scene) < 2:
            raise InputError("palette_from_scene: fewer than two scene elements in the lasso")
        keep = [c for c in scene.columns if c in ("radius", "neighborhood_radius", "color")]
        cols = {c: scene[c] for c in keep}
        x0, y0 = scene.x.min(), scene.y.min()
        used = sorted(set(scene.kind_names.tolist()))
        arr = Arrangement({k: self.shapes[k] for k in used}, scene.kind_names, scene.x - x0, scene.y - y0, scene.rotation, scene.scale, columns=cols)
        self._push_history()
        name = self._add_exemplar(base, arr)
        self._palette_changed()
        return [self.palette_message(), self.status_message(f"new exemplar {name} from {len(arr)} scene elements")]

    # ------------------------------------------------------------------ scene tools
    def _on_region(self, msg: dict, emit: Emit) -> list[dict]:
        if "size" in msg:
            size = msg["size"]
            if not (isinstance(size, list) and len(size) == 2):
                raise InputError("size: must be [width, height]")
            w = get_number({"w": size[0]}, "w", lo=1e-3, hi=1e7)
            h = get_number({"h": size[1]}, "h", lo=1e-3, hi=1e7)
            region = Region.rectangle(w, h)
        else:
            region = self._region_of(get_points(msg, min_points=3))
        self._push_history()
        self._set_region(region)
        return [self.strokes_message(), self.status_message("region set")]

    def _region_of(self, pts: np.ndarray) -> Region:
        try:
            return Region(shapely.Polygon(pts))
        except (ValueError, shapely.errors.GEOSException) as exc:
            raise InputError(f"region: not a usable outline ({exc})") from None

    def _set_region(self, region: Region) -> None:
        self.region = region
        if self.state is not None:
            self.state.region = region
        self._rebuild_flow()
        self._count_outside()

    def _face(self, point: np.ndarray) -> Region:
        """The part of the region on ``point``'s side of the boundary strokes.

        Boundary strokes stop growth (Ijiri §3, Fig. 1f). :func:`strew.grow.grow` takes
        them directly; for the brush and the filler of :mod:`strew.synth`, which know
        only a region, the region is cut along the strokes (widened by half the largest
        element radius of the selection) and synthesis is confined to the piece where
        the stroke or the fill starts.
        """
        st = self.state
        half = 0.5 * float(np.max(st.prep.r)) if st is not None and len(st.prep.r) else 1.0
        return cut_along(self.region, self.boundary_strokes, point, half)

    def _rebuild_flow(self) -> None:
        from ..fields import flow_field

        self.flow = flow_field(self.flow_strokes) if self.flow_strokes else None

    def _on_clear(self, msg: dict, emit: Emit) -> list[dict]:
        what = get_str(msg, "what", choices=("scene", "flow", "boundary"))
        self._push_history()
        if what == "scene":
            self.fixed = _empty({})
            self.state = None
            self.fidelity = None
        elif what == "flow":
            self.flow_strokes = []
            self._rebuild_flow()
        else:
            self.boundary_strokes = []
        out = [self.strokes_message()]
        scene = self.scene_message()
        if scene is not None:
            out.append(scene)
        return out + [self.layers_message(), self.status_message(f"cleared {what}")]

    def _on_stroke_start(self, msg: dict, emit: Emit) -> list[dict]:
        tool = get_str(msg, "tool", choices=TOOLS)
        target = get_str(msg, "target", choices=("scene", "palette"), default="scene")
        radius = get_number(msg, "radius", default=30.0, lo=1e-3, hi=1e6)
        pts = get_points(msg)
        stroke = {"tool": tool, "target": target, "radius": radius, "points": [pts], "added": 0, "compute": 0.0, "t0": time.perf_counter()}
        if "pressure" in msg:  # a pen: its pressure scales the brush density (see _thin)
            stroke["pressure"] = get_number(msg, "pressure", lo=0.0, hi=1.0)
        if target == "palette":
            if tool != "brush":
                raise InputError("target palette: only the generative brush paints into the palette")
            stroke["exemplar"] = self._exemplar(msg)
            self._selection()
        elif tool in ("brush", "spray"):
            self._selection()
            if tool == "spray" and self.grow_mode == "flow" and self.flow is None:
                raise InputError("spray: grow mode 'flow' needs a flow field; draw flow strokes first")
        self._push_history()
        self.stroke = stroke
        if tool in ("brush", "spray") and target == "scene":
            self.rate = None  # until this stroke has its own figure
        if tool in ("brush", "spray"):
            self._note_compiling("synth" if tool == "brush" else "grow", emit)
        self.cancel.clear()
        try:
            return self._apply_segment(pts)
        except InputError:
            self._abandon()
            raise

    def _note_compiling(self, method: str, emit: Emit) -> None:
        """Say in the status bar, once per method and session, that the first stroke or
        fill compiles the method's kernels (numba's cache is empty: a fresh install),
        so that a long first stroke does not look hung (issue 16 point 3)."""
        if method in self._compile_noted:
            return
        self._compile_noted.add(method)
        from .._kernel_cache import kernels_cached

        if not kernels_cached(method):
            emit(self.status_message("compiling kernels, first run only"))

    def _abandon(self) -> None:
        """Undo the half-done operation whose snapshot is on top of the history."""
        self.stroke = None
        self._op = None
        if self.undo_stack:
            self._restore(self.undo_stack.pop())

    def _on_stroke_move(self, msg: dict, emit: Emit) -> list[dict]:
        if self.stroke is None:
            raise InputError("stroke_move: no stroke in progress (send stroke_start first)")
        pts = get_points(msg)
        if "pressure" in msg and "pressure" in self.stroke:
            self.stroke["pressure"] = get_number(msg, "pressure", lo=0.0, hi=1.0)
        self.stroke["points"].append(pts)
        return self._apply_segment(pts)

    def _on_stroke_end(self, msg: dict, emit: Emit) -> list[dict]:
        if self.stroke is None:
            raise InputError("stroke_end: no stroke in progress")
        out: list[dict] = []
        if msg.get("points"):
            pts = get_points(msg)
            self.stroke["points"].append(pts)
            out += self._apply_segment(pts)
        stroke = self.stroke
        allpts = np.concatenate(stroke["points"])
        tool = stroke["tool"]
        note = ""
        try:
            if stroke["target"] == "palette":
                if "pstate" not in stroke:  # a click without a move paints too
                    self._paint_palette(allpts, stroke["radius"])
                painted = len(self.palette[stroke["exemplar"]]) - len(stroke["base"])
                self._palette_changed()
                self._prepare()
                note = f"painted {painted} elements into {stroke['exemplar']}"
                out.append(self.palette_message())
            elif tool == "flow":
                if len(allpts) < 2 or not np.any(np.linalg.norm(np.diff(allpts, axis=0), axis=1) > 0):
                    raise InputError("flow: a flow stroke needs two distinct points")
                self.flow_strokes.append(allpts)
                self._rebuild_flow()
                out.append(self.strokes_message())
            elif tool == "boundary":
                if len(allpts) < 2:
                    raise InputError("boundary: a boundary stroke needs two points")
                self.boundary_strokes.append(allpts)
                out.append(self.strokes_message())
            elif tool == "region":
                self._set_region(self._region_of(allpts))
                out.append(self.strokes_message())
        except InputError:
            self._abandon()
            raise
        if tool == "brush" and stroke["target"] == "scene" and self.state is not None and self.state.n:
            before = self._scene_count()
            t = time.perf_counter()
            self._finish_brush()
            if "n_before" in stroke:
                self._thin()
                self._settle(stroke["n_before"], thinned=True)
            self._op = None
            stroke["compute"] += time.perf_counter() - t
            stroke["added"] += max(0, self._scene_count() - before)
            m = self.scene_message()
            if m is not None:
                out.append(m)
        self._op = None
        if tool in ("boundary", "erase"):
            self._count_outside()
        if tool in ("brush", "spray", "erase"):
            if tool == "erase":
                note = f"erase: {stroke.get('removed', 0)} elements removed"
            else:
                note = note or f"{tool}: {stroke['added']} elements added"
        self.stroke = None
        if tool in ("brush", "spray", "erase"):
            out.append(self.layers_message())  # the layers' counts
        if tool in ("brush", "spray") and stroke["target"] == "scene":
            self.rate = stroke["added"] / stroke["compute"] if stroke["added"] and stroke["compute"] > 0 else None
            area = shapely.union_all([shapely.LineString(r).buffer(stroke["radius"]) if len(r) > 1 else shapely.Point(r[0]).buffer(stroke["radius"]) for r in self._wrap_runs(allpts)])
            self._judge(shapely.intersection(area, stroke.get("face", self.region).geometry))
        return out + [self.status_message(note)]

    def _apply_segment(self, pts: np.ndarray) -> list[dict]:
        """Run the stroke's tool on one segment; returns the streamed scene change."""
        st = self.stroke
        assert st is not None
        tool = st["tool"]
        if tool in ("flow", "boundary", "region"):
            return [{"type": "stroke_echo", "tool": tool, "points": _r(pts)}]
        prev = self.stroke["points"][-2][-1:] if len(self.stroke["points"]) > 1 else np.zeros((0, 2))
        seg = np.concatenate([prev, pts])
        if st["target"] == "palette":
            self._paint_palette(seg, st["radius"])
            return [self.palette_message(), self.status_message()]
        t = time.perf_counter()
        before = self._scene_count()
        if self._scene_count() >= MAX_SCENE and tool != "erase":
            raise InputError(f"scene: over {MAX_SCENE} elements; erase some first")
        for run in self._wrap_runs(seg, st["radius"]):  # one run unless the repeat view wraps the stroke
            if tool == "brush":
                self._brush(run, st["radius"], self._emit)
            elif tool == "spray":
                self._spray(run, st["radius"], self._emit)
            else:
                self._erase(run, st["radius"])
        st["compute"] += time.perf_counter() - t
        st["added"] += max(0, self._scene_count() - before)
        st["removed"] = st.get("removed", 0) + max(0, before - self._scene_count())
        msg = self.scene_message()
        out = [msg] if msg is not None else []
        return out + [self.status_message()]

    def _brush(self, pts: np.ndarray, radius: float, emit: Emit) -> None:
        """Generative brush (Davison §5.4) on one stroke segment.

        At the stroke's first point in empty space the random seed patch of §5.4 is
        copied and shown at once, before region growing continues along the segment;
        partial results stream out while a segment grows. Elements that existed before
        the stroke are re-optimised toward the selection when the brush passes over them
        (§5.4); those the stroke itself made are not re-optimised at every segment.
        """
        from .. import synth
        from scipy.spatial import cKDTree

        st = self._ensure_state()
        stroke = self.stroke
        assert stroke is not None
        if "face" not in stroke:
            stroke["face"] = self._face(pts[0])
        st.region = stroke["face"]
        try:
            if "n_before" not in stroke:
                stroke["n_before"] = st.n
                self._op = {"n0": st.n, "density": self.brush_density, "pen": "pressure" in stroke, "it0": st.iterations, "dropped": np.zeros(0, np.int64)}
                near = st.n > 0 and len(cKDTree(st.pos).query_ball_point(pts[0], r=radius)) > 0
                if not near:
                    # §5.4: "If there are no elements near the first brush-point, a random patch
                    # from the example-palette selection is copied to the output domain".
                    st.brush_points = np.concatenate([st.brush_points, pts[:1]])
                    st.brush_radii = np.concatenate([st.brush_radii, [radius]])
                    synth.seed_patch(st, (float(pts[0, 0]), float(pts[0, 1])), random=True)
                    self._drop_state_overlaps(stroke["n_before"])
                    m = self.scene_message()
                    if m is not None:
                        emit(m)
            n0 = st.n
            old = stroke["n_before"]
            reopt = bool(old) and len(cKDTree(st.pos[:old]).query_ball_point(pts, r=radius, return_length=True).nonzero()[0]) > 0

            def progress(done: int, total: int | None, message: str) -> None:
                m = self.scene_message()
                if m is not None:
                    emit(m)

            synth.brush(st, pts, radius, reoptimize=reopt, progress=progress, max_iterations=BRUSH_ITERATIONS)
        finally:
            st.region = self.region
        n0 -= int(self._settle(stroke["n_before"], thinned=False)[:n0].sum())
        self._drop_state_overlaps(n0, around=pts, reach=radius + 2.0 * float(np.max(st.prep.rbar)))
        self._thin()

    def _finish_brush(self) -> None:
        """Grow what the stroke's segments left (see :data:`BRUSH_ITERATIONS`) and clear B."""
        from .. import synth

        st = self.state
        stroke = self.stroke
        assert st is not None and stroke is not None
        n0 = st.n
        if len(st.brush_points):
            st.region = stroke.get("face", self.region)
            try:
                synth.grow(st, should_cancel=self.cancel.is_set)
            except Cancelled:  # "stop": keep what has grown
                pass
            finally:
                st.region = self.region
            self._drop_state_overlaps(n0, around=st.brush_points, reach=float(st.brush_radii.max()) + 2.0 * float(np.max(st.prep.rbar)))
        st.brush_points = np.zeros((0, 2))
        st.brush_radii = np.zeros(0)

    def _drop_state_overlaps(self, n0: int, around: np.ndarray | None = None, reach: float = 0.0) -> None:
        """Remove synthesis elements that overlap others, near the latest change.

        A new element (index >= n0) goes when it overlaps a fixed scene element. When no
        exemplar of the selection has overlapping shapes (``prep.overlap_free``), the
        later of any two overlapping synthesis elements goes too: the rule by which
        :meth:`strew.synth.SynthState.to_arrangement` leaves them out of the output,
        applied here as elements arrive, so that what the browser shows is what is saved
        and exported. Older elements are checked near the new ones and, when ``around``
        (m, 2) is given, within ``reach`` of those points (optimisation moves them).
        """
        from scipy.spatial import cKDTree

        from ..metrics import overlaps

        st = self.state
        if st is None or st.n <= n0:
            return
        prep = st.prep
        overlap_free = bool(getattr(prep, "overlap_free", False))
        if not overlap_free and len(self.fixed) == 0:
            return
        pos = st.pos

        def state_part(idx: np.ndarray) -> Arrangement:
            return _state_part(st, idx)

        new_idx = np.arange(n0, st.n)
        rmax = float(np.max(state_part(new_idx).radii))
        cand = new_idx
        if overlap_free and n0:
            old_xy = pos[:n0]
            r_old = state_part(np.arange(n0)).radii
            hits = cKDTree(pos[new_idx]).query_ball_point(old_xy, r=r_old + rmax, return_length=True) > 0
            if around is not None and len(around):
                hits |= cKDTree(np.asarray(around, float)).query_ball_point(old_xy, r=reach, return_length=True) > 0
            cand = np.concatenate([np.flatnonzero(hits), new_idx])
        local = state_part(cand)
        fixed = self.fixed.replace(columns={}, meta={}, extra={}, region=None)
        if len(fixed):
            tree = cKDTree(local.xy)
            near = tree.query_ball_point(fixed.xy, r=fixed.radii + float(np.max(local.radii)), return_length=True) > 0
            fixed = fixed.select(near)
        combined = concat([fixed, local]) if len(fixed) else local
        nf = len(fixed)
        pairs, _ = overlaps(combined)
        dropped = overlap_drops(pairs, nf, cand >= n0, later=overlap_free)
        if dropped.any():
            mask = np.zeros(st.n, bool)
            mask[cand[dropped]] = True
            st.remove(mask)

    def _spray(self, pts: np.ndarray, radius: float, emit: Emit) -> None:
        """Spray (Ijiri §3, §5.1): one growth that follows the stroke, only within ``radius``.

        §5.1: "we generate an initial seed at the cursor position when the user starts
        painting and grow all the seeds which are in the user-specified distance from the
        cursor during painting". The stroke keeps one :class:`strew.grow.SprayGrowth`;
        each segment adds its points and grows the seeds they reach. Scene elements near
        the segment are obstacles of the growth, so nothing overlaps the scene. New
        elements stream out in chunks (the first :data:`FIRST_SPRAY` at once), each
        emitted as it is handed out.
        """
        from .._errors import Cancelled

        stroke = self.stroke
        assert stroke is not None
        g = stroke.get("spray")
        first = g is None
        if g is None:
            if not self.region.contains(pts).any():
                return
            from ..grow import SprayGrowth

            g = SprayGrowth(
                self._reference(self._selection()[0]),
                radius=radius,
                region=self.region,
                mode=self.grow_mode,
                flow=self.flow,
                boundary=self.boundary_strokes or None,
                jitter_scale=self.jitter_scale,
                jitter_rotation=self.jitter_rotation,
                rng=int(self.rng.integers(2**31)),
            )
            stroke["spray"] = g
            stroke["spray_reach"] = self._spray_reach(self._selection()[0])
            stroke["spray_scene"] = self._spray_scene()
        self._spray_obstacles(g, pts, radius)
        g.add_points(pts)
        chunk_size = 128  # elements per streamed chunk after the first (about 50 ms of growth)
        chunk = FIRST_SPRAY if first else chunk_size
        while True:
            try:
                out = g.grow(chunk, should_cancel=self.cancel.is_set)
            except Cancelled:  # "stop": keep what has grown
                out = g.grow(0)
                self._add_grown(out, free=True)
                return
            self._add_grown(out, free=True)
            if not g.pending:
                return
            if len(out):
                m = self.scene_message()
                if m is not None:
                    emit(m)
                    time.sleep(0)  # let the server's event loop send it (growth holds the GIL)
            chunk = chunk_size

    def _spray_reach(self, name: str) -> float:
        """Bounding radius of the widest element a spray growth from exemplar ``name`` can
        place: its widest kind at its largest scale, jittered (Ijiri §3). The growth
        knows it too; it does not say so publicly."""
        ex = self.palette[name]
        widest = max((ex.shapes[k].radius for k in ex.kinds), default=0.0)
        top = float(np.max(ex.scale)) if len(ex) else 1.0
        return widest * max(1.0, top * (1.0 + self.jitter_scale))

    def _spray_scene(self) -> dict[str, Any] | None:
        """The scene when a spray stroke starts, indexed for :meth:`_spray_obstacles`."""
        from scipy.spatial import cKDTree

        # the scene as the browser shows it (see _arrays), without scene()'s overlap
        # clean-up pass over the whole synthesis output (0.4 s at 150,000 elements)
        parts = [self.fixed]
        if self.state is not None and self.state.n:
            parts.append(self.state.to_arrangement(clip=False, drop_overlaps=False))
        scene = concat(parts) if len(parts) > 1 else self.fixed
        if len(scene) == 0:
            return None
        return {"scene": scene, "tree": cKDTree(scene.xy), "reach": float(scene.radii.max()), "added": np.zeros(len(scene), bool)}

    def _spray_obstacles(self, g: Any, pts: np.ndarray, radius: float) -> None:
        """Hand the growth the scene elements it can reach from the segment (once each)."""
        sc = self.stroke.get("spray_scene") if self.stroke else None
        if sc is None:
            return
        # a seed within the spray radius can hold an element as wide as the widest
        # exemplar element; the margin covers both that element and the scene's widest
        margin = radius + 2.0 * sc["reach"] + 4.0 * self.stroke["spray_reach"]
        hits = sc["tree"].query_ball_point(np.asarray(pts, float), r=margin)
        idx = np.unique(np.concatenate([np.asarray(h, dtype=np.intp) for h in hits])) if len(hits) else np.zeros(0, np.intp)
        idx = idx[~sc["added"][idx]]
        if len(idx):
            sc["added"][idx] = True
            g.add_obstacles(sc["scene"].select(idx))

    def _add_grown(self, out: Arrangement, *, free: bool = False) -> None:
        """Add grown elements to the fixed part of the scene, leaving out those that overlap it.

        ``free``: the growth already kept them off the scene (its obstacles).
        """
        if len(out) == 0:
            return
        out = out.replace(meta={}, extra={}, region=None)
        out = out.select(~self._out_of_bounds(out))  # no overhang, nothing across a boundary stroke
        if not free:
            scene = self.scene()
            if len(scene):
                out = out.select(~overlapping(out, scene))
        if len(out):
            self.fixed = concat([self.fixed, out]).replace(region=None) if len(self.fixed) else out

    def _erase(self, pts: np.ndarray, radius: float) -> None:
        """Eraser (Davison §5.4): elements whose centre lies within ``radius`` of the path."""
        from .. import synth

        path = shapely.LineString(pts) if len(pts) > 1 else shapely.Point(pts[0])
        if self.state is not None and self.state.n:
            if self.layers["locked"]:  # the same rule as synth.erase, locked layers kept
                st = self.state
                part = _state_part(st, np.arange(st.n))
                gone = shapely.dwithin(path, shapely.points(part.xy), radius) & ~self._locked(part)
                if gone.any():
                    st.remove(gone)
            else:
                synth.erase(self.state, pts, radius)
        if len(self.fixed):
            gone = shapely.dwithin(path, shapely.points(self.fixed.xy), radius) & ~self._locked(self.fixed)
            if gone.any():
                self.fixed = self.fixed.select(~gone)

    def _paint_palette(self, seg: np.ndarray, radius: float) -> int:
        """The generative brush painting into a palette exemplar (Davison §5.5), one segment.

        The selection (less the exemplar painted into) drives a synthesis state of its
        own; after every segment the exemplar is its elements from before the stroke plus
        that state's output, less what would overlap them, so the palette panel follows
        the stroke. Returns the number of painted elements so far.
        """
        from .. import synth
        from ..synth import Palette

        st = self.stroke
        assert st is not None
        name = st["exemplar"]
        if "pstate" not in st:
            usable = {k: v for k, v in self._usable().items() if k != name}
            sel = [n for n in self._selection() if n != name]
            if not sel:
                raise InputError("palette brush: select an exemplar other than the one painted into")
            st["pstate"] = synth.new_state(Palette(usable), None, selection=sel, rng=int(self.rng.integers(2**31)))
            st["base"] = self.palette[name].replace(extra={})
        ps, base = st["pstate"], st["base"]
        synth.brush(ps, seg, radius)
        out = ps.to_arrangement(clip=False) if ps.n else None
        if out is None or len(out) == 0:
            return 0
        if len(base):
            out = out.select(~overlapping(out, base))
        keep = {c: out[c] for c in ("radius", "neighborhood_radius") if c in out}
        out = Arrangement(out.shapes, out.kind_names, out.x, out.y, out.rotation, out.scale, columns=keep)
        merged = concat([base, out]) if len(base) else out
        self.palette[name] = merged.replace(meta={}, region=None, extra={})
        return len(out)

    def _on_fill(self, msg: dict, emit: Emit) -> list[dict]:
        """Filler (Davison §5.4): grow from a point until no room is left in the region."""
        from .. import synth

        p = get_points(msg, "point")[0]
        if not self.region.contains(p[None])[0]:
            raise InputError(f"fill: point {p[0]:g},{p[1]:g} is outside the region")
        self._selection()
        room = MAX_SCENE - self._scene_count()
        if room <= 0:
            raise InputError(f"scene: over {MAX_SCENE} elements; erase some first")
        self._push_history()
        self._note_compiling("synth", emit)
        st = self._ensure_state()
        self.cancel.clear()
        n0 = st.n
        count0 = self._scene_count()
        t = time.perf_counter()

        def progress(done: int, total: int | None, message: str) -> None:
            m = self.scene_message()
            if m is not None:
                emit(m)
                # the one count: what the browser shows (overhanging elements hidden)
                emit(self.status_message(f"filling: {self._scene_count() - count0} elements"))

        face = self._face(p)
        st.region = face
        self._op = {"n0": n0}
        self.rate = None  # until this fill has its own figure
        try:
            synth.fill(st, (float(p[0]), float(p[1])), progress=progress, should_cancel=self.cancel.is_set, max_elements=n0 + room)
            note = "filled" if st.n < n0 + room else f"fill stopped at the scene's limit of {MAX_SCENE} elements"
        except Cancelled:
            note = "fill stopped"
        except InputError:
            self._abandon()
            raise
        finally:
            st.region = self.region
            if self.state is st:  # not abandoned
                self._settle(n0, thinned=False)
            self._op = None
        self._drop_state_overlaps(n0)
        dt = time.perf_counter() - t
        added = max(0, self._scene_count() - count0)
        self.rate = added / dt if dt > 0 and added else self.rate
        # the result is shown at once; the verdict follows (it takes a fraction of the fill)
        self.fidelity = None
        final = f"{note}: {added} elements in {dt:.2f} s"
        m = self.scene_message()
        if m is not None:
            emit(m)
        emit(self.layers_message())
        emit(self.status_message(final))
        self._judge(face)
        return [self.status_message(final)]

    # ------------------------------------------------------------------ files
    def palette_arrangement(self) -> Arrangement:
        """The palette as one strew document: exemplars side by side, tagged by name.

        The layout is the one :class:`strew.synth.Palette` reads (column ``exemplar``,
        ``extra["palette"]["offsets"]``), with the edited connectivity and the selection.
        """
        parts, offsets, conn = [], {}, {}
        x = 0.0
        for name, ex in self.palette.items():
            if len(ex) == 0:
                continue
            b = ex.bounds
            dx, dy = x - b[0], -b[1]
            offsets[name] = [dx, dy]
            if "connectivity" in ex.extra:
                conn[name] = ex.extra["connectivity"]["edges"]
            parts.append(ex.replace(x=ex.x + dx, y=ex.y + dy, region=None, meta={}, extra={}).with_columns(exemplar=[name] * len(ex)))
            x += (b[2] - b[0]) + 0.1 * max(b[2] - b[0], b[3] - b[1], 1e-9)
        if not parts:
            raise InputError("save: the palette is empty")
        arr = concat(parts)
        return arr.replace(meta={"method": "studio.palette"}, extra={"palette": {"offsets": offsets, "connectivity": conn, "selection": list(self.selection)}})

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
        pal = _load_limited(resolve_in_project(self.root, PALETTE_FILE, suffixes=(".json",), must_exist=True)) if pal_path.is_file() else None
        scene = _load_limited(resolve_in_project(self.root, SCENE_FILE, suffixes=(".json",), must_exist=True)) if scene_path.is_file() else None
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


def _element_keys(st: Any, idx: np.ndarray) -> np.ndarray:
    """(len(idx),) int64 keys naming synthesis elements across removals: each element's
    free-space block (allocated afresh for every added or re-assigned element) and source."""
    return (st._free_base[idx].astype(np.int64) << 20) | st.src[idx].astype(np.int64)


def _visible(arr: Arrangement) -> np.ndarray:
    from ..metrics import visible

    return visible(arr)


def _state_part(st: Any, idx: np.ndarray) -> Arrangement:
    """Elements ``idx`` of a synthesis state as an arrangement (no columns)."""
    prep, src, pos = st.prep, st.src, st.pos
    return Arrangement(prep.shapes, prep.kind[src[idx]].astype(np.int64), pos[idx, 0], pos[idx, 1], prep.rotation[src[idx]], prep.scale[src[idx]])
