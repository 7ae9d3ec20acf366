"""Issue 16: numba caches compiled at build time and shipped in the wheel are hits after
an install, and the CLI's look at the cache (``strew._kernel_cache``) agrees with numba.

``hatch_build.py`` runs the warm-up with ``NUMBA_CACHE_DIR`` set and ships the files in
``strew/<package>/__pycache__``. These tests check the two facts that rest on, with
numba as installed: the cache's subfolder names map back to the package's folders
(``hatch_build.cache_folders``), and an index moved next to a copy of its source, with a
new modification time (pip writes every file anew), is still a hit for numba's in-tree
locator, while a change to the source's content is a miss.
"""

from __future__ import annotations

import hashlib
import importlib.util
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]

KERNEL = "import numba\n\n\n@numba.njit(cache=True)\ndef plus(x):\n    return x + 1\n"
DRIVER = (
    "import json, sys\n"
    "sys.path.insert(0, sys.argv[1])\n"
    "from kpkg.mod import plus\n"
    "assert plus(1) == 2\n"
    "s = plus.stats\n"
    "print(json.dumps([sum(s.cache_hits.values()), sum(s.cache_misses.values())]))\n"
)


def _hook_module():
    spec = importlib.util.spec_from_file_location("strew_hatch_build", ROOT / "hatch_build.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def _hits_misses(path: Path, env: dict) -> list[int]:
    run = subprocess.run([sys.executable, "-c", DRIVER, str(path)], env=env, capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    return json.loads(run.stdout.strip().splitlines()[-1])


@pytest.mark.slow  # three processes importing numba: about 6 s of CPU
@pytest.mark.skipif(not (ROOT / "hatch_build.py").exists(), reason="needs the source tree's hatch_build.py")
def test_caches_compiled_with_numba_cache_dir_hit_when_shipped_in_pycache(tmp_path):
    build = tmp_path / "build"
    (build / "kpkg").mkdir(parents=True)
    (build / "kpkg" / "__init__.py").write_text("")
    (build / "kpkg" / "mod.py").write_text(KERNEL)
    base = {k: v for k, v in os.environ.items() if not k.startswith("NUMBA_")}
    base["XDG_CACHE_HOME"] = str(tmp_path / "user-cache")  # numba's user-wide fallback, empty

    # the build: compile into NUMBA_CACHE_DIR
    cache = tmp_path / "numba-cache"
    assert _hits_misses(build, dict(base, NUMBA_CACHE_DIR=str(cache))) == [0, 1]

    # the wheel: the hook's map from cache subfolders to package folders covers them all
    folders = _hook_module().cache_folders(build / "kpkg")
    subs = [d.name for d in cache.iterdir()]
    assert subs and all(s in folders for s in subs)

    # the install: the sources copied elsewhere, written anew, the caches in __pycache__
    site = tmp_path / "site"
    shutil.copytree(build / "kpkg", site / "kpkg", ignore=shutil.ignore_patterns("__pycache__"))
    for s in subs:
        dest = site / folders[s] / "__pycache__"
        dest.mkdir(parents=True, exist_ok=True)
        for f in (cache / s).iterdir():
            shutil.copy(f, dest / f.name)
    later = (site / "kpkg" / "mod.py").stat().st_mtime + 100
    os.utime(site / "kpkg" / "mod.py", (later, later))
    assert _hits_misses(site, base) == [1, 0]

    # numba's stamp is the content: an edited source misses (and compiles)
    with open(site / "kpkg" / "mod.py", "a") as f:
        f.write("# edited\n")
    assert _hits_misses(site, base) == [0, 1]


def test_kernel_cache_look_reads_numba_content_stamp(tmp_path, monkeypatch):
    # point 3's look at the cache: an index counts when it carries the SHA-256 of the
    # kernel module's current source (numba's stamp), whatever its modification time
    import strew._kernel_cache as kc

    monkeypatch.setenv("NUMBA_CACHE_DIR", str(tmp_path))
    src = kc._ROOT / "grow" / "_match.py"
    assert b"njit" in src.read_bytes()
    (folder,) = kc._cache_dirs(src)
    folder.mkdir(parents=True)
    index = folder / f"{src.stem}.kernel-1.py311.nbi"
    index.write_bytes(b"\x80\x04version" + hashlib.sha256(src.read_bytes() + b"#").digest())
    assert not kc.kernels_cached("grow")  # a stamp of other content: stale
    index.write_bytes(b"\x80\x04version" + hashlib.sha256(src.read_bytes()).digest())
    os.utime(index, (1.0, 1.0))  # older than the source: still fresh
    assert kc.kernels_cached("grow")
    assert not kc.kernels_cached("pack")  # nothing for pack's modules
