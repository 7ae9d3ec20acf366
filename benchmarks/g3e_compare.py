"""Helper g3e: rows of two grow_variants JSON files side by side, the ones whose verdict differs.

    python benchmarks/g3e_compare.py BASE.json NEW.json
"""
import json
import sys


def rows(path):
    d = json.load(open(path))
    return {(r["case"], r["variant"], r["seed"]): r for r in d["rows"] if "variant" in r}


a, b = rows(sys.argv[1]), rows(sys.argv[2])
pa = pb = 0
for key in sorted(set(a) & set(b)):
    ra, rb = a[key], b[key]
    pa += ra["faithful"]
    pb += rb["faithful"]
    if ra["faithful"] != rb["faithful"] or ra["n"] != rb["n"]:
        tag = "LOST" if ra["faithful"] and not rb["faithful"] else "GAINED" if rb["faithful"] and not ra["faithful"] else "changed"
        print(f"{tag:7} {key[0]:12} {key[1]:7} s{key[2]}: n {ra['n']} -> {rb['n']}  {ra['failures']} -> {rb['failures']}")
print(f"passes {pa} -> {pb} of {len(set(a) & set(b))} common rows")
