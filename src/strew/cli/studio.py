"""``strew studio``: the interactive editor in the browser."""

from __future__ import annotations

import click


@click.command("studio")
@click.argument("project_dir", required=False, default=".", type=click.Path(file_okay=False))
@click.option("--host", default="127.0.0.1", show_default=True, help="Interface to bind (127.0.0.1: this machine only).")
@click.option("--port", default=8765, show_default=True, type=click.IntRange(0, 65535), help="TCP port (0: any free port).")
@click.option("--no-browser", is_flag=True, help="Do not open the browser.")
@click.option("--seed", type=int, default=0, show_default=True, help="Random seed of the session.")
@click.option("--surface", "surface", metavar="MESH", default=None,
              help="Open the 3D view on MESH (a mesh file in PROJECT_DIR, or examples/meshes/NAME): orbit, pan, zoom; shift-drag paints.")
def command(project_dir: str, host: str, port: int, no_browser: bool, seed: int, surface: str | None) -> None:
    """Paint with example palettes in the browser (generative brush, spray, filler, eraser).

    PROJECT_DIR (default: the current folder) holds the exemplars to load, the saved
    palette.json and scene.json, and exports; the studio reads and writes nowhere else.
    """
    from pathlib import Path

    from .._errors import InputError
    from ..studio import require_studio, serve

    root = Path(project_dir)
    if not root.is_dir():
        raise InputError(f"PROJECT_DIR {project_dir!r}: no such folder")
    page = ""
    if surface is not None:
        from urllib.parse import quote

        from ..studio._paths import resolve_in_project
        from ..studio._surface3d import MESH_SUFFIXES

        rel = surface  # checked now: a path relative to PROJECT_DIR, inside it, or an example mesh
        if not surface.startswith("examples/meshes/"):
            try:
                rel = resolve_in_project(root.resolve(), surface, suffixes=MESH_SUFFIXES, must_exist=True).relative_to(root.resolve()).as_posix()
            except InputError as exc:
                raise InputError(f"--surface: {exc}") from None
        page = "static/view3d.html?mesh=" + quote(rel)
    require_studio()
    if port:
        import socket

        family = socket.AF_INET6 if ":" in host else socket.AF_INET
        try:
            with socket.socket(family, socket.SOCK_STREAM) as sock:
                sock.bind((host, port))
        except OSError as exc:
            raise InputError(f"--port {port}: cannot listen on {host}:{port} ({exc.strerror or exc})") from None
    try:
        serve(root, host=host, port=port, open_browser=not no_browser, seed=seed, page=page)
    except OSError as exc:
        raise InputError(f"--port {port}: cannot listen on {host}:{port} ({exc.strerror or exc})") from None
