"""Helper gh0: a grow audit with the lone-larger orphan gate's blocked swaps printed.

Runs ``benchmarks/grow_variants.py`` (or the benchmark script named first) with its arguments; each swap the gate
(``strew.grow._lone_larger._orphans``) skips prints ``BLOCK`` before its row's line, so
rows with no BLOCK line grew exactly as without the gate (the gate draws nothing from
the rng).

    PYTHONPATH=src python benchmarks/gh0_audit_blocks.py --harder --harder-variants 13,14 \
        --only three_sizes,two_sizes,clusters --seeds 1 --json benchmarks/results/gh0_h1314.json
    PYTHONPATH=src python benchmarks/gh0_audit_blocks.py fidelity.py --method grow --only three_sizes --seeds 1-5
"""
import os
import runpy
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import strew.grow._lone_larger as L

_orig = L._orphans


def _count(g, o):
    out = _orig(g, o)
    if out:
        print("BLOCK", flush=True)
    return out


L._orphans = _count
here = os.path.dirname(os.path.abspath(__file__))
args = sys.argv[1:]
script = args.pop(0) if args and args[0].endswith(".py") else "grow_variants.py"
sys.argv = [os.path.join(here, script), *args]
runpy.run_path(sys.argv[0], run_name="__main__")
