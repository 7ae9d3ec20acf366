"""Helper s69h: run a probe script with the prototype ``_grow._TWO_CLASS_AREA`` on.

    PYTHONPATH=src:benchmarks python benchmarks/s69h_on.py [SE=k] SCRIPT ARGS...
"""
import runpy
import sys

import strew.synth._grow as G

G._TWO_CLASS_AREA = True
args = sys.argv[1:]
if args and args[0].startswith("SE="):
    G._TWO_CLASS_AREA_SE = float(args.pop(0)[3:])
sys.argv = args
runpy.run_path(args[0], run_name="__main__")
