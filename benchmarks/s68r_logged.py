"""Helper s68r: run a benchmark script (runpy) with ``_grow._larger_short`` logged, unchanged: each
time it holds, a line ``[s68r larger_short]`` is printed (before the run's own line). A run without
the line is byte-identical between integ38's src and s68r's (fill_room's second pass runs only
where the gate holds). Works on either tree (PYTHONPATH picks the src).

    PYTHONPATH=src:benchmarks python benchmarks/s68r_logged.py benchmarks/syn13z_rows.py three_sizes:2:25:1,2,3
"""
import runpy
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import strew.synth._grow as G

_short = G._larger_short


def larger_short(state):
    r = _short(state)
    if r:
        print("[s68r larger_short]", flush=True)
    return r


G._larger_short = larger_short
sys.argv = sys.argv[1:]
runpy.run_path(sys.argv[0], run_name="__main__")
