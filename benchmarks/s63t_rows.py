"""Helper s63t: ``s60t_rows.py`` (six-seed rows, same arguments and output) with the gate's
form set from the environment: S63T_ADD=0 (``_grow.OWN_AHEAD_ADD`` off: the larger of slack
and margin, s60t's form), S63T_SPREAD=0 (``_grow.OWN_AHEAD_SPREAD`` off: Poisson's spread).

    S63T_ADD=0 PYTHONPATH=src:benchmarks python benchmarks/s63t_rows.py v25 1-6
"""
import os
import runpy
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import strew.synth._grow as G

if os.environ.get("S63T_ADD") == "0":
    G.OWN_AHEAD_ADD = False
if os.environ.get("S63T_SPREAD") == "0":
    G.OWN_AHEAD_SPREAD = False
print(f"OWN_AHEAD_ADD={G.OWN_AHEAD_ADD} OWN_AHEAD_SPREAD={G.OWN_AHEAD_SPREAD}", flush=True)
runpy.run_path(__file__.rsplit("/", 1)[0] + "/s60t_rows.py", run_name="__main__")
