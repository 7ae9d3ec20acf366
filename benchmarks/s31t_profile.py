"""Helper s31t: cProfile of synth's fill on one fidelity-suite class at 3.5x its frame
(as ``benchmarks/synth_speed.py`` times it), printing the top functions by cumulative time.

    PYTHONPATH=src python benchmarks/s31t_profile.py CLASS [N_TOP]
"""
import cProfile
import importlib.util
import pstats
import sys
import time
from pathlib import Path

from strew import Region
from strew.synth import fill, new_state

ROOT = Path(__file__).resolve().parents[1]
spec = importlib.util.spec_from_file_location("mk", ROOT / "examples/fidelity/make.py")
mk = importlib.util.module_from_spec(spec)
spec.loader.exec_module(mk)
ex = mk.make_exemplar(sys.argv[1])
x0, y0, x1, y1 = ex.region.bounds
region = Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0))
fill(new_state(ex, region, rng=0))  # compile
t = time.process_time()
st = new_state(ex, region, rng=1)
pr = cProfile.Profile()
pr.enable()
fill(st)
pr.disable()
print(f"n={st.n} cpu_s={time.process_time() - t:.2f}")
pstats.Stats(pr).sort_stats("cumulative").print_stats(int(sys.argv[2]) if len(sys.argv) > 2 else 30)
