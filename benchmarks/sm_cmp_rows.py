"""Helper sm: row-for-row comparison of two synth_variants JSON files (verdict and failing metrics).

    python benchmarks/sm_cmp_rows.py BEFORE.json AFTER.json
"""
import json
import sys


def rows(path):
    d = json.load(open(path))
    out = {}
    for r in d["rows"]:
        key = tuple(str(r.get(k)) for k in ("case", "set", "variant", "seed") if k in r) or (json.dumps(r)[:80],)
        out[key] = r
    return out


a, b = rows(sys.argv[1]), rows(sys.argv[2])
lost = gained = 0
for k in sorted(set(a) | set(b)):
    ra, rb = a.get(k), b.get(k)
    pa = ra and ra.get("faithful", ra.get("passed"))
    pb = rb and rb.get("faithful", rb.get("passed"))
    if pa != pb:
        tag = "GAINED" if pb else "LOST"
        gained += bool(pb); lost += not pb
        print(tag, k, "before", (ra or {}).get("failures", ""), "after", (rb or {}).get("failures", ""))
print(f"{sum(bool(r.get('faithful', r.get('passed'))) for r in a.values())}/{len(a)} -> {sum(bool(r.get('faithful', r.get('passed'))) for r in b.values())}/{len(b)}; gained {gained}, lost {lost}")
