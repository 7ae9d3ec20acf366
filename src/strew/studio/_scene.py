"""The studio's scene: the library of kinds, the scene's columns and their messages,
the region, boundary and flow strokes, the repeat view, layers and clipping.

What an element may not do (overhang the region, cross a boundary stroke) is decided by
:class:`strew.editing.Bounds`; the region is cut along boundary strokes by
:func:`strew.region.cut_along`; strokes wrap on a repeat tile by
:func:`strew.editing.wrap_stroke`.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import shapely

from .._errors import InputError
from ..arrangement import Arrangement, concat
from ..editing import Bounds, wrap_stroke
from ..region import Region, cut_along
from ._common import Emit, _empty, _r, _visible
from ._protocol import get_names, get_number, get_points, get_str

__all__ = ["SceneMixin"]


class SceneMixin:
    """The scene part of :class:`~strew.studio._session.Session`."""


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
        show = ~np.asarray(prep.void, bool)[src] & ~st.ghost  # void elements are hidden (§5.6), ghost images (repeat view) too
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

    def _out_of_bounds(self, arr: Arrangement) -> np.ndarray:
        """(n,) bool: elements not wholly inside the region, or crossing a boundary stroke
        (:meth:`strew.editing.Bounds.outside`). In the repeat view the region is a torus:
        an element may cross the tile's edges (it wraps in at the opposite ones), only
        its centre must be in the tile (:func:`strew._periodic.canonical`)."""
        tile = self._repeat_tile()
        if tile is None:
            return self._bounds().outside(arr)
        x0, y0, w, h = tile
        out = ~((arr.x >= x0) & (arr.x < x0 + w) & (arr.y >= y0) & (arr.y < y0 + h))
        if self.boundary_strokes and len(arr) and not out.all():
            # the strokes' test only: a region wide enough that nothing overhangs it
            pad = 2.0 * float(arr.radii.max()) + 1.0
            key = (tuple(tile), pad, len(self.boundary_strokes), self.boundary_strokes[-1] if self.boundary_strokes else None)
            old = self.__dict__.get("_torus_bounds_cache")
            if old is None or old[0][:3] != key[:3] or old[0][3] is not key[3]:
                old = (key, Bounds(Region.rectangle(w + 2 * pad, h + 2 * pad, x0 - pad, y0 - pad), self.boundary_strokes))
                self._torus_bounds_cache = old
            out |= old[1].outside(arr)
        return out

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
        hide = self._out_of_bounds(st.elements(idx))
        op = self._op
        if thinned and op is not None and (op.get("density", 1.0) < 1.0 or op.get("pen")):
            hide |= (st.born[idx] >= op["it0"]) | np.isin(st.element_keys(idx), op["dropped"])
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
        new = idx[st.born[idx] >= op["it0"]]
        drop = self.rng.random(len(new)) >= keep
        op["dropped"] = np.union1d(op["dropped"], st.element_keys(new[drop]))
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
        part = st.elements()
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
