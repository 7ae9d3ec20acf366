"""Run a benchmark with synth's tile-only balance switch (``_grow.BALANCE_TILE``) set to
one of its modes (helper bal19i, issue 19 point 4): ``cut``, ``count``, ``edge`` or
``off`` (``""``: the rule as outside tiles, the code before the switch).

``python benchmarks/bal19i_variant.py MODE SCRIPT -- <the script's arguments>``, SCRIPT a
file of benchmarks/ (worlds_strips.py, ...), e.g. ``python benchmarks/bal19i_variant.py
count worlds_strips.py -- --methods synth --synth-exemplar three_sizes --widths 3,2,1
--seeds 1,2,3,4,5,6,7,8 --no-control --no-fidelity --out F``.
"""

import runpy
import sys
from pathlib import Path

import strew.synth._grow as G

mode, script = sys.argv[1:3]
G.BALANCE_TILE = "" if mode == "off" else mode
print(f"BALANCE_TILE = {G.BALANCE_TILE!r}", flush=True)
sys.argv = [script] + sys.argv[4:]
runpy.run_path(str(Path(__file__).resolve().parent / script), run_name="__main__")
