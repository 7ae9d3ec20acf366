"""Writer hooks of the core types: how :class:`~strew.Arrangement` shows and converts
itself without importing the io layer (issue 15 point 7).

Imports point down (README "Architecture"): the core types may not import
:mod:`strew.io`, yet ``Arrangement.to_svg()``, a notebook's ``_repr_svg_`` /
``_repr_png_`` and ``to_pandas()`` are written by io. So the core declares the hooks
here, by name, and io fills them: ``strew.io`` calls :func:`register` for each writer
when it is imported. Who imports io is the package facade's business: ``strew``'s
``__init__`` (the top layer, which already knows every layer) installs a provider with
:func:`set_provider` that imports :mod:`strew.io` on the first call of a hook, so that
``import strew`` stays as cheap as before and a hook works from any entry point.

Hooks: ``"svg"`` (arr, **kwargs) -> str, ``"png"`` (arr, **kwargs) -> bytes,
``"to_pandas"``, ``"to_geopandas"`` (arr) -> DataFrame and ``"from_pandas"`` (df, shapes,
**kwargs) -> Arrangement.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # pragma: no cover - `import strew` pays for this module
    from collections.abc import Callable

__all__ = ["HOOKS", "register", "set_provider", "hook"]

HOOKS = ("svg", "png", "to_pandas", "to_geopandas", "from_pandas")

_registered: dict[str, Callable[..., Any]] = {}
_provider: Callable[[], object] | None = None


def register(name: str, func: Callable[..., Any]) -> None:
    """Fill the hook ``name`` (one of :data:`HOOKS`) with ``func``; a later call replaces it."""
    if name not in HOOKS:
        raise ValueError(f"unknown display hook {name!r}; use one of {', '.join(HOOKS)}")
    _registered[name] = func


def set_provider(load: Callable[[], object]) -> None:
    """``load()`` is called once a hook is asked for and none is registered: it imports
    the layer that registers them (``strew``'s ``__init__`` passes the import of
    :mod:`strew.io`)."""
    global _provider
    _provider = load


def hook(name: str) -> Callable[..., Any]:
    """The function registered for ``name``, asking the provider first if there is none."""
    func = _registered.get(name)
    if func is None and _provider is not None:
        _provider()
        func = _registered.get(name)
    if func is None:
        raise RuntimeError(f"no {name!r} writer is registered: import strew.io first")
    return func
