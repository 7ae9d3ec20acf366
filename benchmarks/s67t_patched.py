"""Helper s67t: run a benchmark script (runpy) with ``_grow._larger_short`` patched (src untouched):
``noshort`` -> always False (fill_room gives the smallest class ROOM_SHARE_SMALLEST even while a larger
kind is short), ``main`` -> unchanged. Each time main's ``_larger_short`` would hold, a line
``[s67t larger_short]`` is printed (before the run's own line), so rows it never acts on are known to be
byte-identical to main.

    PYTHONPATH=src:benchmarks python benchmarks/s67t_patched.py noshort benchmarks/synth_variants.py --varied-variants 30 --variants '' --only three_sizes --seeds 1
"""
import runpy
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import strew.synth._grow as G

MODE = sys.argv[1]
_short = G._larger_short


def larger_short(state):
    r = _short(state)
    if r:
        print("[s67t larger_short]", flush=True)
    return False if MODE == "noshort" else r


G._larger_short = larger_short
sys.argv = sys.argv[2:]
runpy.run_path(sys.argv[0], run_name="__main__")
