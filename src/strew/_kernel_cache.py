"""Whether numba's on-disk cache already holds a method's kernels, without importing numba.

On a fresh install the first command of each method compiles its numba kernels (issue
16); the CLI says so once on stderr. This is a cheap look at the files numba's cache
would use (the index ``<module>.<kernel>-<line>.py311.nbi`` of each kernel module, in
``$NUMBA_CACHE_DIR``, next to the source in ``__pycache__``, or in the user-wide cache),
so that ``strew --help`` and warm runs pay nothing for it. An index counts when it holds
numba's source stamp of the module as it is now: numba (>= 0.64) stamps an index with
the SHA-256 of the source file's content, so the digest's 32 bytes appear in the index's
pickle (a modification time would not do: a wheel built by ``hatch_build.py`` ships
indexes in ``__pycache__`` that pip writes in no particular order with the sources).
It is a heuristic: the signatures, CPU and numba version in the index are not read.
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


def _stamped(index: Path, stamp: bytes) -> bool:
    """Whether numba's cache index ``index`` was written for the source whose SHA-256
    digest is ``stamp`` (the index pickles ``(stamp, overloads)`` after numba's version)."""
    try:
        return stamp in index.read_bytes()
    except OSError:
        return False


def kernels_cached(method: str) -> bool:
    """True when each subpackage that ``method`` compiles kernels in has a cache index
    stamped with the current source of at least one of its kernel modules (one command of a
    method need not call every kernel; unknown methods: True, nothing to say)."""
    pkgs = _METHODS.get(method, _METHODS.get(method.split(" ")[0], ()))
    for pkg in pkgs:
        found = False
        for src in sorted((_ROOT / pkg).glob("*.py")):
            try:
                source = src.read_bytes()
            except OSError:
                continue
            if b"njit" not in source:
                continue
            stamp = hashlib.sha256(source).digest()  # numba's _hash_source_file
            for d in _cache_dirs(src):
                found = any(_stamped(f, stamp) for f in d.glob(f"{src.stem}.*.nbi"))
                if found:
                    break
            if found:
                break
        if not found:
            return False
    return True
