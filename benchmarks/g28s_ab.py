"""In-process A/B timing of one grower method: this tree's against another tree's copy
of the same mixin module (task g28s).

Loads ``OTHER/src/strew/grow/MODULE.py`` as a second module of this package, and grows
the same output (the two must be byte-identical) with the method taken from each in
turn, ``--repeat`` times, so that both run in one process on the same machine state (a
shared machine varies by 10-15 % between processes). Prints the best CPU seconds of
the whole growth and of the method, for each.

Run: ``PYTHONPATH=src python benchmarks/g28s_ab.py /tmp/main_tree _relax_window _RelaxWindow relax_window stones 2000 5``
"""

from __future__ import annotations

import importlib.util
import sys
import time
from pathlib import Path


def main() -> None:
    from strew.grow import _growth, analyze, grow
    from strew.grow._exemplars import hex_exemplar, stone_exemplar, tile_exemplar

    other, mod, cls_name, meth, name, n, repeat = sys.argv[1:8]
    path = Path(other) / "src" / "strew" / "grow" / f"{mod}.py"
    spec = importlib.util.spec_from_file_location(f"strew.grow.{mod}_other", path)
    m = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = m
    spec.loader.exec_module(m)
    fns = {"this": getattr(_growth._Grower, meth), "other": getattr(getattr(m, cls_name), meth)}
    spent = [0.0]
    ref = analyze({"stones": stone_exemplar, "tiles": tile_exemplar, "hex": hex_exemplar}[name]())
    grow(ref, count=50, rng=1)
    best: dict[str, tuple[float, float]] = {}
    for _ in range(int(repeat)):
        for k, fn in fns.items():
            def wrapped(*a, fn=fn, **kw):
                c = time.process_time()
                try:
                    return fn(*a, **kw)
                finally:
                    spent[0] += time.process_time() - c

            setattr(_growth._Grower, meth, wrapped)
            spent[0] = 0.0
            c = time.process_time()
            grow(ref, count=int(n), rng=1, relax=True)
            t = time.process_time() - c
            b = best.get(k, (t, spent[0]))
            best[k] = (min(b[0], t), min(b[1], spent[0]))
    for k, (t, s) in best.items():
        print(f"{k}: total {t:.3f} s, {meth} {s:.3f} s")


if __name__ == "__main__":
    main()
