"""Where a growth of stones with relaxation spends its work (issue 14 point 5): the
repeated work of §5.1's priority wait, the placements that fail and why, and the cost
per element at several counts.

``profile``: one growth (stones, relaxation on) with wrappers that count the calls and
sum the CPU seconds (``time.process_time``) of ``place`` by outcome (placed, or refused
at which test: the last of ``place``'s own tests it called), ``choose`` (matching, for
seeds then placed or killed), ``_nudge`` by outcome, the priority wait (``outranked``,
``_defer``, ``release_deferred``) and ``relax_window``; the wrappers cost time of their
own, so the shares are of the wrapped run.
``scale``: CPU seconds of growths of 200 to 2,000 stones (median of ``--repeat``), per
element, and the exponent of the cost (least squares of log CPU on log count).

Run: ``PYTHONPATH=src python benchmarks/spd14x_work.py profile --count 2000 --json F``;
``PYTHONPATH=src python benchmarks/spd14x_work.py scale --repeat 3 --json F``.
"""

from __future__ import annotations

import argparse
import collections
import json
import statistics
import time

import numpy as np

from strew.grow import _collide, _growth, _place, analyze, grow
from strew.grow._exemplars import stone_exemplar

#: place's own tests, in its order: a refusal is put down to the last of them it called
TESTS = ("too_close_in_kind", "crowds_own_kind", "lean_ok", "fits_domain", "overlaps_any", "_nudge", "crowds_gap")


def profile(n: int) -> dict:
    ref = analyze(stone_exemplar())
    grow(ref, count=50, rng=1)
    P, C, G = _place._Place, _collide._Collide, _growth._Grower
    cpu: dict[str, float] = collections.defaultdict(float)
    calls: collections.Counter = collections.Counter()
    pc = time.process_time
    state = {"in_place": False, "depth": 0, "last": None, "seed_fate": {}}

    def timed(cls, name, outcome):
        f = cls.__dict__[name]

        def w(self, *a, **k):
            t = pc()
            r = f(self, *a, **k)
            key = f"{name}:{('ok' if r else 'fail')}" if outcome else name
            cpu[key] += pc() - t
            calls[key] += 1
            return r

        setattr(cls, name, w)

    def tagged(cls, name):
        f = cls.__dict__[name]

        def w(self, *a, **k):
            if state["in_place"] and state["depth"] == 0:
                state["last"] = name
            state["depth"] += 1
            try:
                return f(self, *a, **k)
            finally:
                state["depth"] -= 1

        setattr(cls, name, w)

    for name in TESTS:
        for cls in (P, C, G):
            if name in cls.__dict__:
                tagged(cls, name)
                break
    place = P.place

    def place_w(self, s, *a, **k):
        state["in_place"], state["last"], state["depth"] = True, "start", 0
        t = pc()
        r = place(self, s, *a, **k)
        d = pc() - t
        state["in_place"] = False
        key = "place:ok" if r else f"place:fail:{state['last']}"
        cpu[key] += d
        calls[key] += 1
        return r

    P.place = place_w
    choose = P.choose
    choose_cpu: dict[int, float] = {}

    def choose_w(self, s, *a, **k):
        t = pc()
        r = choose(self, s, *a, **k)
        choose_cpu[s] = choose_cpu.get(s, 0.0) + pc() - t
        calls["choose"] += 1
        return r

    P.choose = choose_w
    timed(P, "outranked", True)
    timed(P, "release_deferred", False)
    timed(P, "_nudge", True)
    for name in ("relax_window", "_defer", "kill"):
        for cls in (G, P, C, *G.__mro__):
            if name in cls.__dict__:
                timed(cls, name, False)
                break
    grown = []
    init = G.__init__

    def keep(self, *a, **k):
        init(self, *a, **k)
        grown.append(self)

    G.__init__ = keep
    t = pc()
    out = grow(ref, count=n, rng=1, relax=True)
    total = pc() - t
    g = grown[-1]
    placed = set(g.order)
    cpu["choose:seed placed"] = sum(v for s, v in choose_cpu.items() if s in placed)
    cpu["choose:seed killed"] = sum(v for s, v in choose_cpu.items() if s not in placed)
    calls["choose:seed placed"] = sum(1 for s in choose_cpu if s in placed)
    calls["choose:seed killed"] = sum(1 for s in choose_cpu if s not in placed)
    rows = {k: {"calls": int(calls[k]), "cpu_s": round(cpu[k], 4), "share": round(cpu[k] / total, 4)} for k in sorted(cpu)}
    wait = sum(cpu[k] for k in cpu if k.startswith(("outranked", "_defer", "release_deferred")))
    failed = sum(cpu[k] for k in cpu if k.startswith("place:fail")) + cpu["choose:seed killed"]
    return {
        "elements": len(out),
        "cpu_s_wrapped": round(total, 4),
        "objects_made": int(g.n),
        "priority_wait_share": round(wait / total, 4),
        "failed_placements_share": round(failed / total, 4),
        "rows": rows,
    }


def scale(repeat: int) -> dict:
    ref = analyze(stone_exemplar())
    grow(ref, count=50, rng=1)
    counts = [200, 500, 1000, 2000]
    out = {}
    for n in counts:
        cs = []
        for _ in range(repeat):
            t = time.process_time()
            grow(ref, count=n, rng=1, relax=True)
            cs.append(time.process_time() - t)
        out[n] = statistics.median(cs)
    lx, ly = np.log(counts), np.log([out[n] for n in counts])
    expo = float(np.polyfit(lx, ly, 1)[0])
    return {
        "cpu_s": {str(n): round(out[n], 4) for n in counts},
        "el_per_cpu_s": {str(n): round(n / out[n], 1) for n in counts},
        "exponent_200_2000": round(expo, 3),
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("what", choices=["profile", "scale"])
    ap.add_argument("--count", type=int, default=2000)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--json", default=None)
    args = ap.parse_args()
    res = profile(args.count) if args.what == "profile" else scale(args.repeat)
    text = json.dumps(res, indent=1)
    print(text)
    if args.json:
        with open(args.json, "w") as f:
            f.write(text + "\n")


if __name__ == "__main__":
    main()
