"""Helper s71t: run a benchmark script with _displace's LARGEST_WHOLE_* constants set.

    PYTHONPATH=src:benchmarks python benchmarks/s71t_run.py SCALE MAJORITY script.py args...
SCALE: 'none' or a number; MAJORITY: 0/1; 'off' as SCALE turns LARGEST_WHOLE off."""
import runpy
import sys

import strew.synth._displace as DP

sc, maj = sys.argv[1], sys.argv[2]
if sc == "off":
    DP.LARGEST_WHOLE = False
else:
    DP.LARGEST_WHOLE_SCALE = None if sc == "none" else float(sc)
DP.LARGEST_WHOLE_MAJORITY = bool(int(maj))
sys.argv = sys.argv[3:]
runpy.run_path(sys.argv[0], run_name="__main__")
