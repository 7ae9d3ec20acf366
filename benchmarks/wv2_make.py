"""benchmarks/hie15_make.py with the vase's ``tile_keeps_first_phase`` switched off (helper
wv2, issue 19.4): the base worlds of the same tree, whose code paths are then those
before the flag (strew.tiles._keeps_first_phase returns None).

``PYTHONPATH=src python benchmarks/wv2_make.py --tag wv2base --tiles 48 --seeds 1 --pattern vase``
(the arguments are hie15_make.py's)
"""

from __future__ import annotations

import runpy
import sys
from pathlib import Path

if __name__ == "__main__":
    from strew.ornament.patterns import vase

    vase.pattern.tile_keeps_first_phase = False
    sys.argv[0] = str(Path(__file__).with_name("hie15_make.py"))
    runpy.run_path(sys.argv[0], run_name="__main__")
