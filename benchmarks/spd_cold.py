"""Cold first run of a flow growth (issue 14 point 5): the ``hexflow`` case of
``benchmarks/grow.py --against`` (relaxation on), timed in a fresh process with an empty
numba cache (``NUMBA_CACHE_DIR`` a new folder: every kernel compiles), for this tree and
for git revision ``REV``, in turns; then the same process's second growth (warm).

Run: ``python benchmarks/spd_cold.py main [turns]`` (prints CPU seconds of the first and
second growth per tree, and the ratios this/REV).
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

_CODE = r"""
import sys, time
sys.path.insert(0, sys.argv[1])
t0 = time.process_time()
from spd15_sample import case_kwargs
from strew.grow import analyze, grow
from strew.grow._exemplars import hex_exemplar
ref = analyze(hex_exemplar())
kw = case_kwargs("hexflow", ref)
t1 = time.process_time()
out = grow(ref, rng=1, relax=True, **kw)
t2 = time.process_time()
grow(ref, rng=1, relax=True, **kw)
t3 = time.process_time()
print(t1 - t0, t2 - t1, t3 - t2, len(out))
"""


def main() -> None:
    rev = sys.argv[1] if len(sys.argv) > 1 else "main"
    turns = int(sys.argv[2]) if len(sys.argv) > 2 else 1
    root = Path(__file__).resolve().parents[1]
    rows: dict[str, list] = {"this": [], "base": []}
    with tempfile.TemporaryDirectory() as tmp:
        archive = subprocess.run(["git", "archive", rev, "src"], cwd=root, capture_output=True, check=True).stdout
        subprocess.run(["tar", "-x", "-C", tmp], input=archive, check=True)
        trees = {"this": str(root / "src"), "base": str(Path(tmp) / "src")}
        for t in range(turns):
            for k, path in trees.items():
                cache = Path(tmp) / f"numba_{k}_{t}"
                cache.mkdir()
                env = dict(os.environ, PYTHONPATH=path, NUMBA_CACHE_DIR=str(cache))
                out = subprocess.run([sys.executable, "-c", _CODE, str(root / "benchmarks")], env=env, capture_output=True, text=True, check=True)
                imp, first, second, n = out.stdout.split()[-4:]
                rows[k].append({"import_cpu_s": float(imp), "first_cpu_s": float(first), "second_cpu_s": float(second), "n": int(n)})
    best = {k: {f: min(r[f] for r in v) for f in ("import_cpu_s", "first_cpu_s", "second_cpu_s")} for k, v in rows.items()}
    res = {"rev": rev, "turns": rows, "best": best,
           "ratio_first": best["this"]["first_cpu_s"] / best["base"]["first_cpu_s"],
           "ratio_second": best["this"]["second_cpu_s"] / best["base"]["second_cpu_s"]}
    print(json.dumps(res, indent=1))


if __name__ == "__main__":
    main()
