"""Issue 13 point 1, helper svar13i: can ANY method pass a variant audit's failing row?

The "oracle" result of a case is the exemplar's own generator drawn ``--scale`` times
larger on each side (same class, same parameters and same variant seed, so the same
shapes; counts scaled by the area, lattice sizes by the side): a perfect continuation of
the exemplar's process. ``strew.metrics.fidelity`` judges it against the exemplar as the
audit judges synth. A row whose oracle fails too is limited by the metric on that
exemplar (a small, cropped frame), not by synth. Rows are read from a
``synth_variants.py`` JSON (default: its failing rows) and each oracle is drawn at
``--draws`` seeds: the variant seed itself (the same shapes: make.py draws them first),
then variant seed + 1000 d (other shapes of the same class parameters: the same process).

    python benchmarks/svar13i_oracle.py JSON [--all] [--draws 2] [--scale 3.5]
                                        [--json benchmarks/results/svar13i_oracle.json]
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from typing import Any


sys.path.insert(0, __file__.rsplit("/", 1)[0])
from _runner import fidelity_suite  # noqa: E402

from strew.metrics import fidelity  # noqa: E402

# per class: the size parameter (side) and the count parameters (scaled by the area),
# or the lattice counts (scaled by the side)
SIDE = {"stones": 200.0, "two_sizes": 220.0, "three_sizes": 210.0, "clusters": 300.0, "stripes": 170.0, "sticks": 170.0}
AREA_COUNTS = {"stones": ("count",), "two_sizes": ("n_large", "n_small"), "three_sizes": ("counts",), "stripes": ("count",), "sticks": ("count",)}
LATTICE = {"rings": (("nx", 4), ("ny", 4)), "hex_lattice": (("nx", 11), ("ny", 12)), "rows_noisy": (("nx", 12), ("ny", 11)),
           "bricks": (("per_row", 8), ("rows", 16)), "scales": (("per_row", 10), ("rows", 10))}
DEFAULTS = {"stones": {"count": 160}, "two_sizes": {"n_large": 80, "n_small": 220}, "three_sizes": {"counts": (170, 65, 26)},
            "stripes": {"count": 220}, "sticks": {"count": 120}}


def big_params(name: str, kw: dict[str, Any], scale: float) -> dict[str, Any] | None:
    """The parameters of the oracle draw, or None where the class cannot be drawn larger."""
    out = dict(kw)
    if name in LATTICE:
        for key, default in LATTICE[name]:
            n = int(round(scale * out.get(key, default)))
            out[key] = n + (n % 2 if key in ("ny", "rows") else 0)  # rings: even ny is one period
        return out
    if name not in SIDE:
        return None
    side = out.get("size", SIDE[name])
    out["size"] = scale * side
    for key in AREA_COUNTS.get(name, ()):
        v = out.get(key, DEFAULTS[name][key])
        out[key] = tuple(int(round(x * scale * scale)) for x in v) if isinstance(v, (list, tuple)) else int(round(v * scale * scale))
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("rows")
    ap.add_argument("--all", action="store_true", help="every row's case, not only the failing ones")
    ap.add_argument("--draws", type=int, default=2)
    ap.add_argument("--scale", type=float, default=3.5)
    ap.add_argument("--json", default="benchmarks/results/svar13i_oracle.json")
    ap.add_argument("--harder", action="store_true", help="stones take aspect (grow_variants' suite)")
    a = ap.parse_args()
    if a.harder:
        from grow_variants import _harder_suite

        mk = _harder_suite()
    else:
        mk = fidelity_suite()
    rows = [r for r in json.load(open(a.rows))["rows"] if "faithful" in r]
    cases: dict[tuple, dict[str, Any]] = {}
    for r in rows:
        key = (r["case"], r["variant"])
        c = cases.setdefault(key, {"case": r["case"], "variant": r["variant"], "params": r["params"], "synth": []})
        c["synth"].append(bool(r["faithful"]))
    todo = [c for c in cases.values() if a.all or not all(c["synth"])]
    out = []
    for c in todo:
        name, label = c["case"], c["variant"]
        v = int(label.split("s")[-1]) if "s" in label else int(label[1:])
        kw = {k: (tuple(x) if isinstance(x, list) else x) for k, x in c["params"].items()}
        big = big_params(name, kw, a.scale)
        if big is None:
            print(f"  {name:12s} {label:6s} (no oracle for this class)")
            continue
        ex = mk.make_exemplar(name, rng=v, **kw)
        res = []
        for d in range(a.draws):
            t0 = time.process_time()
            arr = mk.make_exemplar(name, rng=v + 1000 * d, **big)
            rep = fidelity(ex, arr, eq5=False, local=False)
            fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
            res.append({"faithful": rep.faithful, "failures": fails, "n": len(arr), "cpu_s": round(time.process_time() - t0, 2)})
        row = {**c, "oracle": res, "oracle_passes": sum(x["faithful"] for x in res)}
        out.append(row)
        print(f"  {name:12s} {label:6s} synth {sum(c['synth'])}/{len(c['synth'])}  oracle {row['oracle_passes']}/{len(res)}  " + " | ".join(" ".join(x["failures"]) or "pass" for x in res), flush=True)
    with open(a.json, "w") as f:
        json.dump({"benchmark": "svar13i_oracle", "source": a.rows, "scale": a.scale, "rows": out}, f, indent=1)
    print(f"figures written to {a.json}")


if __name__ == "__main__":
    main()
