"""g44v: grow_variants JSON rows of two runs compared field by field (all but cpu_s),
rows matched by (case, set, variant, seed). Run: python benchmarks/g44v_cmp_rows.py BASE.json NEW.json"""

import json
import sys


def rows(p):
    out = {}
    with open(p) as f:
        data = json.load(f)
    for r in data["rows"]:
        out[(r["case"], str(r.get("set")), str(r.get("variant")), r.get("seed"))] = {k: v for k, v in r.items() if k != "cpu_s"}
    return out


a, b = rows(sys.argv[1]), rows(sys.argv[2])
diff = [k for k in a if a[k] != b.get(k)]
print(f"{len(a)} rows in base, {len(b)} in new, {len(set(a) & set(b))} matched, {len(diff)} differing in any figure but cpu_s")
for k in diff[:10]:
    print(k, {f: (a[k].get(f), (b.get(k) or {}).get(f)) for f in a[k] if a[k].get(f) != (b.get(k) or {}).get(f)})
