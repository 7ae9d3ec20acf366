"""Helper sm: benchmarks/synth_variants.py with constants of strew.synth._grow set first
(``--gset NAME=VALUE``, repeatable), to audit a setting before it becomes a default.

    PYTHONPATH=src:benchmarks python benchmarks/sm_variants.py --gset MIDDLE_RARE=99 --harder-variants 13,14 --only three_sizes --seeds 1 --json OUT.json
"""
import runpy
import sys

import strew.synth._grow as G

argv = [sys.argv[0]]
it = iter(sys.argv[1:])
for a in it:
    if a == "--gset":
        name, val = next(it).split("=", 1)
        if not hasattr(G, name):
            raise SystemExit(f"--gset: strew.synth._grow has no {name}")
        setattr(G, name, eval(val))
        print("set", name, val, file=sys.stderr)
    else:
        argv.append(a)
sys.argv = [__file__.rsplit("/", 1)[0] + "/synth_variants.py"] + argv[1:]
runpy.run_path(sys.argv[0], run_name="__main__")
