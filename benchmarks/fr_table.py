"""Helper fr: per-class pass counts and failing rows of variant-audit JSONs, side by side.

    python benchmarks/fr_table.py benchmarks/results/fr_grow_fixed_s11_12.json [...]
"""
import json
import sys
from collections import defaultdict


def main():
    for path in sys.argv[1:]:
        d = json.load(open(path))
        rows = [r for r in d["rows"] if "faithful" in r]
        per = defaultdict(lambda: [0, 0])
        for r in rows:
            per[r["case"]][0] += bool(r["faithful"])
            per[r["case"]][1] += 1
        tot = sum(v[0] for v in per.values()), sum(v[1] for v in per.values())
        print(f"{path.split('/')[-1]}: {tot[0]}/{tot[1]}  " + ", ".join(f"{k} {a}/{n}" for k, (a, n) in per.items()))
        for r in rows:
            if not r["faithful"]:
                print(f"    FAIL {r['case']} {r['variant']} ({r['set']} {r['params']}) seed {r['seed']}: {' '.join(r['failures'])}")


if __name__ == "__main__":
    main()
