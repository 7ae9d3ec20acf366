"""Helper s37h: syn13z_rows.py with synth module constants set first.

    PYTHONPATH=src:benchmarks python benchmarks/s37h_rows.py [MOD.NAME=VALUE ...] CLASS:H:V:SEEDS[:A:B] ...

MOD is a module of strew.synth without its underscore (farmix, displace, ...).
"""
import importlib
import runpy
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
args = []
for a in sys.argv[1:]:
    if "=" in a and "." in a.split("=")[0]:
        k, v = a.split("=", 1)
        mod, name = k.split(".")
        setattr(importlib.import_module(f"strew.synth._{mod}"), name, eval(v))
        print("set", k, v, flush=True)
    else:
        args.append(a)
sys.argv = [sys.argv[0]] + args
runpy.run_path(__file__.rsplit("/", 1)[0] + "/syn13z_rows.py", run_name="__main__")
