"""g44v: the first run on an empty numba cache and the cost growth over a 10x range of
counts, of this tree and of git revision REV, in fresh processes taken in turn.

``first``: ``stones 2000 relax on``, seed 1, with ``NUMBA_CACHE_DIR`` a new empty folder
(every kernel compiled): the growth's CPU seconds and the whole process's.
``growth``: stones grown to 1,000 and 10,000 elements with relaxation (warm cache, after
a growth of 50), CPU seconds per 1,000 elements at each count and their ratio (1.0: linear).

Run: ``PYTHONPATH=src python benchmarks/g44v_speed.py main [--skip-first]``.
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
from pathlib import Path

CODE = r"""
import sys, time
from strew.grow import analyze, grow
from strew.grow._exemplars import stone_exemplar
ref = analyze(stone_exemplar())
n = int(sys.argv[1])
if sys.argv[2] == "warm":
    grow(ref, count=50, rng=1)
c = time.process_time()
out = grow(ref, count=n, rng=1, relax=True)
print(time.process_time() - c, time.process_time(), len(out))
"""


def run(src: str, n: int, how: str, cache: str | None = None) -> tuple[float, float, int]:
    env = dict(os.environ, PYTHONPATH=src)
    if cache is not None:
        env["NUMBA_CACHE_DIR"] = cache
    out = subprocess.run([sys.executable, "-c", CODE, str(n), how], env=env, capture_output=True, text=True, check=True)
    g, p, m = out.stdout.split()[-3:]
    return float(g), float(p), int(m)


def main() -> None:
    rev = sys.argv[1] if len(sys.argv) > 1 else "main"
    root = Path(__file__).resolve().parents[1]
    with tempfile.TemporaryDirectory() as tmp:
        archive = subprocess.run(["git", "archive", rev, "src"], cwd=root, capture_output=True, check=True).stdout
        subprocess.run(["tar", "-x", "-C", tmp], input=archive, check=True)
        trees = {"this": str(root / "src"), rev: str(Path(tmp) / "src")}
        if "--skip-first" not in sys.argv:
            print("# first run, empty numba cache: stones 2000 relax on, seed 1")
            for name, src in trees.items():
                with tempfile.TemporaryDirectory() as cache:
                    g, p, m = run(src, 2000, "cold", cache)
                print(f"{name:6s} n={m} grow CPU {g:.2f} s, process CPU {p:.2f} s")
        print("# cost growth, warm cache: stones relax on, CPU s per 1,000 elements (best of 2)")
        rows = {}
        for n in (1000, 10000):
            for name, src in trees.items():
                best = min(run(src, n, "warm")[0] for _ in range(2))
                rows[(name, n)] = best / n * 1000
        for name in trees:
            a, b = rows[(name, 1000)], rows[(name, 10000)]
            print(f"{name:6s} 1,000: {a:.3f}  10,000: {b:.3f}  ratio {b / a:.2f}")
        for n in (1000, 10000):
            print(f"cpu ratio this/{rev} at {n}: {rows[('this', n)] / rows[(rev, n)]:.3f}")


if __name__ == "__main__":
    main()
