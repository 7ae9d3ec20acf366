"""Helper s69h: run pytest (one process) with the prototype ``_grow._TWO_CLASS_AREA`` on.

    PYTHONPATH=src:benchmarks python benchmarks/s69h_pytest_on.py tests/synth -k "..."
"""
import sys

import pytest

import strew.synth._grow as G

G._TWO_CLASS_AREA = True
CALLS = {"n": 0, "decided": 0}
_owed = G._owed_by_area


def _counted(state):
    got = _owed(state)
    CALLS["n"] += 1
    CALLS["decided"] += got is not None
    return got


G._owed_by_area = _counted
rc = pytest.main(["-p", "no:benchmark", "-p", "no:xdist", "-q", *sys.argv[1:]])
print(f"_owed_by_area calls {CALLS['n']}, decided by area {CALLS['decided']}")
sys.exit(rc)
