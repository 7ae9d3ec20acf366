"""The studio's parameter controls come from the methods' specs (issue 15 point 1)."""

from __future__ import annotations

import math

import pytest

from strew._errors import InputError
from strew._method import spec
from strew.studio import _controls
from strew.studio._session import Session


def _controls_of(session: Session) -> dict[str, dict]:
    msgs = [m for m in session.handle({"type": "hello"}) if m["type"] == "controls"]
    assert len(msgs) == 1
    return {c["key"]: c for c in msgs[0]["controls"]}


def test_every_studio_param_is_a_control_with_its_declared_default_and_range(tmp_path):
    got = _controls_of(Session(tmp_path))
    assert list(got) == [key for _, _, key, _ in _controls.STUDIO_PARAMS]
    for method, name, key, elem in _controls.STUDIO_PARAMS:
        p = _controls.BRUSH_DENSITY if method == "studio" else spec(method).param(name)
        c = got[key]
        f = 180.0 / math.pi if p.unit == "radians" else 1.0
        assert (c["method"], c["name"], c["id"], c["type"]) == (method, name, elem, p.type)
        assert c["default"] == (p.default * f if isinstance(p.default, float) else p.default)
        assert c["low"] == (None if p.low is None else p.low * f)
        assert c["high"] == (None if p.high is None else p.high * f)
        assert (c["low_open"], c["high_open"]) == (p.low_open, p.high_open)
        assert c["choices"] == (None if p.choices is None else list(p.choices))
        assert c["help"] == p.help and c["section"] == p.section
        assert c["unit"] == ("degrees" if p.unit == "radians" else p.unit)


def test_the_session_starts_at_the_declared_defaults(tmp_path):
    s = Session(tmp_path)
    for c in _controls.controls():
        assert getattr(s, c.key) == c.param.default, c.key


def test_settings_are_checked_by_the_methods_params(tmp_path):
    s = Session(tmp_path)
    s.handle({"type": "settings", "grow_mode": "rotate", "jitter_scale": 0.3, "jitter_rotation": 20, "brush_density": 0.5})
    assert (s.grow_mode, s.jitter_scale, s.brush_density) == ("rotate", 0.3, 0.5)
    assert s.jitter_rotation == pytest.approx(math.radians(20))
    jitter = spec("grow").param("jitter_scale")
    assert jitter.high == 1 and jitter.high_open
    for msg, needle in [
        ({"grow_mode": "sideways"}, "grow_mode: unknown choice 'sideways'"),
        ({"jitter_scale": 1.0}, "jitter_scale: "),  # the spec's open bound
        ({"jitter_rotation": -5}, "jitter_rotation: "),
        ({"jitter_rotation": "5"}, "jitter_rotation: must be a number"),
        ({"brush_density": 0}, "brush_density: "),
    ]:
        with pytest.raises(InputError, match=needle):
            s.handle({"type": "settings", **msg})
    assert (s.grow_mode, s.jitter_scale, s.brush_density) == ("rotate", 0.3, 0.5)


def test_the_page_declares_no_method_parameter_by_hand():
    from pathlib import Path

    import strew.studio

    html = (Path(strew.studio.__file__).parent / "static" / "index.html").read_text(encoding="utf-8")
    assert 'id="method-controls"' in html
    for c in _controls.controls():
        if c.method != "studio":  # the method's controls are drawn from the controls message
            assert f'id="{c.id}"' not in html, c.id
