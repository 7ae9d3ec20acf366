"""Helper g31r: ``fresh17_rows.py`` with module constants set first (a screen, not a change).

    PYTHONPATH=src python benchmarks/g31r_rows.py [--set grow._growth.GAP_THIN=0] METHOD CLASS:LABEL 1-3
"""
import importlib
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))


def main():
    argv = sys.argv[1:]
    while argv and argv[0] == "--set":
        name, val = argv[1].split("=")
        mod, attr = name.rsplit(".", 1)
        m = importlib.import_module("strew." + mod)
        setattr(m, attr, type(getattr(m, attr))(eval(val)))
        print(f"set strew.{mod}.{attr} = {getattr(m, attr)}", flush=True)
        argv = argv[2:]
    sys.argv = [sys.argv[0]] + argv
    import fresh17_rows

    fresh17_rows.main()


if __name__ == "__main__":
    main()
