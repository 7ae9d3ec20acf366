"""The studio's painting tools: brush, spray, eraser, filler and the palette brush.

Each tool drives a method of the library on one stroke segment at a time and streams
the change: the generative brush, filler and eraser are :mod:`strew.synth`'s (Davison
et al. 2018, §5.4); the spray is :class:`strew.grow.SprayGrowth` (Ijiri et al. 2008, §3,
§5.1). Which new elements go for overlapping is :func:`strew.editing.overlapping` and
:func:`strew.synth.drop_new_overlaps` (synth's rule, applied as elements arrive).
"""

from __future__ import annotations

import time
from typing import Any

import numpy as np
import shapely

from .._errors import Cancelled, InputError
from ..arrangement import Arrangement, concat
from ..editing import near_stroke, overlapping
from ._common import Emit, FIRST_SPRAY, TOOLS, _r
from ._protocol import get_number, get_points, get_str

__all__ = ["ToolsMixin"]


class ToolsMixin:
    """The tools of :class:`~strew.studio._session.Session`."""


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

    def _torus(self, st: Any) -> None:
        """Put the synthesis state on the torus of the repeat tile, or back in the plane
        (:meth:`strew.synth.SynthState.set_tile`), as the repeat view says."""
        tile = self._repeat_tile()
        if st.tile != (None if tile is None else tuple(tile)):
            st.set_tile(tile)

    def _canonical(self, xy: np.ndarray) -> np.ndarray:
        """(m, 2) points wrapped into the repeat tile (unchanged with the view off)."""
        tile = self._repeat_tile()
        xy = np.asarray(xy, float).reshape(-1, 2)
        if tile is None:
            return xy
        from .._periodic import canonical

        return np.c_[canonical(xy[:, 0], xy[:, 1], tile)]

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
        if self._scene_count() >= self._max_scene and tool != "erase":
            raise InputError(f"scene: over {self._max_scene} elements; erase some first")
        # in the repeat view the tools work on the torus of the tile: the library wraps
        # the segment (SynthState.set_tile, SprayGrowth(tile=...)); the eraser wraps it
        # for the fixed part of the scene (_erase)
        if tool == "brush":
            self._brush(seg, st["radius"], self._emit)
        elif tool == "spray":
            self._spray(seg, st["radius"], self._emit)
        else:
            self._erase(seg, st["radius"])
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
        self._torus(st)
        stroke = self.stroke
        assert stroke is not None
        if "face" not in stroke:
            stroke["face"] = self._face(self._canonical(pts[:1])[0])
        st.region = stroke["face"]
        # the brush discs as the state sees them (in the repeat view: wrapped, with images)
        discs, _ = st.wrap_discs(pts, np.full(len(pts), float(radius)))
        try:
            if "n_before" not in stroke:
                stroke["n_before"] = st.n
                self._op = {"n0": st.n, "density": self.brush_density, "pen": "pressure" in stroke, "it0": st.iterations, "dropped": np.zeros(0, np.int64)}
                first, first_r = st.wrap_discs(pts[:1], np.array([float(radius)]))  # in the repeat view: with its images
                near = st.n > 0 and cKDTree(st.pos).query_ball_point(first, r=radius, return_length=True).any()
                if not near:
                    # §5.4: "If there are no elements near the first brush-point, a random patch
                    # from the example-palette selection is copied to the output domain".
                    st.brush_points = np.concatenate([st.brush_points, first])
                    st.brush_radii = np.concatenate([st.brush_radii, first_r])
                    synth.seed_patch(st, (float(discs[0, 0]), float(discs[0, 1])), random=True)
                    self._drop_state_overlaps(stroke["n_before"])
                    m = self.scene_message()
                    if m is not None:
                        emit(m)
            n0 = st.n
            old = stroke["n_before"]
            reopt = bool(old) and len(cKDTree(st.pos[:old]).query_ball_point(discs, r=radius, return_length=True).nonzero()[0]) > 0

            def progress(done: int, total: int | None, message: str) -> None:
                m = self.scene_message()
                if m is not None:
                    emit(m)

            synth.brush(st, pts, radius, reoptimize=reopt, progress=progress, max_iterations=self._brush_iterations)
        finally:
            st.unwrap()  # no ghost images left (a growth that stopped on an error)
            st.region = self.region
        n0 -= int(self._settle(stroke["n_before"], thinned=False)[:n0].sum())
        self._drop_state_overlaps(n0, around=discs, reach=radius + 2.0 * float(np.max(st.prep.rbar)))
        self._thin()

    def _finish_brush(self) -> None:
        """Grow what the stroke's segments left (see :data:`strew.studio._session.BRUSH_ITERATIONS`) and clear B."""
        from .. import synth

        st = self.state
        stroke = self.stroke
        assert st is not None and stroke is not None
        n0 = st.n
        if len(st.brush_points):
            self._torus(st)
            st.region = stroke.get("face", self.region)
            try:
                synth.grow(st, should_cancel=self.cancel.is_set)
            except Cancelled:  # "stop": keep what has grown
                pass
            finally:
                st.unwrap()
                st.region = self.region
            self._drop_state_overlaps(n0, around=st.brush_points, reach=float(st.brush_radii.max()) + 2.0 * float(np.max(st.prep.rbar)))
        st.brush_points = np.zeros((0, 2))
        st.brush_radii = np.zeros(0)

    def _drop_state_overlaps(self, n0: int, around: np.ndarray | None = None, reach: float = 0.0) -> None:
        """Remove synthesis elements that overlap others, near the latest change: the
        library's rule, :func:`strew.synth.drop_new_overlaps`, with the scene's fixed
        elements and the repeat view's tile."""
        from ..synth import drop_new_overlaps

        drop_new_overlaps(self.state, n0, self.fixed, around=around, reach=reach, tile=self._repeat_tile())

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
        tile = self._repeat_tile()
        if g is None:
            if tile is None and not self.region.contains(pts).any():
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
                tile=tile,  # the repeat view: on the torus of the tile
            )
            stroke["spray"] = g
            stroke["spray_reach"] = g.reach
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
        tile = self._repeat_tile()
        if tile is not None:  # the repeat view: a tree on the torus (scene centres are in the tile)
            x0, y0, w, h = tile
            tree = cKDTree(np.asarray(self._canonical(scene.xy)) - (x0, y0), boxsize=(w, h))
        else:
            tree = cKDTree(scene.xy)
        return {"scene": scene, "tree": tree, "tile": tile, "reach": float(scene.radii.max()), "added": np.zeros(len(scene), bool)}

    def _spray_obstacles(self, g: Any, pts: np.ndarray, radius: float) -> None:
        """Hand the growth the scene elements it can reach from the segment (once each)."""
        sc = self.stroke.get("spray_scene") if self.stroke else None
        if sc is None:
            return
        # a seed within the spray radius can hold an element as wide as the widest
        # exemplar element; the margin covers both that element and the scene's widest
        margin = radius + 2.0 * sc["reach"] + 4.0 * self.stroke["spray_reach"]
        pts = np.asarray(pts, float)
        if sc.get("tile") is not None:  # the repeat view: the segment's points on the torus
            x0, y0, _, _ = sc["tile"]
            pts = np.asarray(self._canonical(pts)) - (x0, y0)
        hits = sc["tree"].query_ball_point(pts, r=margin)
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

        st = self.state
        if st is not None and st.n:
            self._torus(st)  # in the repeat view the eraser's path wraps (SynthState.stroke_path)
            synth.erase(st, pts, radius, keep=self._locked(st.elements()) if self.layers["locked"] else None)
        if len(self.fixed):
            gone = np.zeros(len(self.fixed), bool)
            for run in self._wrap_runs(pts, radius):  # one run unless the repeat view wraps the path
                gone |= near_stroke(self.fixed.xy, run, radius)
            gone &= ~self._locked(self.fixed)
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
        if self.repeat:  # a click on a copy of the repeat view fills the tile there
            p = self._canonical(p[None])[0]
        if not self.region.contains(p[None])[0]:
            raise InputError(f"fill: point {p[0]:g},{p[1]:g} is outside the region")
        self._selection()
        room = self._max_scene - self._scene_count()
        if room <= 0:
            raise InputError(f"scene: over {self._max_scene} elements; erase some first")
        self._push_history()
        self._note_compiling("synth", emit)
        st = self._ensure_state()
        self._torus(st)
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
            note = "filled" if st.n < n0 + room else f"fill stopped at the scene's limit of {self._max_scene} elements"
        except Cancelled:
            note = "fill stopped"
        except InputError:
            self._abandon()
            raise
        finally:
            st.unwrap()  # no ghost images left (a stopped fill)
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
