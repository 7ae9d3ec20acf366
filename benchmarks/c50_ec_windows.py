"""Helper c50: the empty_circle window score alone (every other metric left out of the local
map) for clusters at 50x: synth seeds (as seam17_all50.py makes them) against the class's
generator drawn at 50x (seam17_all50.oracle_row's draw). Prints per draw the windows whose
empty_circle score exceeds 1, the count above 0.9, the highest, and which side fails
(q95 below the exemplar's: too few wide gaps; above: holes).

    PYTHONPATH=src python benchmarks/c50_ec_windows.py [--synth-seeds 1,2,3,4] [--gen-seeds 0,11,12]
"""
import argparse
import json
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import seam17_all50 as S17  # noqa: E402  (patches the generator's dart as seam17 does)

import strew._fidelity as F  # noqa: E402
from strew import Region  # noqa: E402
from strew.metrics import fidelity  # noqa: E402

SIDE: list = []
_wd = F._window_discrepancies


def ec_only(st, ex_stats, kinds, s, flags):
    d = _wd(st, ex_stats, kinds, s, flags)
    SIDE.append(np.sign(st.q95 / ex_stats.q95 - 1.0) if ex_stats.q95 > 0 else 0.0)
    return {"empty_circle": d["empty_circle"]} if "empty_circle" in d else {}


def summary(tag, rep):
    sc = np.asarray(rep.local["score"], float)
    fin = sc[np.isfinite(sc)]
    side = np.array(SIDE[-len(fin):]) if len(SIDE) >= len(fin) else np.zeros(len(fin))
    r = dict(draw=tag, windows=int(fin.size), over1=int((fin > 1).sum()), over09=int((fin > 0.9).sum()), worst=round(float(fin.max()), 4),
             over1_q95_low=int(((fin > 1) & (side < 0)).sum()), mean=round(float(fin.mean()), 4))
    print(r, flush=True)
    return r


ap = argparse.ArgumentParser()
ap.add_argument("--synth-seeds", default="1,2,3,4")
ap.add_argument("--gen-seeds", default="0,11,12")
ap.add_argument("--json", default="benchmarks/results/c50_ec_windows.json")
a = ap.parse_args()
mk = S17.fidelity_suite()
ex = mk.make_exemplar("clusters")
x0, y0, x1, y1 = ex.region.bounds
region = Region.rectangle(7.07 * (x1 - x0), 7.07 * (y1 - y0))
rows = []
F._window_discrepancies = ec_only
from strew.synth import synthesize  # noqa: E402

for s in [int(v) for v in a.synth_seeds.split(",") if v]:
    SIDE.clear()
    out = synthesize(ex, region, rng=s, measure=False)
    rows.append(summary(f"synth s{s}", fidelity(ex, out, region, eq5=False)))
for s in [int(v) for v in a.gen_seeds.split(",") if v]:
    if s != 0 and not S17.FC.same_outlines("clusters", s):
        print("generator seed", s, "draws other outlines: skipped")
        continue
    SIDE.clear()
    arr = S17.FC.larger("clusters", s, 50.0)
    rows.append(summary(f"generator s{s}", fidelity(ex, arr, eq5=False)))
Path(a.json).write_text(json.dumps(rows, indent=1))
