"""g34f: ``benchmarks/g28f_suite.py`` (the suite's 12 flow rows) with GrowParams fields set
(``--p NAME=V``, before g28f_suite's own arguments).

    PYTHONPATH=src python benchmarks/g34f_suite.py --p flow_fit=False -- --only 0,3 [--json F]
"""
import math
import runpy
import sys
from pathlib import Path

from strew.grow import _growth

args = sys.argv[1:]
cut = args.index("--") if "--" in args else len(args)
over = {}
it = iter(args[:cut])
for tok in it:
    if tok == "--p":
        k, v = next(it).split("=")
        over[k] = eval(v, {"inf": math.inf, "None": None, "pi": math.pi})
orig_init = _growth.GrowParams.__init__


def init(self, *a, **kw):
    orig_init(self, *a, **kw)
    for k, v in over.items():
        object.__setattr__(self, k, v)


_growth.GrowParams.__init__ = init
print("set GrowParams", over)
sys.argv = [str(Path(__file__).resolve().parent / "g28f_suite.py")] + args[cut + 1:]
runpy.run_path(sys.argv[0], run_name="__main__")
