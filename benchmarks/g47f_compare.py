"""Helper g47f: an audit JSON against baseline JSONs, row by row (verdict, n, failures).

    python benchmarks/g47f_compare.py BRANCH.json BASE.json [BASE.json ...]
"""
import json
import sys


def rows(f):
    return {(r["case"], r["variant"], r["seed"]): r for r in json.load(open(f))["rows"] if "faithful" in r}


b = rows(sys.argv[1])
base = {}
for f in sys.argv[2:]:
    base.update(rows(f))
common = [k for k in sorted(b) if k in base]
moved = 0
for k in common:
    x, y = base[k], b[k]
    if x["n"] != y["n"]:
        moved += 1
    if x["faithful"] != y["faithful"] or (x["failures"] != y["failures"]):
        print(f"  {k[0]} {k[1]} seed {k[2]}: main {'pass' if x['faithful'] else 'FAIL'} {x['failures']} n={x['n']} | branch {'pass' if y['faithful'] else 'FAIL'} {y['failures']} n={y['n']}")
cases = sorted({k[0] for k in common})
for c in cases:
    ks = [k for k in common if k[0] == c]
    print(f"{c}: main {sum(base[k]['faithful'] for k in ks)}/{len(ks)}, branch {sum(b[k]['faithful'] for k in ks)}/{len(ks)}, rows moved (n differs) {sum(base[k]['n'] != b[k]['n'] for k in ks)}")
print(f"{sys.argv[1]}: {len(common)} rows compared, {moved} moved")
