"""The studio server: protocol, safety (path escapes, size limits, malformed messages), CLI."""

from __future__ import annotations

import json
import os

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

pytest.importorskip("fastapi")
pytest.importorskip("httpx")

from strew.cli import main  # noqa: E402
from strew.studio._protocol import MAX_MESSAGE_BYTES, MAX_POINTS  # noqa: E402

from _studio_client import _alive, _ask, _until, client  # noqa: E402,F401


def test_page_and_static_files(client):
    r = client.get("/")
    assert r.status_code == 200 and 'type="module"' in r.text and "/static/main.js" in r.text
    for f in ("main.js", "render.js", "palette.js", "studio.css"):
        assert client.get(f"/static/{f}").status_code == 200
    assert client.get("/static/../_session.py").status_code == 404
    assert client.get("/static/%2e%2e/_session.py").status_code == 404


def test_hello_gives_the_full_state(client):
    with client.websocket_connect("/ws") as ws:
        types = [m["type"] for m in _ask(ws, {"type": "hello"})]
    assert types[:3] == ["shapes", "palette", "strokes"]
    assert {"scene", "files", "status", "done"} <= set(types)


@pytest.mark.parametrize(
    "text, needle",
    [
        ("not json", "not valid JSON"),
        ("[1, 2]", "JSON object"),
        ('{"x": 1}', "message.type"),
        ('{"type": 7}', "message.type"),
        ('{"type": "__init__"}', "unknown type"),
        ('{"type": "handle"}', "unknown type"),
        ('{"type": "stroke_start", "tool": "brush", "radius": NaN, "points": [[1, 2]]}', "not valid JSON"),
        ('{"type": "stroke_start", "tool": "laser", "radius": 3, "points": [[1, 2]]}', "tool"),
        ('{"type": "stroke_start", "tool": "erase", "radius": 3, "points": [[1, "2"]]}', "points[0]"),
        ('{"type": "stroke_start", "tool": "erase", "radius": -3, "points": [[1, 2]]}', "radius"),
        ('{"type": "stroke_move", "points": [[1, 2]]}', "no stroke in progress"),
        ('{"type": "fill", "point": [[1e300, 2]]}', "coordinates"),
        ('{"type": "region", "size": [0, 10]}', "out of range"),
        ('{"type": "select", "names": "abc"}', "names"),
        ('{"type": "palette_edit", "exemplar": "none", "op": "delete", "index": 0}', "no exemplar"),
        ('{"type": "settings", "grow_mode": "sideways"}', "grow_mode"),
    ],
)
def test_malformed_messages_get_an_error_and_the_server_keeps_serving(client, text, needle):
    with client.websocket_connect("/ws") as ws:
        ws.send_text(text)
        m = ws.receive_json()
        assert m["type"] == "error" and needle in m["message"]
        assert "\n" not in m["message"]
        _alive(ws)


def test_size_limits(client):
    with client.websocket_connect("/ws") as ws:
        big = json.dumps({"type": "ping", "pad": "x" * (MAX_MESSAGE_BYTES + 10)})
        ws.send_text(big)
        m = ws.receive_json()
        assert m["type"] == "error" and "over the limit" in m["message"]
        _alive(ws)
        ws.send_bytes(b"x" * (MAX_MESSAGE_BYTES + 10))
        m = ws.receive_json()
        assert m["type"] == "error" and "over the limit" in m["message"]
        _alive(ws)
        pts = [[1.0, 2.0]] * (MAX_POINTS + 1)
        m = _ask(ws, {"type": "stroke_start", "tool": "erase", "radius": 3, "points": pts})[-1]
        assert m["type"] == "error" and f"limit of {MAX_POINTS}" in m["message"]
        _alive(ws)


@pytest.mark.parametrize(
    "path",
    ["../escape.svg", "/tmp/escape.svg", "a/../../escape.svg", "..\\escape.svg", "~/escape.svg", "escape.py", "", "sub/none/escape.svg", "x\x00.svg"],
)
def test_export_cannot_escape_the_project(client, path):
    with client.websocket_connect("/ws") as ws:
        m = _ask(ws, {"type": "export", "path": path})[-1]
        assert m["type"] == "error" and "path" in m["message"]
        _alive(ws)
    parent = client.project.parent
    assert sorted(p.name for p in parent.iterdir()) == ["project"]
    assert list(client.project.iterdir()) == []


