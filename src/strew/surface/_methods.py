"""The methods' options on a surface: ``strew pack|synth|grow --surface MESH`` (issue 20).

:func:`on_surface` takes a method's name, its input and the values of its spec's
parameters (as the generated CLI converts them) and runs the surface version of the
method; options that have no meaning on a surface are refused by name, so that nothing
is silently ignored.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from .._errors import InputError
from ..arrangement import Arrangement

__all__ = ["on_surface", "SURFACE_METHODS"]

SURFACE_METHODS = ("pack", "synth", "grow")

# parameters of each method's spec that carry over (others are refused)
_PACK = {"max_failures", "rotation", "scale", "margin", "weights"}
_SYNTH = {"selection", "k", "c", "kind_cost", "keep_voids", "optimize", "brush_radius"}
_GROW = {"count", "start_kind", "jitter_scale", "jitter_rotation", "flips"}
# grow parameters whose default means "as on the plane" and that a surface accepts only so
# (the windowed relaxation is replaced on surfaces: strew.surface._grow notes)
_GROW_DEFAULTS = {"mode": "flow", "relax": True, "jitter_color": 0.0, "connectivity": False, "periodic": False,
                  "relax_every": 16, "avoid_overlaps": True}


def _refuse(method: str, values: dict[str, Any], allowed: set[str]) -> None:
    extra = sorted(k for k, v in values.items() if v is not None and k not in allowed)
    if extra:
        raise InputError(f"{extra[0]}: not available with --surface for {method} (on a surface: {', '.join(sorted(allowed))})")


def _one_range(value: Any, name: str) -> Any:
    if isinstance(value, dict):
        raise InputError(f"{name}: per-kind values are not available with --surface; give one range")
    return value


def on_surface(
    method: str,
    input: Any,
    mesh: Any,
    /,
    *,
    field: Any = "smoothest",
    unit: float | None = None,
    rng: Any = None,
    progress: Callable | None = None,
    should_cancel: Callable | None = None,
    **values: Any,
) -> Arrangement:
    """Run ``method`` (pack or synth) on ``mesh``.

    Parameters
    ----------
    method : {"pack", "synth", "grow"}
    input : Any
        The method's input: shapes (pack), exemplars (synth), an exemplar arrangement (grow).
    mesh : trimesh.Trimesh or path
    field : OrientationField or "smoothest"
    unit : float, optional
        Mesh units per document unit: pack scales its shapes by it (default 1); synth
        and grow scale the exemplar by it (default: about 2,000 elements on the mesh).
    values
        The method's parameters (names of its SPEC).

    Raises
    ------
    InputError
        An unknown method, or a parameter with no meaning on a surface (named).
    """
    values = {k: v for k, v in values.items() if v is not None}
    if method == "pack":
        from ._sample import pack

        _refuse(method, values, _PACK)
        rot = values.get("rotation")
        rotation = "field"
        if rot is not None:
            lo, hi = _one_range(rot, "rotation")
            if np.isclose(hi - lo, 2 * np.pi):
                rotation = "random"
            elif not (np.isclose(lo, 0.0) and np.isclose(hi, 0.0)):
                raise InputError("rotation: on a surface elements follow the field (leave it out or 0:0) or turn at random (0:360)")
        sc = _one_range(values.get("scale", (1.0, 1.0)), "scale")
        lo, hi = (float(sc), float(sc)) if np.ndim(sc) == 0 else (float(sc[0]), float(sc[1]))
        u = 1.0 if unit is None else float(unit)
        margin = values.get("margin", 0.0)
        if isinstance(margin, dict):
            raise InputError("margin: per-kind values are not available with --surface; give one number")
        kw: dict[str, Any] = {}
        if "max_failures" in values:
            kw["max_failures"] = values["max_failures"]
        if "weights" in values:
            w = values["weights"]
            kw["weights"] = {k: v for k, v in w.items() if k != "*"} if isinstance(w, dict) else w
        return pack(input, mesh, field=field, rotation=rotation, scale=(lo * u, hi * u), margin=float(margin) * u, rng=rng,
                    progress=progress, should_cancel=should_cancel, **kw)
    if method == "synth":
        from ._synth import synthesize

        _refuse(method, values, _SYNTH)
        if values.get("optimize", "none") not in ("none", "horizon"):
            raise InputError("optimize: on a surface give none (the default) or horizon; global is not carried over")
        values.setdefault("optimize", "none")
        if "brush_radius" in values:
            raise InputError("brush_radius: the brush on a surface is a library tool (strew.surface.SurfaceSynthState.brush)")
        sel = values.pop("selection", None)
        if isinstance(sel, dict) and any(not isinstance(v, (int, float)) for v in sel.values()):
            raise InputError("selection: regions (NAME=REGION) are not available with --surface; give names and weights")
        return synthesize(input, mesh, field=field, selection=sel, scale=unit, rng=rng, progress=progress,
                          should_cancel=should_cancel, **values)
    if method == "grow":
        from ._grow import grow

        if values.get("mode") in ("fixed", "flow"):
            # the orientation field is the flow: growth follows it in either mode (§5.3)
            values.pop("mode")
        if values.get("flips") == ():
            values.pop("flips")
        for name, default in _GROW_DEFAULTS.items():
            if name in values and values[name] == default:
                values.pop(name)
        if "relax" in values:  # --no-relax: there is no windowed relaxation on a surface
            values.pop("relax")
        _refuse(method, values, _GROW)
        return grow(input, mesh, field=field, scale=unit, rng=rng, progress=progress, should_cancel=should_cancel, **values)
    raise InputError(f"--surface: {method} does not run on surfaces (only {', '.join(SURFACE_METHODS)})")
