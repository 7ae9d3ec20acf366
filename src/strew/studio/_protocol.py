"""The studio's websocket protocol: JSON messages with a ``type``, and their limits.

Every message from the browser is a JSON object ``{"type": ..., ...}``. It is parsed
with :func:`json.loads` and checked field by field; nothing in it is ever executed. A
message that is too large, is not JSON, has an unknown type or a bad field gets an
``{"type": "error", "message": ..., "ref": type, "id": id}`` reply, and the server keeps
serving. Every handled message is answered by its replies and then
``{"type": "done", "ref": type, "id": id}`` (``id``: an integer the browser may send).

Browser -> server (coordinates are world units, ``points`` is ``[[x, y], ...]``):

=====================  ==============================================================
``hello``              everything needed to draw the studio (the replies below)
``load_exemplar``      ``path`` (inside PROJECT_DIR, .svg/.json) or ``example`` (a name)
``select``             ``names``: the exemplars that drive synthesis (one or several)
``palette_new``        ``name``: an empty exemplar to place elements in
``palette_remove``     ``exemplar``
``palette_edit``       ``exemplar``, ``op``: ``place`` (``kind, x, y``), ``move``
                       (``index, x, y``), ``delete`` (``index``), ``radius`` (``index``,
                       ``field``: radius or neighborhood_radius, ``value``)
``palette_flip``       ``exemplar, i, j``: flip a connectivity edge (Ijiri Fig. 3)
``palette_from_scene`` ``name`` and optional lasso ``points``
``stroke_start``       ``tool`` (brush, spray, erase, flow, boundary, region), ``radius``,
                       ``points``; ``target``: scene or palette (with ``exemplar``);
                       ``pressure`` (0-1, a pen's): scales the brush density
``stroke_move``        ``points``: the next segment (results stream back at once);
                       ``pressure`` as above
``stroke_end``         optional last ``points``
``fill``               ``point``: ``[[x, y]]``; ``stop`` ends it early
``region``             ``size``: ``[w, h]``, or ``points``: an outline
``clear``              ``what``: scene, flow or boundary
``undo``, ``redo``     the history covers palette and scene
``save``               ``palette.json`` and ``scene.json`` in PROJECT_DIR
``load_project``       reads them back
``export``             ``path`` inside PROJECT_DIR: .svg, .png or .json
``settings``           the ``controls``' keys (``grow_mode``, ``jitter_scale``,
                       ``jitter_rotation`` in degrees, ``brush_density``), checked by
                       their methods' Params;
                       ``repeat`` (true/false): the repeat view, where brush, spray and
                       eraser strokes wrap across the (rectangular) region's edges
``clip``               remove the scene elements outside the region (or across a
                       boundary stroke), locked layers kept
``layers``             ``order``, ``hidden``, ``locked``: kind names (one layer a kind)
``ping``, ``list_files``
=====================  ==============================================================

Server -> browser: ``shapes`` (the kind library: paths and styles), ``palette`` (each
exemplar's elements, radii and edges), ``scene`` (``op`` ``replace`` with columns
``k, x, y, r, s``, or ``patch`` with ``update`` and ``append``), ``strokes`` (flow and
boundary strokes, flow arrows, region outline), ``controls`` (each parameter control:
the method's Param declaration, its ``settings`` key and element id; see
``studio/_controls.py``), ``layers``, ``status`` (the element
count, which is :func:`strew.metrics.visible_count` of the scene as saved; ``rate``:
elements/s of the last operation; ``fidelity``: the verdict of
:func:`strew.metrics.fidelity` on the last fill or stroke, or null; ``outside``:
elements a ``clip`` would remove; history depth; message), ``files``, ``saved``, ``exported``,
``pong``, ``error``, ``done``.
"""

from __future__ import annotations

import json
import math
from typing import Any

import numpy as np

from .._errors import InputError

__all__ = [
    "MAX_MESSAGE_BYTES",
    "MAX_POINTS",
    "MAX_NAME_LENGTH",
    "MESSAGE_TYPES",
    "parse_message",
    "get_points",
    "get_number",
    "get_int",
    "get_str",
    "get_names",
]

#: Largest message accepted from the browser, in bytes (UTF-8).
MAX_MESSAGE_BYTES = 256 * 1024
#: Most points in one message (a stroke segment, a region outline).
MAX_POINTS = 4096
#: Longest exemplar or file name.
MAX_NAME_LENGTH = 255
#: Largest coordinate magnitude accepted.
MAX_COORDINATE = 1e7

