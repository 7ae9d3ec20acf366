"""Helper gh0: ``grw14y_rows.py`` with one module constant of ``strew.grow._growth`` set.

    PYTHONPATH=src python benchmarks/gh0_rows_off.py GAP_SMALLEST_SEVERAL=0 three_sizes:5:14 1-3
"""
import os
import runpy
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import strew.grow._growth as G

name, _, val = sys.argv.pop(1).partition("=")
setattr(G, name, type(getattr(G, name))(int(val)) if isinstance(getattr(G, name), bool) else float(val))
sys.argv[0] = os.path.join(os.path.dirname(os.path.abspath(__file__)), "grw14y_rows.py")
runpy.run_path(sys.argv[0], run_name="__main__")
