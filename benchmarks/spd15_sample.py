"""A sampling profile of grow (issue 14 point 5): the flow-mode growth of
``benchmarks/grow.py --against``'s ``hexflow`` case (or ``stones``), relaxation on.

A SIGPROF timer (every millisecond of CPU) records the Python stack; prints the share of
samples in which each function is on the stack (inclusive), on top of it (self), and
the innermost line in ``strew/grow``. Unlike cProfile it adds no cost per call.

Run: ``PYTHONPATH=src python benchmarks/spd15_sample.py hexflow 5`` (case, growths).
"""

from __future__ import annotations

import collections
import signal
import sys

import numpy as np

from strew import Region
from strew.grow import analyze, grow
from strew.grow._exemplars import hex_exemplar, stone_exemplar


def case_kwargs(name: str, ref):
    if name == "hexflow":
        sp = ref.mean_edge
        w = 30 * sp

        def field(p):
            a = np.radians(90.0) * np.clip(np.asarray(p)[:, 0] / w, 0, 1)
            return np.c_[np.cos(a), np.sin(a)]

        return {"region": Region.rectangle(w, 20 * sp), "mode": "flow", "flow": field}
    return {"count": 2000}


def main() -> None:
    name = sys.argv[1] if len(sys.argv) > 1 else "hexflow"
    reps = int(sys.argv[2]) if len(sys.argv) > 2 else 5
    ref = analyze({"hexflow": hex_exemplar, "stones": stone_exemplar}[name]())
    kw = case_kwargs(name, ref)
    grow(ref, rng=1, relax=True, **kw)  # kernels compiled or loaded outside the samples
    incl: collections.Counter = collections.Counter()
    own: collections.Counter = collections.Counter()
    lines: collections.Counter = collections.Counter()
    total = [0]

    def sample(sig, frame):
        total[0] += 1
        seen: set = set()
        f, top, line = frame, True, False
        while f is not None:
            co = f.f_code
            key = f"{co.co_filename.split('/')[-1]}:{co.co_name}"
            if top:
                own[key] += 1
                top = False
            if key not in seen:
                incl[key] += 1
                seen.add(key)
            if not line and "strew/grow" in co.co_filename:
                lines[f"{key}:{f.f_lineno}"] += 1
                line = True
            f = f.f_back

    signal.signal(signal.SIGPROF, sample)
    signal.setitimer(signal.ITIMER_PROF, 0.001, 0.001)
    for _ in range(reps):
        grow(ref, rng=1, relax=True, **kw)
    signal.setitimer(signal.ITIMER_PROF, 0, 0)
    t = max(total[0], 1)
    print("samples", total[0])
    for title, c, k in (("inclusive", incl, 60), ("self", own, 30), ("innermost strew/grow line", lines, 40)):
        print("---", title)
        for key, v in c.most_common(k):
            print(f"{100 * v / t:5.1f}% {key}")


if __name__ == "__main__":
    main()
