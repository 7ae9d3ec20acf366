"""Side by side: synth's border-strip rows of several ``worlds_strips.py`` JSON files
(density and each kind's share, +-3s/2s/1s, with 95 % intervals; ``*``: the interval
reaches outside [0.97, 1.03]). ``python benchmarks/bal19g_compare.py A.json B.json ...``
(helper bal19g, issue 19 point 4)."""
import json, sys
fs = sys.argv[1:]
T = [json.load(open(f))["methods"]["synth"]["tiled"] for f in fs]
print("files:", " | ".join(fs))
for w in ("3s", "2s", "1s"):
    for key in ("density", "small", "medium", "large"):
        cells = []
        for t in T:
            u = t[f"units_{w}"]
            v = u["density_ratio"] if key == "density" else u["kind_fraction_ratio"][key]
            lo, hi = v["ci"]
            flag = "" if 0.97 <= lo and hi <= 1.03 else "*"
            cells.append(f"{v['value']:.3f} [{lo:.3f}, {hi:.3f}]{flag}")
        print(f"+-{w} {key:8s} " + "  ".join(f"{c:24s}" for c in cells))
