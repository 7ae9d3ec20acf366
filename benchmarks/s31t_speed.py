"""Helper s31t: synth's CPU time and elements/s against a baseline src, both trees in the
same run (alternating subprocesses, as ``benchmarks/synth_speed.py``, whose worker it uses).

    PYTHONPATH=src python benchmarks/s31t_speed.py --base /tmp/s31t_base/src --only suite:sticks,grid [--repeat 3]

Prints per case the median CPU seconds and element count of both trees, the CPU-time
ratio (new / base) and the elements/s ratio (new / base; issue 13 point 6 asks >= 0.5).
"""
import argparse
import json
import statistics

import synth_speed

p = argparse.ArgumentParser()
p.add_argument("--base", required=True)
p.add_argument("--only", required=True)
p.add_argument("--repeat", type=int, default=3)
p.add_argument("--json", default=None)
a = p.parse_args()
new_src = str(synth_speed.ROOT / "src")
rows = []
for case in a.only.split(","):
    got = {"base": [], "new": []}
    for _ in range(a.repeat):
        for key, src in (("base", a.base), ("new", new_src)):
            got[key].append(synth_speed.run(src, case))
    row = {"case": case}
    for key in ("base", "new"):
        row[f"{key}_cpu_s"] = round(statistics.median(r["cpu_s"] for r in got[key]), 3)
        row[f"{key}_n"] = int(statistics.median(r["n"] for r in got[key]))
        row[f"{key}_el_per_s"] = round(statistics.median(r["n"] / r["cpu_s"] for r in got[key]))
    row["cpu_ratio"] = round(row["new_cpu_s"] / row["base_cpu_s"], 3)
    row["el_per_s_ratio"] = round(row["new_el_per_s"] / row["base_el_per_s"], 3)
    rows.append(row)
    print(f"  {case:18s} cpu base {row['base_cpu_s']:7.2f} s new {row['new_cpu_s']:7.2f} s  ratio {row['cpu_ratio']:.2f} | "
          f"n {row['base_n']} -> {row['new_n']} | el/s {row['base_el_per_s']} -> {row['new_el_per_s']} ratio {row['el_per_s_ratio']:.2f}", flush=True)
if a.json:
    with open(a.json, "w") as f:
        json.dump(rows, f, indent=1)
