"""Studio hardening (issue 17, point 7): containment of project files, size limits before
parsing, deeply nested messages, over-long export names, and a server that stops."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time

import pytest

pytest.importorskip("fastapi")
pytest.importorskip("httpx")

from _studio_client import _alive, _ask, _until, client  # noqa: E402,F401


SECRET_DOC = json.dumps(
    {
        "format": "strew.arrangement",
        "version": 1,
        "shapes": {"topsecret": {"paths": [{"points": [[0, 0], [1, 0], [0, 1]], "closed": True}]}},
        "elements": {"kind": ["topsecret"] * 4, "x": [0, 5, 0, 5], "y": [0, 0, 5, 5]},
    }
)


@pytest.mark.parametrize("name", ["scene.json", "palette.json"])
def test_load_project_does_not_follow_a_symlink_out_of_the_folder(client, tmp_path, name):
    outside = tmp_path / "outside.json"
    outside.write_text(SECRET_DOC)
    os.symlink(outside, client.project / name)
    with client.websocket_connect("/ws") as ws:
        replies = _ask(ws, {"type": "load_project"})
        assert replies[-1]["type"] == "error" and "outside the project folder" in replies[-1]["message"]
        assert not any("topsecret" in json.dumps(m) for m in replies)
        _alive(ws)


def test_oversized_exemplar_is_refused_before_parsing(client, monkeypatch):
    import strew.studio._session as session

    monkeypatch.setattr(session, "STUDIO_MAX_FILE_BYTES", 10_000)
    (client.project / "big.svg").write_text(
        '<svg xmlns="http://www.w3.org/2000/svg">' + '<path d="M0 0 L10 0 L0 10 Z"/>' * 2000 + "</svg>"
    )
    with client.websocket_connect("/ws") as ws:
        t0 = time.perf_counter()
        m = _ask(ws, {"type": "load_exemplar", "path": "big.svg"})[-1]
        assert time.perf_counter() - t0 < 2.0
        assert m["type"] == "error" and "over the limit" in m["message"] and "big.svg" in m["message"]
        _alive(ws)


def test_too_many_paths_are_refused(client, monkeypatch):
    import strew.studio._session as session

    monkeypatch.setattr(session, "STUDIO_MAX_PATHS", 50)
    (client.project / "many.svg").write_text(
        '<svg xmlns="http://www.w3.org/2000/svg">' + "".join(f'<path d="M{i} 0 l1 0 l0 1 Z"/>' for i in range(0, 400, 4)) + "</svg>"
    )
    with client.websocket_connect("/ws") as ws:
        m = _ask(ws, {"type": "load_exemplar", "path": "many.svg"})[-1]
        assert m["type"] == "error" and "paths" in m["message"] and "over the limit" in m["message"]
        _alive(ws)


def test_deeply_nested_message_gets_an_error_reply(client):
    with client.websocket_connect("/ws") as ws:
        ws.send_text("[" * 100_000 + "]" * 100_000)
        m = ws.receive_json()
        assert m["type"] == "error" and "nested too deeply" in m["message"]
        ws.send_text('{"type": "ping", "x": ' + "[" * 60_000 + "]" * 60_000 + "}")
        m = ws.receive_json()
        assert m["type"] == "error" and "nested too deeply" in m["message"]
        _alive(ws)


@pytest.mark.parametrize("name", ["a" * 250 + ".svg", "sub" * 80 + "/x.svg", "b" * 255 + ".png"])
def test_over_long_export_names_are_refused_clearly(client, name):
    with client.websocket_connect("/ws") as ws:
        m = _ask(ws, {"type": "export", "path": name})[-1]
        assert m["type"] == "error" and "internal error" not in m["message"]
        assert "path" in m["message"] or "too long" in m["message"]
        _alive(ws)
    assert list(client.project.iterdir()) == []


_SLOW_SERVER = """
import sys, time
import strew.studio._session as s
real = s.Session.handle
def slow(self, msg, emit):
    if msg.get("type") == "list_files":
        time.sleep(120)  # a message that takes very long to handle
    return real(self, msg, emit)
