"""s28k: run pytest with copyable's settings changed in-process (to compare the gates).

    PYTHONPATH=src python benchmarks/s28k_pytest_mode.py MODE [THIN=1|0] -- PYTEST ARGS...

MODE: largest | all | off (COPYABLE_ONLY False). THIN 0 turns _thin.THIN_CROWDED off.
"""

import sys

import pytest

import strew.synth._grow as G
import strew.synth._thin as T

i = sys.argv.index("--")
opts, args = sys.argv[1:i], sys.argv[i + 1 :]
mode = opts[0]
if mode == "off":
    G.COPYABLE_ONLY = False
else:
    G.COPYABLE_SEEDS = mode
if len(opts) > 1 and opts[1] == "0":
    T.THIN_CROWDED = False
sys.exit(pytest.main(["-p", "no:benchmark", "-q", *args]))
