"""The studio's palette: exemplars, the selection and the synthesis state made from them.

Davison et al. 2018, §5.5: the palette is a set of exemplars with a selection
(:class:`strew.synth.Palette`), edited by hand or painted back from the scene; Ijiri et
al. 2008, §4: an exemplar's connectivity (:func:`strew.grow.analyze`), whose edges the
user flips (:func:`strew.grow.flip_edge`).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import shapely

from .._errors import Cancelled, InputError
from ..arrangement import Arrangement, concat
from ..region import Region
from ._common import Emit, _empty, _r
from ._paths import resolve_in_project
from ._protocol import get_int, get_names, get_number, get_points, get_str

__all__ = ["PaletteMixin"]


class PaletteMixin:
    """The palette part of :class:`~strew.studio._session.Session`."""


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
            arr = self._load(path, self.cancel.is_set)
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
        """Add the exemplars of a palette document (:func:`strew.synth.split_palette_document`);
        its saved selection, if any, becomes the selection."""
        from ..synth import split_palette_document

        exemplars, selection = split_palette_document(arr)
        added = [self._add_exemplar(tag, sub) for tag, sub in exemplars.items()]
        if selection is not None:
            self.selection = [s for s in selection if s in self.palette]
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