s.Session.handle = slow
from strew.studio import serve
serve(sys.argv[1], port=0, open_browser=False, on_ready=lambda url: print("READY", url, flush=True))
"""


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM], ids=["SIGINT", "SIGTERM"])
def test_server_stops_while_a_message_is_being_handled(tmp_path, sig):
    websockets = pytest.importorskip("websockets.sync.client")
    proc = subprocess.Popen([sys.executable, "-c", _SLOW_SERVER, str(tmp_path)], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        deadline = time.monotonic() + 60
        line = ""
        while "READY" not in line and time.monotonic() < deadline:
            line = proc.stdout.readline()
            if not line and proc.poll() is not None:
                pytest.fail(proc.stderr.read())
        url = line.split()[-1]
        ws_url = url.replace("http://", "ws://") + "ws"
        with websockets.connect(ws_url, origin=url.rstrip("/")) as ws:
            ws.send(json.dumps({"type": "list_files"}))
            time.sleep(0.5)
            proc.send_signal(sig)
            t0 = time.monotonic()
            proc.wait(timeout=15)
        assert time.monotonic() - t0 < 10
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
        proc.stdout.close()
        proc.stderr.close()


def _slow_exemplar(path, n=4000):
    """An SVG of ``n`` distinct small polygons (every object a new kind: seconds to import)."""
    import numpy as np

    rng = np.random.default_rng(3)
    parts = []
    for _ in range(n):
        x, y = rng.uniform(0, 1000, 2)
        t = np.sort(rng.uniform(0, 2 * np.pi, 6))
        r = rng.uniform(2, 6, 6)
        parts.append('<polygon points="' + " ".join(f"{x + a * np.cos(b):.2f},{y + a * np.sin(b):.2f}" for a, b in zip(r, t)) + '"/>')
    path.write_text('<svg xmlns="http://www.w3.org/2000/svg">' + "".join(parts) + "</svg>")


def test_stop_cancels_an_exemplar_load(tmp_path):
    from strew.studio._session import Session

    _slow_exemplar(tmp_path / "heavy.svg")
    s = Session(tmp_path)
    seen = []

    def stop_once_loading(msg):  # the page's "stop", sent when it sees the load start
        seen.append(msg)
        if msg.get("type") == "status" and msg["message"].startswith("loading"):
            s.cancel.set()

    t0 = time.perf_counter()
    out = s.handle({"type": "load_exemplar", "path": "heavy.svg"}, stop_once_loading)
    assert time.perf_counter() - t0 < 2.0
    assert out[-1]["type"] == "status" and out[-1]["message"] == "loading heavy.svg stopped"
    assert s.palette == {} and s.undo_stack == []  # nothing half-loaded
    # the next load starts afresh (a stale stop does not cancel it)
    s.handle({"type": "load_exemplar", "example": "scales.svg"})
    assert list(s.palette) == ["scales"]


def test_stop_over_the_socket_ends_a_heavy_load_and_the_server_serves_on(client):
    _slow_exemplar(client.project / "heavy.svg")
    with client.websocket_connect("/ws") as ws:
        ws.send_text(json.dumps({"type": "load_exemplar", "path": "heavy.svg"}))
        m = ws.receive_json()
        assert m["type"] == "status" and m["message"] == "loading heavy.svg"
        t0 = time.perf_counter()
        ws.send_text(json.dumps({"type": "stop"}))
        replies = _until(ws, "load_exemplar")
        assert time.perf_counter() - t0 < 2.0
        assert replies[-1]["type"] == "done"
        assert any(r["type"] == "status" and r["message"] == "loading heavy.svg stopped" for r in replies)
        assert client.app.state.session.palette == {}
        assert _until(ws, "stop")[-1]["type"] == "done"  # the stop message's own reply
        _alive(ws)
