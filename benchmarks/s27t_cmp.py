"""s27t: rows that differ in verdict between two synth_variants JSONs.

``python benchmarks/s27t_cmp.py BASE.json NEW.json [OTHER.json]``
"""

import json
import sys


def load(p):
    return {(r["case"], r["variant"], r["seed"]): r for r in json.load(open(p))["rows"] if "variant" in r}


runs = [load(p) for p in sys.argv[1:]]
keys = sorted(set().union(*runs), key=str)
for k in keys:
    v = [r.get(k, {}).get("faithful") for r in runs]
    if len(set(v)) > 1:
        print(k, " | ".join(f"{x} {r.get(k, {}).get('failures', '')}" for x, r in zip(v, runs)))
for p, r in zip(sys.argv[1:], runs):
    print(p, sum(x["faithful"] for x in r.values()), "/", len(r))
