"""Helper g26s: rows of two grow_variants.py JSON files whose element count or verdict differ.

    python benchmarks/g26s_compare.py BASE.json NEW.json
"""
import json
import sys


def rows(p):
    return {(r["case"], r["variant"], r["seed"]): r for r in json.load(open(p))["rows"] if "seed" in r and "variant" in r}


b, n = rows(sys.argv[1]), rows(sys.argv[2])
common = [k for k in n if k in b]
ch = [(k, b[k]["n"], n[k]["n"], b[k]["faithful"], n[k]["faithful"]) for k in common if b[k]["n"] != n[k]["n"] or b[k]["faithful"] != n[k]["faithful"]]
print(f"{len(common)} common rows; base {sum(b[k]['faithful'] for k in common)} faithful, new {sum(n[k]['faithful'] for k in common)}; changed {len(ch)}:")
for c in ch:
    print("  ", c)
