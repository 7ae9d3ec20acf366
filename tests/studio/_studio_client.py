"""Shared helpers of the studio server tests: an in-process client and websocket requests."""

from __future__ import annotations

import json
import warnings

import pytest


@pytest.fixture
def client(tmp_path):
    """A TestClient on a studio app serving an empty project folder (``client.project``),
    with an empty palette (no example preloaded)."""
    with warnings.catch_warnings():
        # starlette's TestClient warns about httpx at import time
        warnings.simplefilter("ignore")
        from fastapi.testclient import TestClient
    from strew.studio import create_app

    project = tmp_path / "project"
    project.mkdir()
    with TestClient(create_app(project, warm=False, preload=False)) as c:
        c.project = project
        yield c


def _until(ws, ref):
    """Messages up to the 'done' for ``ref`` (or the first error)."""
    out = []
    while True:
        m = ws.receive_json()
        out.append(m)
        if (m["type"] == "done" and m["ref"] == ref) or m["type"] == "error":
            return out


def _ask(ws, msg):
    ws.send_text(json.dumps(msg))
    return _until(ws, msg["type"])


def _alive(ws, t=5):
    assert _ask(ws, {"type": "ping", "t": t})[0] == {"type": "pong", "t": t}
