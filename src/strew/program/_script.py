"""SVG in and out (Table 5: ImportSVG, ExportSVG), and running scripts (``strew run``).

Output convention (§3, "Overview example"): induced faces are exported as closed paths
and edges as open paths. Each cell is one element of a strew
:class:`~strew.arrangement.Arrangement` with its own shape (bounded faces first, then
edges), placed at its bounding-box centre, with columns ``cell`` ("face" / "edge") and
``labels`` (space-separated).
"""

from __future__ import annotations

import hashlib
import math
import os
import runpy
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from contextvars import ContextVar
from pathlib import Path
from typing import Any

import numpy as np

from .._errors import InputError
from .._limits import MAX_COORD
from .._method import MethodSpec, Param
from ..arrangement import Arrangement
from ..region import Region
from ..shape import Path as ShapePath
from ..shape import Shape
from ._context import script_context, top
from ._curves import Curve, Curves
from ._operators import ArrangementFunction, MapperError, as_arrangement
from ._planar_map import PlanarMap

__all__ = ["import_svg", "export_svg", "to_strew", "run", "run_script", "run_size", "evaluate", "ScriptError", "SPEC"]

_IN_RUN: ContextVar[bool] = ContextVar("strew_program_in_run", default=False)
_RUN_SIZE: ContextVar[float | None] = ContextVar("strew_program_run_size", default=None)
_SVG_CACHE: dict[tuple[str, int, int], Curves] = {}


class ScriptError(InputError):
    """A program script failed; the message names the script and the line."""


# -- import ---------------------------------------------------------------------------------
def import_svg(filename: str | os.PathLike[str], *, tolerance: float | None = None) -> Curves:
    """ImportSVG(String filename): loads curves from an SVG file.

    Every drawn path and basic shape becomes curves (one per sub-path, flattened to
    polylines; closed sub-paths are closed curves), with every transform applied, in the
    file's *user units*: the numbers it is written in, so a point drawn at ``cx="0"`` is
    at 0 in the script whatever the ``viewBox`` (issue 15 point 5; before, curves came in
    viewport coordinates, shifted by the viewBox's origin). An element's Inkscape label,
    or else its id when the id is not an editor's automatic one (``path123``), labels
    its curves (see :func:`curve_labeled`); curves without one take their group's or
    clone's. A labelled ``<circle>`` or ``<ellipse>`` is a labelled *point* at its
    centre, such as ``"start"`` and ``"end"`` (see :func:`point_labeled`), not a curve.
    Hidden layers and objects are left out. The file is read by
    :func:`strew.io.svg.read_svg_curves`, the exemplar reader's walk of the document
    (``<use>`` clones and symbols, the file size and path limits).

    Parameters
    ----------
    filename : path
    tolerance : float, optional
        Largest distance between a curved segment and its polyline, in the file's user
        units (as for :func:`strew.io.svg.read_svg`); default 1/2000 of the drawing's
        diagonal. Before issue 15 it was a step along the curve: ``tolerance=2.0`` on a
        circle of radius 13 (42 points) is now about ``tolerance=0.04``.
    """
    from ..io.svg import read_svg_curves

    path = Path(filename)
    try:
        st = path.stat()
    except FileNotFoundError:
        raise InputError(f"import_svg: {str(filename)!r}: no such file") from None
    key = (str(path.resolve()), st.st_mtime_ns, hash(tolerance))
    if key in _SVG_CACHE:
        return _SVG_CACHE[key]
    read, points = read_svg_curves(path, tolerance=tolerance, what="import_svg")
    curves = [Curve(xy, closed, frozenset([label]) if label else frozenset()) for xy, closed, label in read]
    if not curves and not points:
        raise InputError(f"import_svg: {path.name}: no curves or labelled points found")
    out = Curves(tuple(curves), points)
    _SVG_CACHE[key] = out
    return out


# -- export ---------------------------------------------------------------------------------
# a label's colour: light for face fills, a dark shade of the same hue for edges, which
# are thin lines that must read on white and on the light fills (contrast ratio against
# white at least 4.5 for every stroke colour; tested)
_PALETTE = ["#e8c547", "#5d9bd5", "#e07a5f", "#81b29a", "#b388d9", "#f2a65a", "#6cc3c1", "#d16b8f"]
_STROKE_PALETTE = ["#7a5f00", "#1f5f9e", "#a8361b", "#2e6b4f", "#6a3d9a", "#9a4d00", "#16706e", "#9e2a5b"]


