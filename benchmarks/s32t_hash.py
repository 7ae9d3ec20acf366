"""Helper s32t: sha256 of synth's output on fidelity-suite classes (as
``benchmarks/synth_speed.py`` fills them: 3.5x the frame's side, rng 1), so two trees'
outputs can be compared byte for byte.

    PYTHONPATH=src python benchmarks/s32t_hash.py sticks,scales,rows_noisy [SCALE]

Prints per class the element count and the hash of the output's positions and exemplar
sources, and of its arrangement's xy, rotations, scales and kinds (float64 / int64 bytes) and the CPU seconds.
"""
import hashlib
import importlib.util
import sys
import time
from pathlib import Path

import numpy as np

from strew import Region
from strew.synth import fill, new_state

ROOT = Path(__file__).resolve().parents[1]
spec = importlib.util.spec_from_file_location("mk", ROOT / "examples/fidelity/make.py")
mk = importlib.util.module_from_spec(spec)
spec.loader.exec_module(mk)
scale = float(sys.argv[2]) if len(sys.argv) > 2 else 3.5
for name in sys.argv[1].split(","):
    ex = mk.make_exemplar(name)
    x0, y0, x1, y1 = ex.region.bounds
    t = time.process_time()
    st = new_state(ex, Region.rectangle(scale * (x1 - x0), scale * (y1 - y0)), rng=1)
    fill(st)
    arr = st.to_arrangement()
    h = hashlib.sha256()
    h.update(np.ascontiguousarray(st.pos[: st.n], np.float64).tobytes())
    h.update(np.ascontiguousarray(st.src[: st.n], np.int64).tobytes())
    for v in (arr.xy, arr.rotation, arr.scale):
        h.update(np.ascontiguousarray(v, np.float64).tobytes())
    h.update(np.ascontiguousarray(arr.kind, np.int64).tobytes())
    print(f"{name:12s} n={st.n} out={len(arr)} sha256={h.hexdigest()[:16]} cpu_s={time.process_time() - t:.2f}", flush=True)
