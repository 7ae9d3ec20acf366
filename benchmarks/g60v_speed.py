"""g60v: hexflow (the hexagonal lattice grown in flow mode along a field turning 90
degrees, relaxation on, with the passes after the growth: ``benchmarks/grow.py
--against``'s ``hexflow``) on a first run with an empty numba cache, and its cost growth
over a 10x range of element counts, of this tree and of git revision REV, in fresh
processes taken in turn.

``first``: the region 30 x 20 spacings (651 elements), ``NUMBA_CACHE_DIR`` a new empty
folder (every kernel compiled): the growth's CPU seconds and the whole process's.
``growth``: regions W x 2W/3 spacings, W = 20 and 63 (281 and about 2,800 elements),
warm cache (after a flow growth 8 x 6 spacings; before 00:50 on stop 60 it was a
(fixed-mode) growth of 50, which left a tree extracted afresh compiling flow mode's kernels in
the first timed growth), CPU seconds per 1,000 elements at each and their
ratio (1.0: linear).

Run: ``PYTHONPATH=src python benchmarks/g60v_speed.py main [--repeat N] [--skip-first]``.
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
from pathlib import Path

CODE = r"""
import sys, time
import numpy as np
from strew import Region
from strew.grow import analyze, grow
from strew.grow._exemplars import hex_exemplar
ref = analyze(hex_exemplar())
W = float(sys.argv[1])
sp = ref.mean_edge
def field_of(w):
    def field(p):
        a = np.radians(90.0) * np.clip(np.asarray(p)[:, 0] / w, 0, 1)
        return np.c_[np.cos(a), np.sin(a)]
    return field
if sys.argv[2] == "warm":
    # (flow mode's kernels compiled or loaded outside the timing: a small flow growth)
    grow(ref, rng=1, relax=True, region=Region.rectangle(8 * sp, 6 * sp), mode="flow", flow=field_of(8 * sp))
w = W * sp
field = field_of(w)
c = time.process_time()
out = grow(ref, rng=1, relax=True, region=Region.rectangle(w, W * 2 / 3 * sp), mode="flow", flow=field)
print(time.process_time() - c, time.process_time(), len(out))
"""


def run(src: str, W: float, how: str, cache: str | None = None) -> tuple[float, float, int]:
    env = dict(os.environ, PYTHONPATH=src)
    if cache is not None:
        env["NUMBA_CACHE_DIR"] = cache
    out = subprocess.run([sys.executable, "-c", CODE, str(W), how], env=env, capture_output=True, text=True, check=True)
    g, p, m = out.stdout.split()[-3:]
    return float(g), float(p), int(m)


def main() -> None:
    rev = sys.argv[1] if len(sys.argv) > 1 and not sys.argv[1].startswith("-") else "main"
    repeat = int(sys.argv[sys.argv.index("--repeat") + 1]) if "--repeat" in sys.argv else 1
    root = Path(__file__).resolve().parents[1]
    with tempfile.TemporaryDirectory() as tmp:
        archive = subprocess.run(["git", "archive", rev, "src"], cwd=root, capture_output=True, check=True).stdout
        subprocess.run(["tar", "-x", "-C", tmp], input=archive, check=True)
        trees = {"this": str(root / "src"), rev: str(Path(tmp) / "src")}
        if "--skip-first" not in sys.argv:
            first: dict[str, list] = {k: [] for k in trees}
            for _ in range(repeat):
                for k, src in trees.items():
                    with tempfile.TemporaryDirectory() as cache:
                        first[k].append(run(src, 30, "cold", cache))
            for k, rows in first.items():
                g = min(r[0] for r in rows)
                p = min(r[1] for r in rows)
                print(f"first run (empty numba cache) hexflow 30 {k}: growth {g:.2f} CPU s ({rows[0][2] / g:.0f} el/CPU-s), process {p:.2f} CPU s; all {[(round(r[0], 2), round(r[1], 2)) for r in rows]}", flush=True)
        per: dict[str, dict[float, tuple[float, int]]] = {k: {} for k in trees}
        for W in (20.0, 63.0):
            got: dict[str, list] = {k: [] for k in trees}
            for _ in range(repeat):
                for k, src in trees.items():
                    got[k].append(run(src, W, "warm"))
            for k in trees:
                g = min(r[0] for r in got[k])
                m = got[k][0][2]
                per[k][W] = (1000.0 * g / m, m)
                print(f"warm hexflow {W:g} {k}: {m} elements, {g:.2f} CPU s, {m / g:.0f} el/CPU-s, {1000.0 * g / m:.3f} CPU s per 1,000; all {[round(r[0], 2) for r in got[k]]}", flush=True)
        for k in trees:
            a, b = per[k][20.0], per[k][63.0]
            print(f"cost growth {k}: per 1,000 elements {a[0]:.3f} ({a[1]}) -> {b[0]:.3f} ({b[1]}), x{b[0] / a[0]:.2f} over x{b[1] / a[1]:.1f} elements")
        t, m = per["this"], per[rev]
        print(f"ratio this/{rev}: {t[20.0][0] / m[20.0][0]:.3f} at W=20, {t[63.0][0] / m[63.0][0]:.3f} at W=63")


if __name__ == "__main__":
    main()