def _label_color(labels: frozenset[str], palette: list[str] = _PALETTE) -> str:
    h = hashlib.blake2b(" ".join(sorted(labels)).encode(), digest_size=2).digest()
    return palette[int.from_bytes(h, "little") % len(palette)]


def to_strew(pm: PlanarMap, region: Region | None = None, *, stroke_width: float | None = None) -> Arrangement:
    """A planar map as a strew Arrangement: faces as closed paths, edges as open paths.

    Parameters
    ----------
    pm : PlanarMap
    region : Region, optional
        Recorded as the arrangement's region.
    stroke_width : float, optional
        Edge width (default: 1/1000 of the drawing's size).

    Returns
    -------
    Arrangement
        One element per bounded face (kind ``face-i``), then one per edge (``edge-i``);
        columns ``cell`` and ``labels``.
    """
    t = pm._t
    if stroke_width is None:
        if region is not None:
            x0, y0, x1, y1 = region.bounds
        elif len(pm.vertex_xy):
            (x0, y0), (x1, y1) = pm.vertex_xy.min(axis=0), pm.vertex_xy.max(axis=0)
        else:
            x0 = y0 = 0.0
            x1 = y1 = 1000.0
        stroke_width = max(x1 - x0, y1 - y0, 1e-9) / 1000.0
    shapes: dict[str, Shape] = {}
    xs, ys, cells, labels = [], [], [], []
    for f in range(1, pm.n_faces):
        poly = t.face_polygons[f]
        x0, y0, x1, y1 = poly.bounds
        c = np.array([(x0 + x1) / 2, (y0 + y1) / 2])
        paths = [ShapePath(np.asarray(r.coords)[:-1] - c, True) for r in [poly.exterior, *poly.interiors]]
        labs = t.face_labels[f]
        style = {"fill": _label_color(labs), "fill_opacity": 0.45, "stroke": "none"} if labs else {"fill": "none", "stroke": "none"}
        shapes[f"face-{f}"] = Shape(tuple(paths), style=style)
        xs.append(c[0])
        ys.append(c[1])
        cells.append("face")
        labels.append(" ".join(sorted(labs)))
    for e in range(pm.n_edges):
        pts = t.edge_points[e]
        c = (pts.min(axis=0) + pts.max(axis=0)) / 2
        labs = t.edge_labels[e]
        style = {"fill": "none", "stroke": _label_color(labs, _STROKE_PALETTE) if labs else "#1d1f24", "stroke_width": stroke_width}
        shapes[f"edge-{e}"] = Shape((ShapePath(pts - c, False),), style=style)
        xs.append(c[0])
        ys.append(c[1])
        cells.append("edge")
        labels.append(" ".join(sorted(labs)))
    kinds = list(shapes)
    return Arrangement(
        shapes,
        np.arange(len(kinds), dtype=np.int64),
        xs,
        ys,
        columns={"cell": cells, "labels": labels},
        region=region,
        meta={"method": "program"},
    )


def _square(size: Any) -> tuple[float, Region]:
    try:
        n = float(size)
    except (TypeError, ValueError):
        raise InputError(f"size must be a number, got {size!r}") from None
    if not (math.isfinite(n) and n > 0):
        raise InputError(f"size must be positive, got {size!r}")
    return n, Region.rectangle(n, n)


def evaluate(arrangement: Any, size: float = 2000, *, seed: int | None = None) -> tuple[PlanarMap, Arrangement]:
    """Evaluate an arrangement on the square [0, size]^2.

    Returns
    -------
    (PlanarMap, Arrangement)
        The induced planar map (already induced) and its strew Arrangement.
    """
    arr = as_arrangement(arrangement, "evaluate")
    n, region = _square(size)
    pm = arr(region, seed=seed)
    return pm, to_strew(pm, region)


def export_svg(a: Any, size: float, filename: str | os.PathLike[str] | None = None) -> Path | None:
    """ExportSVG(Arrangement A, Scalar size): exports ``A``, evaluated on [0, size]^2, in SVG.

    Writes ``filename`` (default: the running script's name with ``.svg``, in the
    current folder) and returns its path. Under ``strew run`` the outputs are the
    ``--out`` files, so this call writes nothing and returns None.
    """
    arr = as_arrangement(a, "export_svg")
    if _IN_RUN.get():
        return None
    from ..io import save

    if filename is None:
        stem = Path(sys.argv[0]).stem if sys.argv and sys.argv[0] not in ("", "-c") else "arrangement"
        filename = f"{stem}.svg"
    _, strew_arr = evaluate(arr, size, seed=top().root)
    return save(strew_arr, filename)


