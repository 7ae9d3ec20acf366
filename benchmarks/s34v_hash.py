"""Helper s34v: sha256 of synth's output (``new_state`` + ``fill``, horizon optimisation)
on every fidelity-suite class at 3.5x its frame's side and on the four
``strew.synth._exemplars`` at ``benchmarks/synth_speed.py``'s quick sizes, at several
seeds, so that two trees' outputs can be compared byte for byte (as ``s32t_hash.py``,
with seeds and the quick exemplars).

    PYTHONPATH=TREE/src python benchmarks/s34v_hash.py [--seeds 1,2] [--only grid,suite:bricks]

Prints one line per (case, seed): element count and the hash of the state's positions
and sources and of its arrangement's xy, rotations, scales and kinds (float64 / int64).
"""
import argparse
import hashlib
import importlib.util
import sys
from pathlib import Path

import numpy as np

from strew import Region
from strew.synth import fill, new_state
from strew.synth._exemplars import EXEMPLARS

ROOT = Path(__file__).resolve().parents[1]
QUICK = {"rings": (300, 260), "grid": (400, 400), "stripes": (320, 320), "apples": (300, 300)}
spec = importlib.util.spec_from_file_location("mk", ROOT / "examples/fidelity/make.py")
mk = importlib.util.module_from_spec(spec)
spec.loader.exec_module(mk)

ap = argparse.ArgumentParser()
ap.add_argument("--seeds", default="1,2")
ap.add_argument("--only", default=None)
args = ap.parse_args()
cases = args.only.split(",") if args.only else list(QUICK) + [f"suite:{n}" for n in mk.NAMES]
for case in cases:
    if case.startswith("suite:"):
        ex = mk.make_exemplar(case[6:])
        x0, y0, x1, y1 = ex.region.bounds
        region = Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0))
    else:
        ex = EXEMPLARS[case]()
        region = Region.rectangle(*QUICK[case])
    for seed in (int(s) for s in args.seeds.split(",")):
        st = new_state(ex, region, rng=seed)
        fill(st)
        arr = st.to_arrangement()
        h = hashlib.sha256()
        h.update(np.ascontiguousarray(st.pos[: st.n], np.float64).tobytes())
        h.update(np.ascontiguousarray(st.src[: st.n], np.int64).tobytes())
        for v in (arr.xy, arr.rotation, arr.scale):
            h.update(np.ascontiguousarray(v, np.float64).tobytes())
        h.update(np.ascontiguousarray(arr.kind, np.int64).tobytes())
        print(f"{case:20s} seed={seed} n={st.n} out={len(arr)} sha256={h.hexdigest()[:16]}", flush=True)
