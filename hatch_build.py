"""Wheel build hook: compile strew's numba kernels at build time and ship their caches.

Issue 16: on a fresh install the first command of each method compiled its numba
kernels (15-25 s of CPU for pack, synth, the studio). Numba's on-disk cache is
portable between a build and an install on the same machine:

- numba's in-tree cache locator keeps a kernel's cache in the ``__pycache__`` folder
  next to its source file (when that folder is writable), so files shipped there in
  the wheel are found after ``pip install .``;
- the index's source stamp is a hash of the source file's content (numba >= 0.64;
  ``numba.core.caching._SourceFileBackedLocatorMixin.get_source_stamp``), not its
  modification time or path, and the wheel's sources are the built ones, byte for byte;
- each entry is keyed by the signature, the CPU (target triple, CPU name and
  features: ``codegen.magic_tuple()``) and the function's bytecode; the index also
  holds numba's version. An install on another CPU or with another numba or Python
  just misses and compiles, as without the shipped files.

For the wheel target (not editable installs, not the sdist) this hook runs ``python -m
strew._warmup`` from the source tree in a subprocess with ``NUMBA_CACHE_DIR`` set to a
scratch folder, then adds the cache files it wrote to the wheel as
``strew/<package>/__pycache__/<file>`` (``force_include``; the wheel's ``exclude`` of
``__pycache__`` keeps a development checkout's own caches out). The warm-up therefore
needs strew's runtime dependencies in the build environment: :meth:`dependencies`
asks for them (with pip's build isolation they are installed into it from the same
index as the install's; they match the install's versions when both resolve the
newest, as in a fresh venv).

The warm-up never fails the build: if it fails, times out or is skipped, the wheel
ships whatever caches it wrote (maybe none) and the build prints a warning; the
kernels then compile on first use, as before.

Environment:

- ``STREW_NO_WARMUP=1``: skip the warm-up (and do not ask for the runtime dependencies
  at build time);
- ``STREW_WARMUP_TIMEOUT``: seconds the warm-up may take (default 1200).

Not covered: an install whose site-packages is read-only for the user running strew
(numba then uses its user-wide cache and compiles once), or ``NUMBA_CACHE_DIR`` set at
run time (numba then looks only there).
"""

from __future__ import annotations

import hashlib
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

try:
    from hatchling.builders.hooks.plugin.interface import BuildHookInterface
except ImportError:  # imported without hatchling (tests of cache_folders): no hook
    BuildHookInterface = object

SKIP_ENV = "STREW_NO_WARMUP"
TIMEOUT_ENV = "STREW_WARMUP_TIMEOUT"
DEFAULT_TIMEOUT_S = 1200.0


def _skipped() -> bool:
    return os.environ.get(SKIP_ENV, "").strip().lower() not in ("", "0", "false", "no")


def cache_folders(package: Path) -> dict[str, str]:
    """Map numba's ``NUMBA_CACHE_DIR`` subfolder name of each folder of ``package``
    (``<folder name>_<sha1 of its absolute path>``, numba's
    ``_CacheLocator.get_suitable_cache_subpath``) to that folder's path relative to the
    package's parent (its place in the wheel)."""
    out = {}
    for d in [package, *sorted(p for p in package.rglob("*") if p.is_dir())]:
        if d.name == "__pycache__":
            continue
        path = os.path.abspath(d)
        out[f"{d.name}_{hashlib.sha1(path.encode()).hexdigest()}"] = d.relative_to(package.parent).as_posix()
    return out


class KernelCacheHook(BuildHookInterface):
    """Run strew's warm-up and ship the numba caches it writes (see the module's doc)."""

    PLUGIN_NAME = "custom"

    def dependencies(self) -> list[str]:
        if _skipped():
            return []
        # the warm-up imports strew and runs every method: its runtime dependencies
        return list(self.metadata.core.dependencies)

    def initialize(self, version: str, build_data: dict) -> None:
        self._scratch = None
        if self.target_name != "wheel" or version == "editable":
            return
        if _skipped():
            self.app.display_info(f"strew: {SKIP_ENV} is set: no compiled kernels shipped")
            return
        src = Path(self.root).resolve() / "src"
        self._scratch = tempfile.mkdtemp(prefix="strew-kernels-")
        env = dict(os.environ, NUMBA_CACHE_DIR=self._scratch)
        env.pop("NUMBA_DISABLE_JIT", None)
        # keep the build environment's path (pip's isolation lives there), source first
        env["PYTHONPATH"] = os.pathsep.join(p for p in (str(src), os.environ.get("PYTHONPATH", "")) if p)
        try:
            timeout = float(os.environ.get(TIMEOUT_ENV, DEFAULT_TIMEOUT_S))
        except ValueError:
            timeout = DEFAULT_TIMEOUT_S
        self.app.display_info("strew: compiling numba kernels to ship in the wheel (python -m strew._warmup)")
        problem = None
        try:
            run = subprocess.run(
                [sys.executable, "-m", "strew._warmup"],
                env=env, cwd=self._scratch, capture_output=True, text=True, timeout=timeout,
            )
            for line in run.stdout.splitlines():
                self.app.display_info(f"  {line}")
            if run.returncode != 0:
                problem = f"the warm-up exited with status {run.returncode}: {run.stderr.strip()[-1500:]}"
        except subprocess.TimeoutExpired:
            problem = f"the warm-up took over {timeout:.0f} s ({TIMEOUT_ENV}) and was stopped"
        except OSError as e:
            problem = f"the warm-up could not start: {e}"
        folders = cache_folders(src / "strew")
        shipped, unknown = 0, []
        for sub in sorted(Path(self._scratch).iterdir()):
            if not sub.is_dir():
                continue
            rel = folders.get(sub.name)
            if rel is None:  # a kernel outside strew's source (none today)
                unknown.append(sub.name)
                continue
            for f in sorted(sub.iterdir()):
                if f.suffix in (".nbi", ".nbc"):
                    build_data["force_include"][str(f)] = f"{rel}/__pycache__/{f.name}"
                    shipped += 1
        if unknown:
            self.app.display_warning(f"strew: cache folders of no strew package left out: {', '.join(unknown)}")
        if problem:
            self.app.display_warning(
                f"strew: {problem}; the wheel ships {shipped} kernel cache files, and the "
                "kernels missing from them compile on first use"
            )
        else:
            self.app.display_info(f"strew: {shipped} kernel cache files shipped")

    def finalize(self, version: str, build_data: dict, artifact_path: str) -> None:
        if getattr(self, "_scratch", None):
            shutil.rmtree(self._scratch, ignore_errors=True)
            self._scratch = None
