"""The studio's parameter controls, generated from the methods' specs (issue 15 point 1).

A method declares each parameter once, in its ``SPEC`` (:class:`strew._method.Param`:
type, default, range or choices, unit, help, paper section). The studio picks the ones
it offers (:data:`STUDIO_PARAMS`) and sends their declarations to the browser in a
``controls`` message, which draws one input per control; a ``settings`` message is
checked by the same :meth:`~strew._method.Param.check`. The studio's own setting (the
brush density, an extension of Davison §5.4) is declared the same way, here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from .._errors import InputError
from .._method import Param, spec

__all__ = ["STUDIO_PARAMS", "BRUSH_DENSITY", "Control", "controls", "controls_message", "read_setting"]

#: Brush density: the studio's own parameter (the paper synthesises at the exemplar's
#: density only; §7 names adapting density as a limitation).
BRUSH_DENSITY = Param(
    "brush_density", "float", 1.0, low=0.05, high=1.0,
    help="Brush density: the share of the texture's elements a brush stroke keeps (1 = the exemplar's density); a pen's pressure scales it",
    section="extension of Davison §5.4",
)

#: (method, parameter, settings key, element id) of every control the studio offers, in
#: toolbar order. The settings key is the field of the ``settings`` message (and the
#: session attribute); the element id names the browser's input.
STUDIO_PARAMS: tuple[tuple[str, str, str, str], ...] = (
    ("studio", "brush_density", "brush_density", "density"),
    ("grow", "mode", "grow_mode", "grow-mode"),
    ("grow", "jitter_scale", "jitter_scale", "jitter-scale"),
    ("grow", "jitter_rotation", "jitter_rotation", "jitter-rotation"),
)


@dataclass(frozen=True)
class Control:
    """One studio control: a method's :class:`~strew._method.Param` and where it goes.

    Angles declared in radians are shown (and sent by the browser) in degrees:
    :attr:`factor` converts the declared unit to the shown one.
    """

    method: str
    param: Param
    key: str
    id: str

    @property
    def factor(self) -> float:
        return 180.0 / math.pi if self.param.unit == "radians" else 1.0

    @property
    def unit(self) -> str:
        return "degrees" if self.param.unit == "radians" else self.param.unit

    def shown(self, value: Any) -> Any:
        """A declared value (default, bound) in the shown unit."""
        return value * self.factor if isinstance(value, (int, float)) and not isinstance(value, bool) else value

    def to_json(self) -> dict[str, Any]:
        p = self.param
        return {
            "method": self.method,
            "name": p.name,
            "key": self.key,
            "id": self.id,
            "type": p.type,
            "default": self.shown(p.default),
            "low": self.shown(p.low),
            "high": self.shown(p.high),
            "low_open": p.low_open,
            "high_open": p.high_open,
            "choices": None if p.choices is None else list(p.choices),
            "unit": self.unit,
            "help": p.help,
            "section": p.section,
        }

    def read(self, msg: dict[str, Any]) -> Any:
        """The value of :attr:`key` in a ``settings`` message, checked by the Param, in
        the declared unit; :class:`InputError` naming the key when bad."""
        value = msg[self.key]
        if self.factor != 1.0:
            if isinstance(value, bool) or not isinstance(value, (int, float)):
                raise InputError(f"{self.key}: must be a number of {self.unit}, got {str(value)[:40]!r}")
            value = value / self.factor
        try:
            return self.param.check(value)
        except InputError as exc:
            text = str(exc)
            if text.startswith(self.param.name + ":"):
                text = self.key + text[len(self.param.name):]
            if self.factor != 1.0:
                text += f" (in radians; the studio reads {self.unit})"
            raise InputError(text) from None


def controls() -> list[Control]:
    """Every control of :data:`STUDIO_PARAMS`, its Param read from the method's spec."""
    out = []
    for method, name, key, elem in STUDIO_PARAMS:
        p = BRUSH_DENSITY if method == "studio" else spec(method).param(name)
        out.append(Control(method, p, key, elem))
    return out


def controls_message() -> dict[str, Any]:
    """The ``controls`` message: every control's declaration, for the browser."""
    return {"type": "controls", "controls": [c.to_json() for c in controls()]}


def read_setting(msg: dict[str, Any], key: str) -> Any:
    """The checked value of settings field ``key`` (see :meth:`Control.read`)."""
    for c in controls():
        if c.key == key:
            return c.read(msg)
    raise KeyError(key)
