"""The fidelity judge before and after a change, on the same outputs (issue 13, judge13).

Judging is deterministic and the methods do not depend on the judge, so the outputs of
``benchmarks/fidelity.py --method synth|grow --seeds 1-5`` (region 3.5x the frame's side,
Eq. 5 on) and of ``benchmarks/synth_variants.py --varied`` / ``grow_variants.py --varied``
(Eq. 5 and the local map off; grow enlarged to 10x the exemplar's count) are made once,
pickled under ``--cache``, and scored by both judges in one run: the working tree's
``strew._fidelity`` and the file ``<--base>/strew/_fidelity.py`` (e.g. ``/work/main/src``
at the commit before the change), loaded as a second module. The verdict of each run is
the one the named benchmark prints (same exemplar, region, seed and judge arguments).

    python benchmarks/judge_rescore.py make --sets suite-synth,suite-grow,var-synth,var-grow [--only NAME,...]
    python benchmarks/judge_rescore.py score --base /work/main/src [--sets ...] [--only ...]

Printed per set: faithful counts before/after, per class, and every run whose verdict
changed with its failures; JSON to ``benchmarks/results/judge_rescore.json``.
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import math
import pickle
import sys
import time
from pathlib import Path
from typing import Any

from _runner import fidelity_suite
from _variants import cases

from strew import Region

ROOT = Path(__file__).resolve().parents[1]
SETS = ("suite-synth", "suite-grow", "var-synth", "var-grow", "seams-synth", "calib")
ROTATE = ("hex_lattice", "rows_noisy", "bricks", "scales", "rings", "sticks")


def jobs(sets: list[str], only: list[str]) -> list[tuple[str, str, str, int, dict[str, Any], str, int, float]]:
    """(set, class, label, variant seed, variation, method, seed, scale) of every run."""
    mk = fidelity_suite()
    names = only or list(mk.NAMES)
    out = []
    if "calib" in sets:
        out += [("calib", lab, "seam", 0, {}, "seam", 0, 0.0) for lab in ("rings", "two_sizes", "clusters")]
    for st in sets:
        for name in names:
            if st == "calib":  # fidelity_calibration.py: fresh draws at 10x, 50x (seed 0) and its --seams controls
                out += [(st, name, f"x{k:g}", 0, {}, "draw", 0, k) for k in (10.0, 50.0)]
                continue
            if st == "seams-synth":  # synth.py --seams: 50x the area, the local map's failing windows
                if name != "sticks" or only:
                    out += [(st, name, "v0", 0, {}, "synth", seed, 7.07) for seed in (1, 2, 3)]
                continue
            if st.startswith("suite"):
                methods = ["synth"] if st == "suite-synth" else ["grow:fixed"] + (["grow:rotate"] if name in ROTATE else [])
                for m in methods:
                    for seed in range(1, 6):
                        out.append((st, name, "v0", 0, {}, m, seed, 3.5))
            else:
                if name == "sticks" and st == "var-synth" and not only:
                    continue  # as synth_variants.py (default_skip); grow_variants.py keeps it
                for label, _tag, v, kw in cases(name, [1, 2, 3], True):
                    for seed in (1, 2):
                        out.append((st, name, label, v, kw, "synth" if st == "var-synth" else "grow:fixed", seed, 3.5))
    return out


FREE = ""  # "--free-support X": synth made with strew.synth._prepare.FREE_SUPPORT = X (cache key suffix)


def key(j: tuple[Any, ...]) -> str:
    st, name, label, _v, _kw, m, seed, _scale = j
    return f"{st}_{name}_{label}_{m.replace(':', '-')}_{seed}" + (f"_fs{FREE}" if FREE and m == "synth" else "")


def make(j: tuple[Any, ...]) -> tuple[Any, Any]:
    st, name, _label, v, kw, m, seed, scale = j
    mk = fidelity_suite()
    if st == "calib":
        import fidelity_calibration as FC

        if m == "seam":
            return (mk.make_exemplar("rings"), FC.rings_seam(21)) if name == "rings" else (mk.make_exemplar(name), FC.synth_obstacle_seam(name))
        return mk.make_exemplar(name), FC.larger(name, 0, scale)
    ex = mk.make_exemplar(name, rng=v or None, **kw)
    x0, y0, x1, y1 = ex.region.bounds
    if m == "synth":
        from strew.synth import synthesize

        region = Region.rectangle(scale * (x1 - x0), scale * (y1 - y0))
        out = synthesize(ex, region, rng=seed) if st.startswith("suite") else synthesize(ex, region, rng=seed, measure=False)
        if st == "seams-synth":
            out = out.replace(region=region)
        return ex, out
    from strew.grow import grow

    mode = m.split(":")[1]
    if st.startswith("suite"):
        return ex, grow(ex, region=Region.rectangle(scale * (x1 - x0), scale * (y1 - y0)), mode=mode, rng=seed)
    for _ in range(2):  # as grow_variants.py: enlarge once to reach 10x the exemplar's count
        out = grow(ex, region=Region.rectangle(scale * (x1 - x0), scale * (y1 - y0)), mode=mode, rng=seed)
        if len(out) >= 10 * len(ex):
            break
        scale *= 1.05 * math.sqrt(10 * len(ex) / max(len(out), 1))
    return ex, out


def load_base(base: str) -> Any:
    path = Path(base) / "strew" / "_fidelity.py"
    spec = importlib.util.spec_from_file_location("strew._fidelity_base", path)
    mod = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = mod
    spec.loader.exec_module(mod)
    return mod


def verdict(F: Any, ex: Any, out: Any, suite: bool, seams: bool = False) -> dict[str, Any]:
    rep = F.fidelity(ex, out, eq5=suite, local=seams)
    fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
    if seams:
        import numpy as np

        sc = np.asarray(rep.local["score"], float)
        sc = sc[np.isfinite(sc)]
        w = rep.local["worst"] or {}
        fails.append(f"failing windows {float(np.mean(sc > 1.0)):.3f} of {sc.size}, worst {w.get('score', 0.0):.3f} {w.get('metric')}")
    return {"faithful": bool(rep.faithful), "failures": fails}


def main() -> None:
    if "--quick" in sys.argv[1:]:
        print("judge_rescore: skipped: it needs the positional make|score, outputs made beforehand under --cache and a baseline src folder (--base), which have no honest default")
        sys.exit(3)  # _runner.SKIPPED
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("what", choices=["make", "score"])
    p.add_argument("--sets", default=",".join(SETS))
    p.add_argument("--only", default="")
    p.add_argument("--cache", default="/tmp/judge_rescore_cache")
    p.add_argument("--base", default="/work/main/src")
    p.add_argument("--json", default=str(ROOT / "benchmarks" / "results" / "judge_rescore.json"))
    p.add_argument("--free-support", default="", help="synth with strew.synth._prepare.FREE_SUPPORT set to this (its own cache entries)")
    p.add_argument("--quick", action="store_true", help="run_all.py's check: skips (see main)")
    a = p.parse_args()
    global FREE
    if a.free_support:
        import strew.synth._prepare as P

        FREE = a.free_support
        P.FREE_SUPPORT = float(FREE)
    sets = [s for s in a.sets.split(",") if s]
    only = [s for s in a.only.split(",") if s]
    cache = Path(a.cache)
    cache.mkdir(parents=True, exist_ok=True)
    todo = sorted(jobs(sets, only), key=lambda j: j[7] if j[0] == "calib" else 0.0)  # calib: the 50x draws last
    if a.what == "make":
        for j in todo:
            f = cache / (key(j) + ".pkl")
            if f.exists():
                continue
            t0 = time.process_time()
            ex, out = make(j)
            f.write_bytes(pickle.dumps((j, ex, out)))
            print(f"made {key(j)}: {len(out)} elements, {time.process_time() - t0:.1f} s cpu", flush=True)
        return
    import strew._fidelity as NEW

    OLD = load_base(a.base)
    rows = []
    for j in todo:
        f = cache / (key(j) + ".pkl")
        if not f.exists():
            continue
        _, ex, out = pickle.loads(f.read_bytes())
        suite = j[0].startswith("suite")
        seams = j[0] in ("seams-synth", "calib")
        b, n = verdict(OLD, ex, out, suite, seams), verdict(NEW, ex, out, suite, seams)
        r = {"set": j[0], "case": j[1], "variant": j[2], "method": j[5], "seed": j[6], "before": b, "after": n}
        rows.append(r)
        flag = "" if b["faithful"] == n["faithful"] else "  CHANGED"
        print(f"{j[0]:11s} {j[1]:12s} {j[2]:5s} {j[5]:11s} s{j[6]}: before {'pass' if b['faithful'] else 'FAIL'} after {'pass' if n['faithful'] else 'FAIL'}{flag}  {' '.join(b['failures'])} -> {' '.join(n['failures'])}", flush=True)
    print()
    for st in sets:
        rs = [r for r in rows if r["set"] == st]
        if not rs:
            continue
        names = list(dict.fromkeys(r["case"] for r in rs))
        per = ", ".join(f"{n} {sum(r['before']['faithful'] for r in rs if r['case'] == n)}->{sum(r['after']['faithful'] for r in rs if r['case'] == n)}/{sum(r['case'] == n for r in rs)}" for n in names)
        print(f"{st}: before {sum(r['before']['faithful'] for r in rs)}/{len(rs)}, after {sum(r['after']['faithful'] for r in rs)}/{len(rs)}  ({per})")
    Path(a.json).parent.mkdir(parents=True, exist_ok=True)
    Path(a.json).write_text(json.dumps({"benchmark": "judge_rescore", "base": a.base, "rows": rows}, indent=1) + "\n")


if __name__ == "__main__":
    main()
