"""``strew surface``: pack shapes on a 3D surface mesh (issue 20; :func:`strew.surface.pack`).

Outputs by extension: ``.glb`` (the surface and one node per element, sharing one mesh
per kind), ``.json`` (a version 2 strew document with the 3D columns), ``.png`` (a
preview rendered without a GPU) and ``.svg`` (the top view). Needs
``pip install 'strew[surface]'``.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import click

from .._errors import InputError
from ._common import command_line, echo, flag_for, out_option, parse_range, progress_bar, quiet_option

_OUTS = (".glb", ".json", ".png", ".svg")


def _check_outs(outs: tuple[str, ...]) -> None:
    from ..io._atomic import probe_writable
    from ._common import _out_height_profiles

    if _out_height_profiles():
        raise InputError("--height-profile: a surface scene has no height map (.height.png is written for flat outputs)")

    for o in outs:
        suffix = Path(o).suffix.lower()
        if suffix not in _OUTS or o.lower().endswith(".height.png"):
            raise InputError(f"--out {o!r}: a surface scene is written as {', '.join(_OUTS)}")
        if not Path(o).parent.exists():
            raise InputError(f"--out {o!r}: folder {str(Path(o).parent)!r} does not exist")
        probe_writable(o)


@click.command("surface")
@click.argument("shapes", nargs=-1, metavar="[SHAPE...]", type=click.Path(dir_okay=False))
@click.option("--surface", "mesh", required=True, type=click.Path(dir_okay=False),
              help="The surface: a triangle mesh (.obj, .ply, .stl, .off, .glb, .gltf).")
@click.option("--radius", type=float, default=None, help="Pack discs of this radius (instead of SHAPE files).")
@click.option("--scale", default=None, metavar="A:B", help="Scale of the shapes, or a range drawn per element [default: 1].")
@click.option("--margin", type=float, default=0.0, show_default=True, help="Added to every bounding-sphere radius.")
@click.option("--field", "field_file", type=click.Path(dir_okay=False), default=None,
              help="Orientation field: per-vertex directions (.npy) or a design (.json: strokes, sources, sinks) "
                   "[default: the smoothest field, Davison §5.7].")
@click.option("--rotation", type=click.Choice(["field", "random"]), default="field", show_default=True,
              help="Tangents along the field, or turned by a random angle.")
@click.option("--style", type=click.Choice(["extrude", "decal"]), default="extrude", show_default=True,
              help="How 2D shapes are drawn in the .glb.")
@click.option("--element", "elements", multiple=True, metavar="KIND=MESH", help="A 3D mesh for a kind in the .glb (repeatable).")
@click.option("--instancing", is_flag=True, help="One .glb node per kind with EXT_mesh_gpu_instancing (not one node per element).")
@click.option("--seed", type=int, default=0, show_default=True, help="Random seed.")
@out_option()
@quiet_option
def command(shapes: tuple[str, ...], mesh: str, radius: float | None, scale: str | None, margin: float,
            field_file: str | None, rotation: str, style: str, elements: tuple[str, ...], instancing: bool, seed: int,
            outs: tuple[str, ...], quiet: bool) -> None:
    """Pack SHAPE... (SVG or JSON files), or discs of --radius, on the --surface mesh.

    Bounding spheres never overlap (Davison et al. §5.7); free-space points and fill-gap
    rounds on the surface (Sakurai & Miyata §4).
    """
    import time

    from .. import surface

    _require()
    _check_outs(outs)
    if (radius is None) == (not shapes):
        raise InputError("give SHAPE files or --radius R (one of them)")
    element_meshes = _element_meshes(elements)
    if shapes:
        from ..io import load_shapes

        lib: dict = {}
        for path in shapes:
            for name, sh in load_shapes(path).items():
                lib[name if name not in lib else f"{Path(path).stem}-{name}"] = sh
        source: object = lib
    else:
        source = radius
    m = surface.load_mesh(mesh, name="--surface")
    with flag_for("field", "--field"):
        field = surface.load_field(field_file, m) if field_file else "smoothest"
    t0 = time.perf_counter()
    with progress_bar("surface", quiet=quiet) as (prog, cancel):
        arr = surface.pack(source, m, field=field, rotation=rotation, scale=parse_range(scale, "--scale", default=(1.0, 1.0)),
                           margin=margin, rng=seed, progress=prog, should_cancel=cancel)
    seconds = time.perf_counter() - t0
    if len(arr) == 0:
        raise InputError("surface: no element fits (are the shapes larger than the mesh?); nothing written")
    write_scene(arr, m, outs, mesh_file=mesh, element_meshes=element_meshes, style=style, quiet=quiet, instancing=instancing)
    counts = ", ".join(f"{k} {c}" for k, c in arr.counts().items())
    echo(f"packed {len(arr)} elements ({counts}) on {len(m.faces)} faces, {seconds:.2f} s", quiet=quiet)


def _require() -> None:
    from ..surface._deps import require

    for dep in ("trimesh", "potpourri3d"):
        try:
            require(dep)
        except ImportError as exc:  # a missing extra is a usage problem: exit 2, one line
            raise InputError(str(exc)) from None


def _element_meshes(elements: tuple[str, ...]) -> dict[str, str]:
    out: dict[str, str] = {}
    for text in elements:
        kind, sep, path = text.partition("=")
        if not sep or not kind or not path:
            raise InputError(f"--element: expected KIND=MESH, got {text!r}")
        out[kind] = path
    return out


def write_scene(arr, m, outs: tuple[str, ...], *, mesh_file: str, element_meshes: dict, style: str, quiet: bool,
                instancing: bool = False) -> None:
    """Write a surface arrangement to every ``--out`` (.glb, .json, .png, .svg), all or none."""
    from .. import surface
    from ..io._atomic import atomic_write_many

    arr = arr.with_meta(command=command_line(), surface_file=Path(mesh_file).name)
    data = []
    for o in outs:
        suffix = Path(o).suffix.lower()
        if suffix == ".glb":
            data.append((o, surface.to_glb(arr, mesh=m, element_meshes=element_meshes, style=style, instancing=instancing)))
        elif suffix == ".png":
            data.append((o, surface.render_preview(arr, m)))
        else:
            from ..io import encode

            data.append((o, encode(arr, o)))
    atomic_write_many(data)
    if not quiet:
        for o in outs:
            click.echo(f"wrote {o}", err=True)


# -- ``strew pack|synth|grow --surface MESH`` (the options and the run; cli/_spec.py calls these)
def surface_options() -> list:
    """The options a method command gains for surfaces (issue 20)."""
    return [
        click.option("--surface", "surface_mesh", type=click.Path(dir_okay=False), default=None,
                     help="Run on this triangle mesh (.obj, .ply, .stl, .off, .glb, .gltf); outputs .glb, .json, .png, .svg."),
        click.option("--field", "surface_field", type=click.Path(dir_okay=False), default=None,
                     help="With --surface: orientation field, per-vertex directions (.npy) or a design (.json) "
                          "[default: the smoothest field, Davison §5.7]."),
        click.option("--mesh-scale", "surface_unit", type=float, default=None,
                     help="With --surface: mesh units per document unit [default: pack 1; synth and grow about 2,000 elements]."),
        click.option("--element", "surface_elements", multiple=True, metavar="KIND=MESH",
                     help="A 3D mesh for a kind in the .glb (repeatable; with --surface, or a flat run's .glb output)."),
        click.option("--style", "surface_style", type=click.Choice(["extrude", "decal"]), default="extrude", show_default=True,
                     help="How 2D shapes are drawn in the .glb (with --surface, or a flat run's .glb output)."),
        click.option("--instancing", "surface_instancing", is_flag=True,
                     help="One .glb node per kind with EXT_mesh_gpu_instancing (with --surface, or a flat run's .glb output)."),
    ]


_SURFACE_KEYS = ("surface_mesh", "surface_field", "surface_unit", "surface_elements", "surface_style", "surface_instancing")


def pop_surface_options(options: dict) -> dict:
    """Remove the surface options from a command's options; returns them."""
    return {k: options.pop(k) for k in _SURFACE_KEYS if k in options}


