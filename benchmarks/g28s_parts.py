"""CPU seconds of one ``strew.grow`` run and of chosen grower methods within it (task g28s).

Each named method of the grower (``_nudge``, ``relax_window``, ...) is wrapped with a
CPU-time accumulator, so that two trees whose growth is byte-identical (the same calls in
the same order) can be compared part by part on a shared machine, where whole-run
timings vary by 10-15 %. The best of ``--repeat`` runs is kept for each figure.

Run: ``PYTHONPATH=src python benchmarks/g28s_parts.py stones 2000 _nudge,relax_window``
(exemplar stones, tiles, hex or hexflow (30 spacings); count; methods), once per tree.
"""

from __future__ import annotations

import sys
import time

import numpy as np


def main() -> None:
    from strew import Region
    from strew.grow import _growth, analyze, grow
    from strew.grow._exemplars import hex_exemplar, stone_exemplar, tile_exemplar

    name, n = sys.argv[1], int(sys.argv[2])
    names = sys.argv[3].split(",") if len(sys.argv) > 3 else []
    repeat = int(sys.argv[4]) if len(sys.argv) > 4 else 3
    spent = {m: 0.0 for m in names}
    cls = _growth._Grower
    for m in names:
        fn = getattr(cls, m)

        def wrapped(*a, fn=fn, m=m, **kw):
            c = time.process_time()
            try:
                return fn(*a, **kw)
            finally:
                spent[m] += time.process_time() - c

        setattr(cls, m, wrapped)
    ref = analyze({"stones": stone_exemplar, "tiles": tile_exemplar, "hex": hex_exemplar, "hexflow": hex_exemplar}[name]())
    grow(ref, count=50, rng=1)
    kw = dict(count=n)
    if name == "hexflow":
        sp = ref.mean_edge
        w = n * sp

        def field(p):
            a = np.radians(90.0) * np.clip(np.asarray(p)[:, 0] / w, 0, 1)
            return np.c_[np.cos(a), np.sin(a)]

        kw = dict(region=Region.rectangle(w, 2 * n / 3 * sp), mode="flow", flow=field)
        grow(ref, rng=1, region=Region.rectangle(6 * sp, 4 * sp), mode="flow", flow=field)
    best: dict[str, float] = {}
    for _ in range(repeat):
        for m in names:
            spent[m] = 0.0
        c = time.process_time()
        out = grow(ref, rng=1, relax=True, **kw)
        row = {"total": time.process_time() - c, **spent}
        best = {k: min(v, best.get(k, v)) for k, v in row.items()}
    print(name, n, len(out), " ".join(f"{k}={v:.3f}" for k, v in best.items()))


if __name__ == "__main__":
    main()
