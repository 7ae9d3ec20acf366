"""Helper s36m: syn13z_rows.py with _prepare.PARENTLESS_CUT off when the first argument is "off"
(apply benchmarks/results/s36m_rejected_parentless.patch first; without it "off" changes nothing).

    PYTHONPATH=src:benchmarks python benchmarks/s36m_rows.py on|off CLASS:H:V:SEEDS[:A:B] ...
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import strew.synth._prepare as P

P.PARENTLESS_CUT = sys.argv[1] != "off"
del sys.argv[1]
import runpy

runpy.run_path(__file__.rsplit("/", 1)[0] + "/syn13z_rows.py", run_name="__main__")