# -- running scripts ------------------------------------------------------------------------
def run_size(default: float) -> float:
    """The side of the square a script is evaluated on: ``--size`` under ``strew run``
    (and :func:`run_script`), else ``default`` (e.g. when run as ``python SCRIPT.py``).

    Not one of the paper's operators: a script whose lengths are multiples of
    ``run_size(2000) / 2000`` draws the same picture at every size, instead of a fixed
    number of units that a small square cannot hold.

    Examples
    --------
    >>> run_size(2000)
    2000.0
    """
    n = _RUN_SIZE.get()
    return float(default) if n is None else n


def _script_line(exc: BaseException, script: Path) -> int | None:
    line = None
    tb = exc.__traceback__
    target = str(script.resolve())
    while tb is not None:
        if os.path.abspath(tb.tb_frame.f_code.co_filename) == target:
            line = tb.tb_lineno
        tb = tb.tb_next
    return line


@contextmanager
def _script_environment(script: Path) -> Iterator[None]:
    folder = str(script.parent.resolve())
    old_argv = sys.argv
    sys.argv = [str(script)]
    sys.path.insert(0, folder)
    token = _IN_RUN.set(True)
    try:
        yield
    finally:
        _IN_RUN.reset(token)
        try:
            sys.path.remove(folder)
        except ValueError:
            pass
        sys.argv = old_argv


def run_script(script: str | os.PathLike[str], *, size: float = 2000, seed: int = 0, name: str = "arrangement") -> tuple[PlanarMap, Arrangement]:
    """Run a program script as ``python SCRIPT.py`` would, then evaluate its arrangement.

    ``__file__`` is set and the script's folder is on ``sys.path``; the module-level
    variable ``name`` (default ``arrangement``) is evaluated on [0, size]^2.

    Raises
    ------
    ScriptError
        The script is missing, does not compile, raises, has no ``arrangement``, or a
        mapper fails; the message names the script line.
    """
    path = Path(script)
    if not path.is_file():
        raise ScriptError(f"{str(script)!r}: no such script")
    n, region = _square(size)
    return _run_on(path, name, region, seed, n)


def _run_on(
    path: Path, name: str, region: Region, seed: int, n: float, tile: tuple[float, float, float, float] | None = None,
    convert: bool = True, seam: Curve | None = None,
) -> tuple[PlanarMap, Any]:
    """Run the script at ``path`` with ``run_size() == n`` and evaluate ``name`` on ``region``
    (on the torus ``tile`` when given: see :func:`_periodic_map`); without ``convert`` the
    planar map only (a world's tile clips it itself)."""
    size_token = _RUN_SIZE.set(n)
    try:
        with script_context(seed), _script_environment(path):
            return _run(path, name, region, seed, tile, convert, seam)
    finally:
        _RUN_SIZE.reset(size_token)


SPEC = MethodSpec(
    name="program",
    command="run",
    entry="strew.program:run",
    paper="Loi, Hurtut, Vergne, Thollot, A Programmable Model for Designing Stationary 2D Arrangements, 2015",
    summary="Run a program script (planar maps, partitions, mappers) and write its arrangement.",
    progress_message="program",
    region_required=False,
    input=Param("script", "any", help="A Python script defining a module-level arrangement (a Python program: trusted files only).",
                section="§3", parse="text", metavar="SCRIPT"),
    params=(
        Param("size", "float", None, low=0, high=MAX_COORD, low_open=True, unit="document units",
              help="Evaluate on the square [0, N] x [0, N] when no region is given [default: 2000].", cli=False, flag="--size",
              section="§4"),
        Param("name", "str", "arrangement", help="Module-level variable to evaluate.", section="§3"),
        Param("periodic", "bool", False, cli="flag",
              help="Make a repeat tile of the rectangular region: partitions repeat with it and faces cut by its edge continue on the opposite side (issue 18)."),
    ),
)


