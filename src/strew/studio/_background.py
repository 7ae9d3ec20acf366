"""A studio server in a background thread, for tests, benchmarks and notebooks."""

from __future__ import annotations

import threading
import time
from pathlib import Path
from typing import Any

__all__ = ["BackgroundStudio", "CHROMIUM", "CHROMIUM_ARGS"]

#: Debian's chromium, which the browser tests and the benchmark drive through Playwright.
CHROMIUM = "/usr/bin/chromium"
CHROMIUM_ARGS = [
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
]


class BackgroundStudio:
    """Run the studio on 127.0.0.1 and a free port until :meth:`stop` (or the ``with`` block ends).

    Parameters
    ----------
    project_dir : path
    seed : int
    warm : bool
        Load the compiled kernels before serving (see :func:`strew.studio._app.warm_up`).
    preload : bool
        Load the example palette at the first page (see :func:`strew.studio._app.create_app`).

    Examples
    --------
    >>> with BackgroundStudio(".") as studio:  # doctest: +SKIP
    ...     print(studio.url)
    """

    def __init__(self, project_dir: str | Path, *, seed: int = 0, warm: bool = True, preload: bool = True) -> None:
        import uvicorn

        from ._app import create_app, warm_up

        if warm:
            warm_up()
        self.app = create_app(project_dir, seed=seed, warm=False, preload=preload)
        from ._protocol import MAX_MESSAGE_BYTES

        config = uvicorn.Config(self.app, host="127.0.0.1", port=0, log_level="warning", lifespan="off", ws_max_size=MAX_MESSAGE_BYTES * 4)
        self.server = uvicorn.Server(config)
        self.thread = threading.Thread(target=self.server.run, name="strew-studio", daemon=True)
        self.thread.start()
        t0 = time.perf_counter()
        while not self.server.started:
            if not self.thread.is_alive() or time.perf_counter() - t0 > 30:
                raise RuntimeError("studio server did not start")
            time.sleep(0.02)
        port = self.server.servers[0].sockets[0].getsockname()[1]
        self.url = f"http://127.0.0.1:{port}/"

    def stop(self) -> None:
        self.server.should_exit = True
        self.thread.join(10)

    def __enter__(self) -> BackgroundStudio:
        return self

    def __exit__(self, *exc: Any) -> None:
        self.stop()
