"""strew studio: a local web editor for painting with example palettes.

A FastAPI server on uvicorn serves a static front end (plain JavaScript modules, no
build step) and talks to it over one websocket. The browser draws; the library does the
work: the generative brush, filler and eraser of Davison et al. (§5.4-5.5, through
:mod:`strew.synth`) and the spray, flow-field and boundary tools of Ijiri et al. (§3,
through :mod:`strew.grow` and :mod:`strew.fields`).

Install with ``pip install '.[studio]'`` from a clone and run ``strew studio [PROJECT_DIR]``.

Safety: the server binds 127.0.0.1 by default, reads and writes only inside
``PROJECT_DIR`` (:func:`strew.studio._paths.resolve_in_project`), limits message sizes,
answers malformed messages with an error and keeps serving, and never executes anything
sent by the browser: messages are JSON data checked field by field.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from .._errors import InputError

__all__ = ["create_app", "serve", "Session", "require_studio"]


def require_studio() -> None:
    """Raise :class:`strew.InputError` naming the extra when FastAPI or uvicorn is missing."""
    try:
        import fastapi  # noqa: F401
        import uvicorn  # noqa: F401
    except ImportError as exc:
        raise InputError(f"studio: needs the 'studio' extra ({exc.name} is missing); from a clone of strew: pip install '.[studio]'") from None


def create_app(project_dir: str | Path, **kwargs: Any) -> Any:
    """The FastAPI application; see :func:`strew.studio._app.create_app`."""
    require_studio()
    from ._app import create_app as _create

    return _create(project_dir, **kwargs)


def __getattr__(name: str) -> Any:
    if name == "Session":
        from ._session import Session

        return Session
    raise AttributeError(f"module 'strew.studio' has no attribute {name!r}")


def serve(
    project_dir: str | Path,
    *,
    host: str = "127.0.0.1",
    port: int = 8765,
    open_browser: bool = True,
    seed: int = 0,
    on_ready: Any = None,
    page: str = "",
) -> None:
    """Run the studio until interrupted.

    Parameters
    ----------
    project_dir : path
        Folder of the project: exemplars to load, ``palette.json``, ``scene.json`` and
        exports live here.
    host : str
        Interface to bind; 127.0.0.1 (this machine only) by default.
    port : int
        TCP port; 0 picks a free one.
    open_browser : bool
        Open the studio in the default browser once the server listens.
    seed : int
        Seed of the session's random generator.
    on_ready : callable, optional
        Called with the URL once the server listens.
    page : str
        Path and query appended to the URL that is shown and opened, e.g. the 3D view's
        ``static/view3d.html?mesh=...``.
    """
    require_studio()
    import threading
    import webbrowser

    import uvicorn

    from ._app import LOCAL_HOSTS, create_app as _create
    from ._protocol import MAX_MESSAGE_BYTES

    allowed = LOCAL_HOSTS if host in LOCAL_HOSTS else (*LOCAL_HOSTS, host)
    app = _create(project_dir, seed=seed, allowed_hosts=allowed)
    # A bounded graceful shutdown: Ctrl-C or SIGTERM stops the server within seconds even
    # while a message is being handled (its worker is a daemon thread, see _app).
    config = uvicorn.Config(app, host=host, port=port, log_level="warning", ws_max_size=MAX_MESSAGE_BYTES * 4, lifespan="off",
                            timeout_graceful_shutdown=2)
    server = uvicorn.Server(config)

    def announce() -> None:
        while not server.started:
            if server.should_exit:
                return
            threading.Event().wait(0.05)
        bound = server.servers[0].sockets[0].getsockname()[1] if server.servers else port
        shown = f"[{host}]" if ":" in host else host
        url = f"http://{shown}:{bound}/{page}"
        print(f"strew studio on {url} (project {Path(project_dir).resolve()}); Ctrl-C stops it", flush=True)
        if on_ready is not None:
            on_ready(url)
        if open_browser:
            webbrowser.open(url)

    threading.Thread(target=announce, daemon=True).start()
    server.run()
