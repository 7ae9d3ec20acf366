"""Inclusive CPU shares of the parts of a flow-mode growth (issue 14 point 5): the
``hexflow`` case of ``benchmarks/grow.py --against``, relaxation on. The passes that
``_growth.run`` calls (the growth ``advance``, ``fill_holes``, ``close_gaps``,
``insert_stretched``, ``reshape_shear``, ``close_holes``, the network's one-edge pass
``relax_network`` and its band's ``relax_network band``, ``densify``,
``regrow_sheared``, ...) and, inside the growth, ``place``, ``flow_respace`` and the
windowed relaxation ``relax_window`` (§5.5), each wrapped with a CPU timer: inclusive
(a part called inside another counts in both; a part inside itself once).

Run: ``PYTHONPATH=src python benchmarks/spd15_passes.py 5`` (growths).
"""

from __future__ import annotations

import collections
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))

from spd15_sample import case_kwargs

from strew.grow import _growth, analyze, grow
from strew.grow._exemplars import hex_exemplar

PASSES = ("fill_holes", "close_gaps", "insert_stretched", "reshape_shear", "close_holes", "relax_network",
          "densify", "regrow_sheared", "six_share", "snapshot", "restore")
METHODS = ("advance", "settle", "place", "flow_respace", "relax_window")


def main() -> None:
    reps = int(sys.argv[1]) if len(sys.argv) > 1 else 5
    ref = analyze(hex_exemplar())
    kw = case_kwargs("hexflow", ref)
    grow(ref, rng=1, relax=True, **kw)
    spent: collections.Counter = collections.Counter()
    calls: collections.Counter = collections.Counter()
    active: collections.Counter = collections.Counter()

    def wrap(name, fn):
        def timed(*a, **k):
            key = name + (" band" if name == "relax_network" and (len(a) > 1 or k.get("band") is not None) else "")
            if active[key]:
                return fn(*a, **k)
            active[key] += 1
            c = time.process_time()
            try:
                return fn(*a, **k)
            finally:
                spent[key] += time.process_time() - c
                calls[key] += 1
                active[key] -= 1
        return timed

    for name in PASSES:
        setattr(_growth, name, wrap(name, getattr(_growth, name)))
    G = _growth._Grower
    for meth in METHODS:
        setattr(G, meth, wrap(meth, getattr(G, meth)))
    total = 0.0
    for _ in range(reps):
        c = time.process_time()
        out = grow(ref, rng=1, relax=True, **kw)
        total += time.process_time() - c
    print(f"{len(out)} elements, {total / reps:.3f} CPU s per growth ({len(out) * reps / total:.0f} el/CPU-s); inclusive shares:")
    for name, s in spent.most_common():
        print(f"{100 * s / total:5.1f}% {s / reps:.3f} s  {name} ({calls[name] / reps:g} calls)")


if __name__ == "__main__":
    main()
