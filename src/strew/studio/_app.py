"""The studio's web server: FastAPI on uvicorn, a static front end and one websocket.

``GET /`` serves the page, ``/static/...`` its JavaScript modules and stylesheet, and
``/ws`` carries the protocol of :mod:`strew.studio._protocol`. The server holds one
:class:`~strew.studio._session.Session`: reloading the page finds the work as it was, and
the newest window takes over from an older one. Messages are handled one at a time by a
worker thread, so that the receiving side stays responsive: consecutive
stroke segments waiting in the queue are merged into one (the generative brush then
works on a longer segment instead of falling behind), and ``stop`` takes effect at
once.
"""

from __future__ import annotations

import asyncio
import json
import threading
from pathlib import Path
from typing import Any
from urllib.parse import urlsplit

from fastapi import FastAPI, WebSocket, WebSocketDisconnect
from fastapi.responses import FileResponse, JSONResponse, Response
from fastapi.staticfiles import StaticFiles

from .._errors import Cancelled, InputError
from ._protocol import MAX_MESSAGE_BYTES, MAX_POINTS, parse_message
from ._session import Session

__all__ = ["create_app", "STATIC_DIR", "LOCAL_HOSTS"]

STATIC_DIR = Path(__file__).resolve().parent / "static"
_TAKEOVER = "\x00takeover"  # outbox marker: a newer window took over this session
LOCAL_HOSTS = ("127.0.0.1", "localhost", "::1", "[::1]")


def _dumps(msg: dict[str, Any]) -> str:
    return json.dumps(msg, separators=(",", ":"), allow_nan=False, default=_plain)


def _plain(obj: Any) -> Any:
    import numpy as np

    if isinstance(obj, np.generic):
        return obj.item()
    if isinstance(obj, np.ndarray):
        return obj.tolist()
    raise TypeError(f"{type(obj).__name__} is not JSON serialisable")


def _origin_ok(origin: str | None, allowed_hosts: tuple[str, ...], host_header: str | None = None) -> bool:
    """A websocket from a page of another site is refused (cross-site websocket hijacking).

    The page's origin must name one of ``allowed_hosts`` *and* the studio's own port (the
    port of the ``Host`` header the websocket was opened with): another local server's
    page, e.g. ``http://localhost:3000``, is refused. When the server was bound to every
    interface (``0.0.0.0`` or ``::`` among them), a same-origin page (``Origin`` matching
    the ``Host`` header) is accepted too.
    """
    if origin is None:
        return True
    parts = urlsplit(origin)
    try:
        host, port = parts.hostname, parts.port
    except ValueError:  # a port that is not a number
        return False
    if host is None or parts.scheme not in ("http", "https"):
        return False
    if host in allowed_hosts or f"[{host}]" in allowed_hosts:
        if host_header is None:
            return True
        own = urlsplit(f"//{host_header}")
        try:
            own_port = own.port
        except ValueError:
            return False
        default = 443 if parts.scheme == "https" else 80
        return (port or default) == (own_port or default)
    wildcard = any(h in ("0.0.0.0", "::", "[::]") for h in allowed_hosts)
    return wildcard and host_header is not None and parts.netloc == host_header


async def _in_daemon_thread(fn: Any, *args: Any) -> Any:
    """Run ``fn(*args)`` in a daemon thread and await its result.

    Unlike ``asyncio.to_thread`` (the loop's default executor, joined at shutdown), a
    daemon thread never keeps the process alive: Ctrl-C or SIGTERM stops the server even
    while a heavy message is being handled.
    """
    loop = asyncio.get_running_loop()
    fut = loop.create_future()

    def settle(ok: bool, value: Any) -> None:
        if fut.done():
            return
        if ok:
            fut.set_result(value)
        else:
            fut.set_exception(value)

    def run() -> None:
        try:
            result = fn(*args)
        except BaseException as exc:  # handed to the awaiting task
            try:
                loop.call_soon_threadsafe(settle, False, exc)
            except RuntimeError:  # the loop has closed: the server is stopping
                pass
            return
        try:
            loop.call_soon_threadsafe(settle, True, result)
        except RuntimeError:
            pass

    threading.Thread(target=run, name="strew-studio-worker", daemon=True).start()
    return await fut


