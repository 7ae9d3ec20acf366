"""s46w: row-by-row verdicts of an audit JSON against a baseline JSON.

    python benchmarks/s46w_compare.py BASE.json MINE.json
"""
import json
import sys


def rows(p):
    return {(r["case"], r["variant"], r["seed"]): r for r in json.load(open(p))["rows"] if "variant" in r and "faithful" in r}


a, b = rows(sys.argv[1]), rows(sys.argv[2])
fa = sum(r["faithful"] for r in a.values())
fb = sum(r["faithful"] for r in b.values())
print(f"base {fa}/{len(a)}  mine {fb}/{len(b)}  (common rows {len(set(a) & set(b))})")
for k in sorted(set(a) | set(b)):
    ra, rb = a.get(k), b.get(k)
    if ra is None or rb is None:
        print("only in one:", k)
        continue
    if ra["faithful"] != rb["faithful"]:
        print("CHANGED", k, "base", ra["faithful"], ra["failures"], "mine", rb["faithful"], rb["failures"])
    elif not ra["faithful"]:
        print("fail both", k, "base", ra["failures"], "mine", rb["failures"])
