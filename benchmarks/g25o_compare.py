"""Helper g25o: two grow_variants.py JSON files row for row (verdict, count, failures).

    python benchmarks/g25o_compare.py BEFORE.json AFTER.json
"""
import json
import sys

a, b = (json.load(open(p))["rows"] for p in sys.argv[1:3])
key = lambda r: (r["case"], r["variant"], r["seed"])
ra = {key(r): r for r in a if "faithful" in r}
rb = {key(r): r for r in b if "faithful" in r}
same = changed = 0
for k in ra:
    if k not in rb:
        continue
    x, y = ra[k], rb[k]
    if x["faithful"] != y["faithful"] or x["failures"] != y["failures"]:
        print(f"  {k[0]:12s} {k[1]:6s} s{k[2]}: {'pass' if x['faithful'] else 'FAIL'} {' '.join(x['failures'])} n={x['n']} -> {'pass' if y['faithful'] else 'FAIL'} {' '.join(y['failures'])} n={y['n']}")
    changed += x["n"] != y["n"]
    same += x["n"] == y["n"]
pa = sum(r["faithful"] for k, r in ra.items() if k in rb)
pb = sum(r["faithful"] for k, r in rb.items() if k in ra)
print(f"{len([k for k in ra if k in rb])} rows: before {pa} pass, after {pb} pass; element count changed in {changed}, equal in {same}")