def run(
    script: str | os.PathLike[str],
    region: Region | Any = None,
    *,
    context: Arrangement | None = None,
    rng: int | np.random.Generator | None = None,
    progress: Any = None,
    should_cancel: Any = None,
    **params: Any,
) -> Arrangement:
    """Run a program script and evaluate its arrangement on a region (the method contract).

    Parameters
    ----------
    script : path
        Run as ``python SCRIPT.py`` would (``__file__`` set, its folder on
        ``sys.path``). A script is a Python program: run only scripts you trust.
    region : Region, shapely polygon, ``"WxH"`` or (W, H), optional
        Where to evaluate; default the square [0, size]^2. :func:`run_size` gives
        scripts the larger side of its bounding box.
    context : Arrangement, optional
        Fixed elements (issue 15): faces and edges that would overlap their footprint
        are left out of the result.
    rng : int, Generator or None
        The script's root seed: an int as given, a Generator draws one; recorded in meta.
    progress, should_cancel : callables, optional
        Reported (and checked) before the script runs, after it ran and after evaluation.
    size : float, optional
        Side of the square when no region is given (2000).
    name : str
        The module-level variable to evaluate (``arrangement``).

    Returns
    -------
    Arrangement
        Faces as closed paths, then edges as open paths (see :func:`to_strew`); the
        planar map itself is :func:`run_script`'s first result.
    """
    from .._method import as_region, check_context, context_footprint, empty_result, seed_record, stamp
    from .._progress import Reporter

    prm = SPEC.validate(params)
    gen, seed = seed_record(rng)
    root = int(rng) if isinstance(rng, (int, np.integer)) and not isinstance(rng, bool) else (
        int(seed["seed"]) if "seed" in seed else int(gen.integers(2**31)))
    dom = as_region(region)
    if dom is not None and prm["size"] is not None:
        raise InputError("size: give a region or a size, not both")
    if dom is None:
        n, dom = _square(2000 if prm["size"] is None else prm["size"])
    else:
        x0, y0, x1, y1 = dom.bounds
        n = float(max(x1 - x0, y1 - y0, 0.0))
    ctx = check_context(context)
    path = Path(script)
    if not path.is_file():
        raise ScriptError(f"{str(script)!r}: no such script")
    rep = Reporter(progress, should_cancel, total=2, message=f"program {path.name}")
    rep.tick(0, force=True)
    tile = None
    if prm["periodic"]:
        from .._periodic import frame_of_region

        tile = frame_of_region(dom)
    if not (dom.area > 0):
        arr = empty_result({}, dom, "the region is empty")
    else:
        pm, arr = _run_on(path, prm["name"], dom, root, n, tile)
        arr = arr.with_meta(program={"vertices": pm.n_vertices, "edges": pm.n_edges, "faces": pm.n_faces})
        rep.tick(1, force=True)
        if ctx is not None and len(ctx) and len(arr):
            arr = _drop_overlapping(arr, context_footprint(ctx))
    rep.tick(2, force=True)
    rep.done(2)
    record = {**prm, "size": prm["size"] if prm["size"] is not None or region is not None else 2000.0}
    if "seed" in seed and root != seed["seed"]:
        seed = {**seed, "seed": root}
    return stamp(arr, SPEC, path, record, seed, region=dom, context=ctx)


def _drop_overlapping(arr: Arrangement, footprint: Any) -> Arrangement:
    """``arr`` without the cells that overlap ``footprint`` (areas, or lines inside it)."""
    import shapely

    geoms = arr.geometry_of("geometry")
    inter = shapely.intersection(geoms, footprint)
    clash = (shapely.area(inter) > 1e-12) | (shapely.length(inter) > 1e-9) & ~shapely.is_empty(inter)
    # a line along the footprint's edge touches it without overlapping it
    lines = ~np.asarray([g.area > 0 for g in geoms], bool)
    if lines.any():
        inner = shapely.buffer(footprint, -1e-9)
        clash[lines] = shapely.intersects(geoms[lines], inner)
    return arr.select(~clash).with_meta(program_context={"left_out": int(clash.sum())})


#: Label of the tile's outline on a periodic evaluation: it closes the faces cut by the
#: tile's edge but is a seam, not a line of the arrangement, so it is not drawn.
_SEAM = "__strew_tile_seam__"


