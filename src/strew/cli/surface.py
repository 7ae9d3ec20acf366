"""``strew surface``: pack shapes on a 3D surface mesh (issue 20; :func:`strew.surface.pack`).

Outputs by extension: ``.glb`` (the surface and one node per element, sharing one mesh
per kind), ``.json`` (a version 2 strew document with the 3D columns), ``.png`` (a
preview rendered without a GPU) and ``.svg`` (the top view). Needs
``pip install 'strew[surface]'``.
"""

from __future__ import annotations

from pathlib import Path

import click

from .._errors import InputError
from ._common import command_line, echo, out_option, parse_range, progress_bar, quiet_option

_OUTS = (".glb", ".json", ".png", ".svg")


def _check_outs(outs: tuple[str, ...]) -> None:
    from ..io._atomic import probe_writable

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
@click.option("--seed", type=int, default=0, show_default=True, help="Random seed.")
@out_option()
@quiet_option
def command(shapes: tuple[str, ...], mesh: str, radius: float | None, scale: str | None, margin: float,
            field_file: str | None, rotation: str, style: str, elements: tuple[str, ...], seed: int,
            outs: tuple[str, ...], quiet: bool) -> None:
    """Pack SHAPE... (SVG or JSON files), or discs of --radius, on the --surface mesh.

    Bounding spheres never overlap (Davison et al. §5.7); free-space points and fill-gap
    rounds on the surface (Sakurai & Miyata §4).
    """
    import time

    from .. import surface
    from ..io._atomic import atomic_write_many

    from ..surface._deps import require

    for dep in ("trimesh", "potpourri3d"):
        try:
            require(dep)
        except ImportError as exc:  # a missing extra is a usage problem: exit 2, one line
            raise InputError(str(exc)) from None
    _check_outs(outs)
    if (radius is None) == (not shapes):
        raise InputError("give SHAPE files or --radius R (one of them)")
    element_meshes: dict[str, str] = {}
    for text in elements:
        kind, sep, path = text.partition("=")
        if not sep or not kind or not path:
            raise InputError(f"--element: expected KIND=MESH, got {text!r}")
        element_meshes[kind] = path
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
    field = surface.load_field(field_file, m) if field_file else "smoothest"
    t0 = time.perf_counter()
    with progress_bar("surface", quiet=quiet) as (prog, cancel):
        arr = surface.pack(source, m, field=field, rotation=rotation, scale=parse_range(scale, "--scale", default=(1.0, 1.0)),
                           margin=margin, rng=seed, progress=prog, should_cancel=cancel)
    seconds = time.perf_counter() - t0
    if len(arr) == 0:
        raise InputError("surface: no element fits (are the shapes larger than the mesh?); nothing written")
    arr = arr.with_meta(command=command_line(), surface_file=Path(mesh).name)
    data = []
    for o in outs:
        suffix = Path(o).suffix.lower()
        if suffix == ".glb":
            data.append((o, surface.to_glb(arr, mesh=m, element_meshes=element_meshes, style=style)))
        elif suffix == ".png":
            data.append((o, surface.render_preview(arr, m)))
        else:
            from ..io import encode

            data.append((o, encode(arr, o)))
    atomic_write_many(data)
    if not quiet:
        for o in outs:
            click.echo(f"wrote {o}", err=True)
    counts = ", ".join(f"{k} {c}" for k, c in arr.counts().items())
    echo(f"packed {len(arr)} elements ({counts}) on {len(m.faces)} faces, {seconds:.2f} s", quiet=quiet)
