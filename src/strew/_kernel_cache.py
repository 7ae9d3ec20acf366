"""Whether numba's on-disk cache already holds a method's kernels, without importing numba.

On a fresh install the first command of each method compiles its numba kernels (issue
16); the CLI says so once on stderr. This is a cheap look at the files numba's cache
would use (the index ``<module>.<kernel>-<line>.py311.nbi`` of each kernel module, in
``$NUMBA_CACHE_DIR``, next to the source in ``__pycache__``, or in the user-wide cache),
so that ``strew --help`` and warm runs pay nothing for it. It is a heuristic: an index
newer than its source counts as cached.
"""

from __future__ import annotations

import hashlib
import os
from pathlib import Path

__all__ = ["kernels_cached"]

_ROOT = Path(__file__).resolve().parent
# method (the CLI's progress description, or its first word) -> subpackages with kernels
_METHODS = {
    "pack (naive)": (),  # dart throwing compiles no kernel
    "pack": ("pack",),
    "synth": ("synth",),
    "grow": ("grow",),
    "ornament": ("ornament",),
    "program": ("pack",),  # strew run: the Poisson-disk sampling of program's partitions
    "gallery": ("pack", "synth", "grow", "ornament"),
}


def _cache_dirs(src: Path) -> list[Path]:
    """Where numba's cache locators look for the kernels of source file ``src``."""
    folder = str(src.parent)
    sub = f"{src.parent.name}_{hashlib.sha1(folder.encode()).hexdigest()}"
    if os.environ.get("NUMBA_CACHE_DIR"):
        return [Path(os.environ["NUMBA_CACHE_DIR"]) / sub]  # numba then looks nowhere else
    xdg = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return [src.parent / "__pycache__", Path(xdg) / "numba" / sub]


def kernels_cached(method: str) -> bool:
    """True when each subpackage that ``method`` compiles kernels in has a cache index
    newer than the source for at least one of its kernel modules (one command of a
    method need not call every kernel; unknown methods: True, nothing to say)."""
    pkgs = _METHODS.get(method, _METHODS.get(method.split(" ")[0], ()))
    for pkg in pkgs:
        found = False
        for src in sorted((_ROOT / pkg).glob("*.py")):
            try:
                if "njit" not in src.read_text(encoding="utf-8"):
                    continue
                stamp = src.stat().st_mtime
            except OSError:
                continue
            for d in _cache_dirs(src):
                try:
                    found = any(f.stat().st_mtime >= stamp for f in d.glob(f"{src.stem}.*.nbi"))
                except OSError:
                    found = False
                if found:
                    break
            if found:
                break
        if not found:
            return False
    return True
