"""Stripes snapped to a periodic tile: the old rule (round the lattice vector) against
``_snap_stripes`` (bounded: a turn of at most 15 degrees, widths within a factor 2), on
random cases of the hypothesis test's domain (angle in [-3.2, 3.2], 1 to 3 widths in
[1, 40], three face labels, tile sides in [100, 900]). Helper snap18i, issue 18.

Prints: cases the old rule put out of bounds, and its largest turn; how many of those the
new snap refused or moved into bounds; in-bounds cases whose snap changed (must be 0); the
new snap's largest turn and widths' ratio; CPU time per call, new / old (median of
``--repeat`` runs in the same process). Writes ``benchmarks/results/snap18i_bounds.json``.

    python benchmarks/snap18i_bounds.py [--cases 20000] [--seed 0] [--repeat 3]
"""

from __future__ import annotations

import argparse
import json
import math
import statistics
import time
from dataclasses import replace
from pathlib import Path

import numpy as np

from strew._errors import InputError
from strew.program._operators import _snap_stripes, _stripes_repeat, set_face_labels, stripes_properties

MAX_TURN, MAX_RATIO = math.radians(15.0), 2.0


def old_snap(p, tile):
    """The rule of 31cff62: k and l rounded, no bounds."""
    _, _, w, h = tile
    period = _stripes_repeat(p)
    n0 = np.array([-math.sin(p.angle), math.cos(p.angle)])
    k, l = round(w * n0[0] / period), round(h * n0[1] / period)
    if k == 0 and l == 0:
        raise InputError("smaller than two stripes")
    v = np.array([k / w, l / h])
    p_new = 1.0 / float(np.hypot(v[0], v[1]))
    n = v * p_new
    return replace(p, angle=math.atan2(-n[0], n[1]), widths=tuple(x * p_new / period for x in p.widths))


def measures(p, q):
    turn = abs(math.remainder(q.angle - p.angle, 2 * math.pi))
    return turn, q.widths[0] / p.widths[0]


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--cases", type=int, default=20000)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--json", default=str(Path(__file__).parent / "results" / "snap18i_bounds.json"))
    args = ap.parse_args()
    rng = np.random.default_rng(args.seed)
    cases = []
    for _ in range(args.cases):
        ws = rng.uniform(1, 40, int(rng.integers(1, 4)))
        cases.append((set_face_labels(stripes_properties(rng.uniform(-3.2, 3.2), *ws), "a", "b", "c"), (0.0, 0.0, *rng.uniform(100, 900, 2))))
    out = dict(cases=len(cases), small=0, old_out_of_bounds=0, old_max_turn_deg=0.0, refused=0, moved_into_bounds=0,
               in_bounds_changed=0, new_max_turn_deg=0.0, new_max_abs_log2_ratio=0.0)
    for p, tile in cases:
        try:
            qo = old_snap(p, tile)
        except InputError:
            out["small"] += 1
            continue
        to, so = measures(p, qo)
        bad = to > MAX_TURN or not (1 / MAX_RATIO <= so <= MAX_RATIO)
        out["old_out_of_bounds"] += bad
        out["old_max_turn_deg"] = max(out["old_max_turn_deg"], math.degrees(to))
        try:
            q = _snap_stripes(p, tile)
        except InputError:
            out["refused"] += 1
            continue
        tn, sn = measures(p, q)
        out["new_max_turn_deg"] = max(out["new_max_turn_deg"], math.degrees(tn))
        out["new_max_abs_log2_ratio"] = max(out["new_max_abs_log2_ratio"], abs(math.log2(sn)))
        same = abs(q.angle - qo.angle) < 1e-12 and abs(q.widths[0] - qo.widths[0]) < 1e-9 * qo.widths[0]
        if bad:
            out["moved_into_bounds"] += 1
        elif not same:
            out["in_bounds_changed"] += 1
    times = {"old": [], "new": []}
    for _ in range(args.repeat):
        for name, fn in (("old", old_snap), ("new", _snap_stripes)):
            t = time.process_time()
            for p, tile in cases:
                try:
                    fn(p, tile)
                except InputError:
                    pass
            times[name].append((time.process_time() - t) / len(cases) * 1e6)
    out["old_us_per_call"] = statistics.median(times["old"])
    out["new_us_per_call"] = statistics.median(times["new"])
    out["time_ratio_new_over_old"] = out["new_us_per_call"] / out["old_us_per_call"]
    for k, v in out.items():
        print(f"{k:24s} {v:.3f}" if isinstance(v, float) else f"{k:24s} {v}")
    Path(args.json).parent.mkdir(parents=True, exist_ok=True)
    Path(args.json).write_text(json.dumps(dict(args=vars(args), **out), indent=1))


if __name__ == "__main__":
    main()