def _periodic_map(value: Any, name: str, tile: tuple[float, float, float, float], seed: int) -> tuple[PlanarMap, Any]:
    """Evaluate ``value`` as a repeat tile (issue 18; not in the paper, which works in the plane).

    The arrangement is evaluated on the tile grown by half its larger side, with its
    partitions made periodic (stripes snapped to the tile's periods, irregular sets drawn
    on the torus) and every per-cell random value a function of the cell's position on
    the torus, so that mappers see whole faces and a cell's translates get the same
    result. The curves are then cut at the tile, whose outline (labelled ``_SEAM``) closes
    the faces that cross its edge: their pieces continue on the opposite side.

    Returns
    -------
    (PlanarMap, shapely geometry)
        The planar map of the tile, and the lines of the arrangement in it (the seam
        is drawn where they run along it).
    """
    import shapely

    from ._context import Periodic, periodic_evaluation
    from ._operators import _crop

    x0, y0, w, h = tile
    box = shapely.box(x0, y0, x0 + w, y0 + h)
    margin = 0.5 * max(w, h)
    domain = shapely.box(x0 - margin, y0 - margin, x0 + w + margin, y0 + h + margin)
    with periodic_evaluation(Periodic(tuple(tile), domain)):
        curves = as_arrangement(value, name).curves(domain, seed=seed)
    cut = _crop(curves, box, True)
    outline = Curve(np.array([[x0, y0], [x0 + w, y0], [x0 + w, y0 + h], [x0, y0 + h]]), True, frozenset([_SEAM]))
    lines = [shapely.LineString(c.polyline) for c in cut.curves if len(c.polyline) >= 2]
    drawn = shapely.union_all(lines) if lines else shapely.LineString()
    return PlanarMap(Curves(cut.curves + (outline,), cut.points, cut.marks)), drawn


def _drop_seam(arr: Arrangement, drawn: Any, tol: float) -> Arrangement:
    """``arr`` without the tile's outline: edges that carry only the seam label go, unless
    a line of the arrangement runs along them (``drawn``, within ``tol``); the seam label
    leaves the others."""
    import shapely

    labels = np.asarray(arr["labels"], dtype=object)
    cells = np.asarray(arr["cell"], dtype=object)
    seam_only = (cells == "edge") & (labels == _SEAM)
    idx = np.flatnonzero(seam_only)
    if len(idx) and not drawn.is_empty:
        along = shapely.covered_by(arr.geometry[idx], shapely.buffer(drawn, tol))
        seam_only[idx[along]] = False
    cleaned = [" ".join(x for x in str(lab).split(" ") if x != _SEAM) for lab in labels.tolist()]
    out = arr.with_columns(labels=np.asarray(cleaned, dtype=object))
    return out.select(np.flatnonzero(~seam_only))


def _run(path: Path, name: str, region: Region, seed: int, tile: tuple[float, float, float, float] | None = None,
         convert: bool = True, seam: Curve | None = None) -> tuple[PlanarMap, Any]:
    """Body of :func:`run_script`, inside the script's context and environment."""
    try:
        glb = runpy.run_path(str(path), run_name="__main__")
    except SyntaxError as exc:
        raise ScriptError(f"{path.name} line {exc.lineno}: SyntaxError: {exc.msg}") from None
    except MapperError:
        raise
    except SystemExit as exc:
        if exc.code not in (None, 0):
            raise ScriptError(f"{path.name}: the script exited with status {exc.code}") from None
        raise ScriptError(f"{path.name}: the script exited before defining {name!r}") from None
    except Exception as exc:
        line = _script_line(exc, path)
        where = f"{path.name} line {line}" if line else path.name
        msg = str(exc).replace("\n", " ")
        raise ScriptError(f"{where}: {type(exc).__name__}: {msg}") from exc
    if name not in glb:
        raise ScriptError(f"{path.name}: no module-level {name!r}; assign the final arrangement to it, e.g. `{name} = map_to_faces(mapper, partition)`")
    value = glb[name]
    if not isinstance(value, (ArrangementFunction, Curves)):
        raise ScriptError(f"{path.name}: {name!r} is {type(value).__name__}, expected an arrangement (the result of a partition, mapping or merging operator)")
    try:
        if tile is None and seam is not None:
            # a world's tile (strew.program._world): the curves closed by the region's outline
            cs = as_arrangement(value, name).curves(region, seed=seed)
            pm = PlanarMap(Curves(cs.curves + (seam,), cs.points, cs.marks))
        elif tile is None:
            pm = as_arrangement(value, name)(region, seed=seed)
        else:
            pm, drawn = _periodic_map(value, name, tile, seed)
        _ = pm.n_faces  # induce inside the error handling
    except MapperError:
        raise
    except InputError as exc:
        line = _script_line(exc, path)
        where = f"{path.name} line {line}" if line else path.name
        raise ScriptError(f"{where}: {exc}") from exc
    if tile is None:
        return pm, to_strew(pm, region) if convert else None
    from .._periodic import mark

    arr = _drop_seam(to_strew(pm, region), drawn, 1e-7 * max(tile[2], tile[3]))
    if len(arr) < 2:
        raise InputError(f"periodic: the tile ({tile[2]:g} x {tile[3]:g}) holds fewer than two cells; use a larger tile")
    return pm, mark(arr, tile)