MESSAGE_TYPES = (
    "hello",
    "ping",
    "list_files",
    "load_exemplar",
    "select",
    "palette_new",
    "palette_remove",
    "palette_edit",
    "palette_flip",
    "palette_from_scene",
    "stroke_start",
    "stroke_move",
    "stroke_end",
    "fill",
    "stop",
    "region",
    "clear",
    "undo",
    "redo",
    "save",
    "load_project",
    "export",
    "settings",
    "clip",
    "layers",
    "load_mesh",  # the 3D view (studio/_surface3d.py)
    "brush3d",
    "clear3d",
)


def parse_message(text: str | bytes) -> dict[str, Any]:
    """Parse and check the envelope of one message.

    Raises
    ------
    InputError
        Too large, not JSON, not an object, or an unknown ``type``.
    """
    size = len(text.encode("utf-8")) if isinstance(text, str) else len(text)
    if size > MAX_MESSAGE_BYTES:
        raise InputError(f"message: {size} bytes is over the limit of {MAX_MESSAGE_BYTES}")
    try:
        msg = json.loads(text, parse_constant=_no_constant)
    except (json.JSONDecodeError, UnicodeDecodeError, ValueError) as exc:
        raise InputError(f"message: not valid JSON ({exc})") from None
    except RecursionError:  # a RuntimeError: the receiver would take it for a closed socket
        raise InputError("message: nested too deeply") from None
    if not isinstance(msg, dict):
        raise InputError("message: must be a JSON object with a 'type'")
    t = msg.get("type")
    if not isinstance(t, str):
        raise InputError("message.type: missing or not a string")
    if t not in MESSAGE_TYPES:
        raise InputError(f"message.type: unknown type {t[:40]!r}")
    return msg


def _no_constant(name: str) -> float:
    raise ValueError(f"{name} is not allowed")


def get_points(msg: dict[str, Any], key: str = "points", *, min_points: int = 1) -> np.ndarray:
    """``msg[key]`` as an (n, 2) float array of finite points (1 <= n <= MAX_POINTS)."""
    raw = msg.get(key)
    if not isinstance(raw, list):
        raise InputError(f"{key}: must be a list of [x, y] points")
    if len(raw) > MAX_POINTS:
        raise InputError(f"{key}: {len(raw)} points is over the limit of {MAX_POINTS}")
    if len(raw) < min_points:
        raise InputError(f"{key}: needs at least {min_points} point(s)")
    for i, p in enumerate(raw):
        if not (isinstance(p, list) and len(p) == 2 and all(_is_number(v) for v in p)):
            raise InputError(f"{key}[{i}]: must be [x, y] with two numbers")
    arr = np.asarray(raw, dtype=float).reshape(-1, 2)
    if not np.all(np.abs(arr) <= MAX_COORDINATE):
        raise InputError(f"{key}: coordinates must be finite and within ±{MAX_COORDINATE:g}")
    return arr


def _is_number(v: Any) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def get_number(msg: dict[str, Any], key: str, *, default: float | None = None, lo: float | None = None, hi: float | None = None) -> float:
    """``msg[key]`` as a finite float in ``[lo, hi]``."""
    v = msg.get(key, default)
    if v is None or not _is_number(v):
        raise InputError(f"{key}: must be a number")
    v = float(v)
    if (lo is not None and v < lo) or (hi is not None and v > hi):
        raise InputError(f"{key}: {v:g} is out of range [{lo if lo is not None else '-inf'}, {hi if hi is not None else 'inf'}]")
    return v


def get_int(msg: dict[str, Any], key: str, *, lo: int = 0, hi: int = 2**31) -> int:
    """``msg[key]`` as an integer in ``[lo, hi]``."""
    v = msg.get(key)
    if isinstance(v, bool) or not isinstance(v, int):
        raise InputError(f"{key}: must be an integer")
    if not lo <= v <= hi:
        raise InputError(f"{key}: {v} is out of range [{lo}, {hi}]")
    return v


def get_str(msg: dict[str, Any], key: str, *, choices: tuple[str, ...] | None = None, default: str | None = None) -> str:
    """``msg[key]`` as a short string (one of ``choices`` if given)."""
    v = msg.get(key, default)
    if not isinstance(v, str) or not v or len(v) > MAX_NAME_LENGTH:
        raise InputError(f"{key}: must be a non-empty string of at most {MAX_NAME_LENGTH} characters")
    if choices is not None and v not in choices:
        raise InputError(f"{key}: unknown value {v[:40]!r}; use one of {', '.join(choices)}")
    return v


def get_names(msg: dict[str, Any], key: str = "names") -> list[str]:
    """``msg[key]`` as a list of short strings."""
    v = msg.get(key)
    if not isinstance(v, list) or len(v) > 256 or not all(isinstance(s, str) and 0 < len(s) <= MAX_NAME_LENGTH for s in v):
        raise InputError(f"{key}: must be a list of names")
    return list(v)