def test_symlink_out_of_the_project_is_refused(client, tmp_path):
    outside = tmp_path / "outside"
    outside.mkdir()
    (outside / "secret.json").write_text("{}")
    os.symlink(outside, client.project / "link")
    with client.websocket_connect("/ws") as ws:
        m = _ask(ws, {"type": "load_exemplar", "path": "link/secret.json"})[-1]
        assert m["type"] == "error" and "outside the project folder" in m["message"]
        m = _ask(ws, {"type": "export", "path": "link/new.svg"})[-1]
        assert m["type"] == "error" and "outside the project folder" in m["message"]
    assert sorted(p.name for p in outside.iterdir()) == ["secret.json"]


def test_load_paint_and_export_over_the_websocket(client):
    with client.websocket_connect("/ws") as ws:
        _ask(ws, {"type": "hello"})
        out = _ask(ws, {"type": "load_exemplar", "example": "scales.svg"})
        assert any(m["type"] == "palette" and m["exemplars"][0]["name"] == "scales" for m in out)
        ws.send_text(json.dumps({"type": "stroke_start", "tool": "brush", "radius": 40, "points": [[100, 200]]}))
        for i in range(1, 12):
            ws.send_text(json.dumps({"type": "stroke_move", "points": [[100 + 20 * i, 200]]}))
        out = _ask(ws, {"type": "stroke_end"})
        n = out[-2]["count"]
        assert n > 10
        scenes = [m for m in out if m["type"] == "scene"]
        assert scenes and scenes[-1]["n"] == n
        out = _ask(ws, {"type": "export", "path": "scene.svg"})
        assert out[0] == {"type": "exported", "path": "scene.svg", "count": n}
        m = _ask(ws, {"type": "load_exemplar", "path": "scene.svg"})[-1]
        assert m["type"] == "done"
    svg = (client.project / "scene.svg").read_text()
    assert svg.count("<use") == n


def test_cross_site_websocket_is_refused(client):
    from starlette.websockets import WebSocketDisconnect

    with pytest.raises(WebSocketDisconnect):
        with client.websocket_connect("/ws", headers={"origin": "http://evil.example"}) as ws:
            ws.receive_json()
    # a page of another local server (another port) is another site
    with pytest.raises(WebSocketDisconnect):
        with client.websocket_connect("/ws", headers={"origin": "http://127.0.0.1:3000", "host": "127.0.0.1:8765"}) as ws:
            ws.receive_json()
    with client.websocket_connect("/ws", headers={"origin": "http://127.0.0.1:8765", "host": "127.0.0.1:8765"}) as ws:
        _alive(ws)


def test_cli_binds_localhost_by_default(tmp_path, monkeypatch):
    import strew.studio

    calls = []
    monkeypatch.setattr(strew.studio, "serve", lambda root, **kw: calls.append((root, kw)))
    assert main(["studio", str(tmp_path), "--no-browser", "--port", "0"]) == 0
    (root, kw), = calls
    assert root == tmp_path and kw["host"] == "127.0.0.1" and kw["open_browser"] is False and kw["port"] == 0
    assert main(["studio", str(tmp_path)]) == 0
    assert calls[-1][1]["open_browser"] is True and calls[-1][1]["port"] == 8765


