"""Helper s27e: rows of s27e_audit.py's printout whose verdict or failing metrics differ
between main's clip (the ``main-clip:`` line above each row) and this tree's.

    python benchmarks/s27e_compare.py benchmarks/results/s27e_*.txt
"""
import re
import sys

for path in sys.argv[1:]:
    lines = open(path).read().splitlines()
    n = same = 0
    m0 = m1 = 0
    for a, b in zip(lines, lines[1:]):
        if not a.strip().startswith("main-clip:") or " seed " not in b:
            continue
        n += 1
        va, vb = "pass" in a.split()[1], " pass " in b
        fa = sorted(re.findall(r"(\S+)=", a.split("n=", 1)[1]))
        fb = sorted(re.findall(r"(\S+)=", b.split("cpu", 1)[1]))
        m0 += va
        m1 += vb
        if va == vb and fa == fb:
            same += 1
        else:
            print(f"  {path}: DIFFERS\n    {a.strip()}\n    {b.strip()}")
    print(f"{path}: {n} rows, main-clip {m0}/{n}, this {m1}/{n}, same verdict and failing metrics {same}/{n}")