def warm_up() -> None:
    """Load the compiled kernels of synthesis and growth once (numba caches), so that
    the first stroke of a session does not pay for it."""
    import numpy as np

    from .. import synth
    from ..arrangement import Arrangement
    from ..grow import grow
    from ..shape import Shape

    g = np.mgrid[0:5, 0:5].reshape(2, -1).T * 10.0
    g[:, 0] += 5.0 * (np.arange(len(g)) % 2)
    ex = Arrangement({"dot": Shape.circle(3.0, segments=8)}, [0] * len(g), g[:, 0], g[:, 1])
    try:
        st = synth.new_state(ex, None, rng=0)
        synth.brush(st, np.array([[0.0, 0.0], [30.0, 0.0]]), 15.0)
        synth.erase(st, np.array([[0.0, 0.0]]), 5.0)
        synth.average_neighborhood_distance(st, sample=20)
        grow(ex, count=12, rng=0)
    except Exception:  # a warm-up failure must not take the server down
        pass


def create_app(project_dir: str | Path, *, seed: int = 0, allowed_hosts: tuple[str, ...] = LOCAL_HOSTS, warm: bool = True, preload: bool = True) -> Any:
    """The FastAPI application of a studio on ``project_dir``.

    Parameters
    ----------
    project_dir : path
        The only folder the studio reads and writes.
    seed : int
        Seed of each session's random generator.
    allowed_hosts : tuple of str
        Host names a page may be served under; a websocket whose ``Origin`` names another
        host is refused.
    warm : bool
        Load the compiled kernels in a background thread at once (:func:`warm_up`).
    preload : bool
        On a project's first start (no ``palette.json``), the first page loads the
        example palette (:data:`~strew.studio._session.PRELOAD_EXAMPLE`), so that the
        first stroke paints with no extra click.
    """
    root = Path(project_dir).resolve()
    if not root.is_dir():
        raise InputError(f"PROJECT_DIR {str(project_dir)!r}: no such folder")
    app = FastAPI(title="strew studio", docs_url=None, redoc_url=None, openapi_url=None)
    app.mount("/static", StaticFiles(directory=STATIC_DIR), name="static")
    app.state.sessions = 0
    if warm:
        threading.Thread(target=warm_up, name="strew-studio-warm-up", daemon=True).start()

    @app.get("/")
    def index() -> FileResponse:
        return FileResponse(STATIC_DIR / "index.html", media_type="text/html")

    @app.get("/favicon.ico")
    def favicon() -> Response:
        return Response(status_code=204)

    @app.get("/health")
    def health() -> JSONResponse:
        return JSONResponse({"ok": True, "project": root.name})

    # One session per server: reloading the page (or opening it again) finds the palette and
    # the scene as they were. The newest window takes over; the previous one is told and closed.
    from ._session import PRELOAD_EXAMPLE

    session = Session(root, seed=seed, preload=PRELOAD_EXAMPLE if preload else None)
    app.state.session = session
    lock = threading.Lock()
    current: dict[str, Any] = {"outbox": None}

    def handle(msg: dict[str, Any], emit: Any) -> list[dict[str, Any]]:
        with lock:
            return session.handle(msg, emit)

    @app.websocket("/ws")
    async def ws(websocket: WebSocket) -> None:
        if not _origin_ok(websocket.headers.get("origin"), allowed_hosts, websocket.headers.get("host")):
            await websocket.close(code=1008)
            return
        await websocket.accept()
        app.state.sessions += 1
        loop = asyncio.get_running_loop()
        inbox: asyncio.Queue[dict[str, Any] | None] = asyncio.Queue()
        outbox: asyncio.Queue[str | None] = asyncio.Queue()
        previous = current["outbox"]
        current["outbox"] = outbox
        if previous is not None:
            previous.put_nowait(_TAKEOVER)

        def emit(msg: dict[str, Any]) -> None:  # from the worker thread
            try:
                text = _dumps(msg)
            except (TypeError, ValueError):  # a partial result that cannot be sent is skipped
                return
            loop.call_soon_threadsafe(outbox.put_nowait, text)

        def error(message: str, msg: dict[str, Any] | None = None) -> str:
            ref = msg.get("type") if msg is not None else None
            mid = msg.get("id") if msg is not None and isinstance(msg.get("id"), int) and not isinstance(msg.get("id"), bool) else None
            return _dumps({"type": "error", "message": message, "ref": ref, "id": mid})

        async def receiver() -> None:
            try:
                while True:
                    data = await websocket.receive()
                    if data["type"] == "websocket.disconnect":
                        break
                    text = data.get("text")
                    if text is None:
                        raw = data.get("bytes") or b""
                        if len(raw) > MAX_MESSAGE_BYTES:
                            await outbox.put(error(f"message: {len(raw)} bytes is over the limit of {MAX_MESSAGE_BYTES}"))
                            continue
                        text = raw.decode("utf-8", errors="replace")
                    try:
                        msg = parse_message(text)
                    except InputError as exc:
                        await outbox.put(error(str(exc)))
                        continue
                    if msg["type"] == "stop":  # takes effect while a fill runs
                        session.cancel.set()
                    await inbox.put(msg)
            except (WebSocketDisconnect, RuntimeError):  # closed by us (takeover) or by the page
                pass
            finally:
                if current["outbox"] is outbox:  # a fill running for this window stops
                    session.cancel.set()
                await inbox.put(None)

        def merge_moves(msg: dict[str, Any]) -> dict[str, Any]:
            """Merge stroke segments already waiting in the queue into ``msg``."""
            pts = msg.get("points")
            if not isinstance(pts, list):
                return msg
            while not inbox.empty():
                nxt = inbox._queue[0]  # type: ignore[attr-defined]
                if nxt is None or nxt.get("type") != "stroke_move" or not isinstance(nxt.get("points"), list):
                    break
                if len(pts) + len(nxt["points"]) > MAX_POINTS:
                    break
                inbox.get_nowait()
                pts = pts + nxt["points"]
            return {**msg, "points": pts}

        async def worker() -> None:
            while True:
                msg = await inbox.get()
                if msg is None:
                    break
                if msg["type"] == "stroke_move":
                    msg = merge_moves(msg)
                try:
                    replies = await _in_daemon_thread(handle, msg, emit)
                    texts = [_dumps(r) for r in replies]
                except InputError as exc:
                    await outbox.put(error(str(exc).replace("\n", " "), msg))
                    continue
                except Cancelled:
                    await outbox.put(error("cancelled", msg))
                    continue
                except Exception as exc:  # the server keeps serving
                    await outbox.put(error(f"internal error: {type(exc).__name__}: {exc}", msg))
                    continue
                for t in texts:
                    await outbox.put(t)
                await outbox.put(_dumps({"type": "done", "ref": msg["type"], "id": msg.get("id") if isinstance(msg.get("id"), int) else None}))
            await outbox.put(None)

        async def sender() -> None:
            while True:
                text = await outbox.get()
                if text is None:
                    break
                try:
                    if text is _TAKEOVER:
                        await websocket.send_text(_dumps({"type": "error", "message": "the studio was opened in another window", "ref": None, "id": None}))
                        await websocket.close(code=4000)
                        break
                    await websocket.send_text(text)
                except Exception:
                    break

        tasks = [asyncio.create_task(receiver()), asyncio.create_task(worker()), asyncio.create_task(sender())]
        try:
            await asyncio.gather(*tasks)
        finally:
            for t in tasks:
                t.cancel()
            app.state.sessions -= 1
            if current["outbox"] is outbox:
                current["outbox"] = None

    return app
