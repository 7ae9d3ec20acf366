"""Helper s26h: run a benchmark script with ``_grow.OWN_SMALLEST_CLASSES = 0`` (the baseline, integ26's behaviour).

    PYTHONPATH=TREE/src:benchmarks python benchmarks/s26h_off.py benchmarks/synth_variants.py ARGS...
"""
import runpy
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import strew.synth._grow as G

G.OWN_SMALLEST_CLASSES = 0
sys.argv = sys.argv[1:]
runpy.run_path(sys.argv[0], run_name="__main__")