def remember_flat_glb(surf: dict, outs: tuple[str, ...]) -> None:
    """A flat run's ``--element KIND=MESH``, ``--style`` and ``--instancing``: they shape
    its ``.glb`` outputs (the elements on the plane z = 0, Sakurai & Miyata Fig. 15);
    without a ``.glb`` output they are refused, as they would do nothing."""
    from ._common import remember_glb_options

    elements = surf.get("surface_elements") or ()
    glb = any(str(o).lower().endswith(".glb") for o in outs)
    if not glb:
        for key, flag in (("surface_elements", "--element"), ("surface_instancing", "--instancing")):
            if surf.get(key):
                raise InputError(f"{flag}: only for --surface runs or .glb outputs")
        return
    remember_glb_options(_element_meshes(elements), surf.get("surface_style") or "extrude", bool(surf.get("surface_instancing")))


def run_on_surface(spec, options: dict, raw_input, outs: tuple[str, ...], surf: dict, *, seed: int, quiet: bool,
                   region: tuple, around, convert: Callable[[Any, Any], Any], read_input: Callable[[Any], Any]) -> None:
    """``strew METHOD ... --surface MESH``: convert the options as the generated command
    does (``convert(param, raw)`` and ``read_input(raw_input)`` are the command's own, handed
    down by cli/_spec.py so that this module does not import it back), run
    :func:`strew.surface.on_surface`, write the scene."""
    import time

    from .. import surface
    from .._method import names_to_flags
    from ..surface._methods import on_surface

    _require()
    _check_outs(outs)
    if any(v is not None for v in region) or around is not None:
        raise InputError("--surface: the surface is the domain; leave out --region, --size and --around")
    values = {}
    for p in spec.params:
        if p.cli:
            v = convert(p, options.get(p.name))
            if v is not None:
                values[p.name] = v
    element_meshes = _element_meshes(surf.get("surface_elements") or ())
    data = read_input(raw_input)
    m = surface.load_mesh(surf["surface_mesh"], name="--surface")
    with flag_for("field", "--field"):
        field = surface.load_field(surf["surface_field"], m) if surf.get("surface_field") else "smoothest"
    t0 = time.perf_counter()
    try:
        with progress_bar(spec.progress_message or spec.name, quiet=quiet) as (prog, cancel):
            arr = on_surface(spec.name, data, m, field=field, unit=surf.get("surface_unit"), rng=seed, progress=prog,
                             should_cancel=cancel, **values)
    except InputError as exc:  # the library names Python parameters; answer with flags
        msg = names_to_flags(spec, str(exc))
        if msg == str(exc):
            raise
        raise InputError(msg) from exc
    seconds = time.perf_counter() - t0
    if len(arr) == 0:
        raise InputError(f"{spec.name}: no element fits on the surface (are the elements larger than the mesh?); nothing written")
    write_scene(arr, m, outs, mesh_file=surf["surface_mesh"], element_meshes=element_meshes,
                style=surf.get("surface_style") or "extrude", quiet=quiet, instancing=bool(surf.get("surface_instancing")))
    counts = ", ".join(f"{k} {c}" for k, c in arr.counts().items())
    echo(f"{spec.name}: {len(arr)} elements ({counts}) on {len(m.faces)} faces, {seconds:.2f} s", quiet=quiet)