def test_cli_bad_project_dir(tmp_path, capsys):
    missing = tmp_path / "missing"
    assert main(["studio", str(missing), "--no-browser"]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "PROJECT_DIR" in err and "no such folder" in err
    assert not missing.exists()
    assert main(["studio", str(tmp_path), "--port", "70000"]) == 2


def test_cli_port_in_use(tmp_path, capsys):
    import socket

    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        sock.listen()
        port = sock.getsockname()[1]
        assert main(["studio", str(tmp_path), "--no-browser", "--port", str(port)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and f"--port {port}" in err


@settings(max_examples=200, deadline=None)
@given(parts=st.lists(st.sampled_from(["..", ".", "a", "b", "", "~", "/", "c.svg", "..svg", "x.json"]), min_size=1, max_size=6))
def test_resolved_paths_never_leave_the_project(tmp_path_factory, parts):
    from strew import InputError
    from strew.studio._paths import resolve_in_project

    root = tmp_path_factory.getbasetemp().resolve() / "resolve_root"
    (root / "a" / "b").mkdir(parents=True, exist_ok=True)
    name = "/".join(parts)
    try:
        full = resolve_in_project(root, name, suffixes=(".svg", ".json"))
    except InputError:
        return
    assert full.is_relative_to(root) and full.suffix in (".svg", ".json")


def test_internal_error_is_reported_and_the_server_keeps_serving(client, monkeypatch):
    from strew.studio._session import Session

    def broken(self, msg, emit):
        raise ZeroDivisionError("boom")

    monkeypatch.setattr(Session, "_on_list_files", broken)
    with client.websocket_connect("/ws") as ws:
        m = _ask(ws, {"type": "list_files"})[-1]
        assert m["type"] == "error" and "internal error" in m["message"] and "boom" in m["message"]
        _alive(ws)
        assert _ask(ws, {"type": "hello"})[-1]["type"] == "done"


def test_error_replies_name_the_message(client):
    with client.websocket_connect("/ws") as ws:
        m = _ask(ws, {"type": "stroke_start", "tool": "brush", "radius": 5, "points": [[1, 1]], "id": 42})[-1]
        assert m == {"type": "error", "message": "palette: empty; load an exemplar first", "ref": "stroke_start", "id": 42}
        m = _ask(ws, {"type": "undo", "id": 43})
        assert m[-1] == {"type": "done", "ref": "undo", "id": 43}


def test_cli_without_the_studio_extra(tmp_path, capsys, monkeypatch):
    import sys

    monkeypatch.setitem(sys.modules, "uvicorn", None)  # as if it were not installed
    assert main(["studio", str(tmp_path), "--no-browser"]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "pip install '.[studio]'" in err and "uvicorn" in err


def test_reloading_the_page_keeps_the_work(client):
    with client.websocket_connect("/ws") as ws:
        _ask(ws, {"type": "load_exemplar", "example": "scales.svg"})
        _ask(ws, {"type": "fill", "point": [[400, 300]]})
    with client.websocket_connect("/ws") as ws:
        out = _ask(ws, {"type": "hello"})
        palette = next(m for m in out if m["type"] == "palette")
        scene = next(m for m in out if m["type"] == "scene")
    assert [e["name"] for e in palette["exemplars"]] == ["scales"]
    assert scene["op"] == "replace" and scene["n"] > 20


def test_a_new_window_takes_over(client):
    from starlette.websockets import WebSocketDisconnect

    with client.websocket_connect("/ws") as old:
        _alive(old)
        with client.websocket_connect("/ws") as new:
            m = old.receive_json()
            assert m["type"] == "error" and "another window" in m["message"]
            with pytest.raises(WebSocketDisconnect):
                old.receive_json()
            _alive(new)


def test_origin_rule():
    from strew.studio._app import LOCAL_HOSTS, _origin_ok

    assert _origin_ok(None, LOCAL_HOSTS)
    assert _origin_ok("http://localhost:8765", LOCAL_HOSTS)
    assert _origin_ok("http://[::1]:8765", LOCAL_HOSTS)
    assert not _origin_ok("http://evil.example", LOCAL_HOSTS, "evil.example")
    assert not _origin_ok("null", LOCAL_HOSTS)
    # the port must be the studio's own (the Host header's)
    assert _origin_ok("http://localhost:8765", LOCAL_HOSTS, "localhost:8765")
    assert _origin_ok("http://localhost:8765", LOCAL_HOSTS, "127.0.0.1:8765")
    assert not _origin_ok("http://localhost:3000", LOCAL_HOSTS, "127.0.0.1:8765")
    assert not _origin_ok("http://127.0.0.1", LOCAL_HOSTS, "127.0.0.1:8765")
    assert not _origin_ok("http://127.0.0.1:99999x", LOCAL_HOSTS, "127.0.0.1:8765")
    assert not _origin_ok("file://localhost:8765", LOCAL_HOSTS, "127.0.0.1:8765")
    # bound to every interface: same-origin pages only
    wide = (*LOCAL_HOSTS, "0.0.0.0")
    assert _origin_ok("http://10.0.0.5:8765", wide, "10.0.0.5:8765")
    assert not _origin_ok("http://evil.example:8765", wide, "10.0.0.5:8765")
