"""In-process A/B of grow speed changes (issue 14 point 5): this tree's grow with the base
tree's versions of the changed methods swapped in, in turns.

The base tree's ``grow/_place.py``, ``grow/_index.py`` and ``grow/_collide.py`` (first
argument: its ``src`` folder) are loaded as modules of this tree's package
(``strew.grow._place_base``, ...) and their ``_Place.place``, ``GrowIndex._index_edge``
and ``_Collide.too_close_in_kind`` replace this tree's for the base rounds. Rounds alternate which goes first; CPU seconds
(``time.process_time``) per growth, the median ratio this/base, and the digests of both
outputs (they must be equal).

Run: ``PYTHONPATH=src python benchmarks/spd14x_inproc.py /work/main/src stones 2000 12 1``
(base src, exemplar stones|tiles|hex, count, rounds, relax 1|0).
"""

from __future__ import annotations

import hashlib
import importlib.util
import statistics
import sys
import time
from pathlib import Path

import numpy as np
import shapely

from strew.grow import analyze, grow
from strew.grow._exemplars import hex_exemplar, stone_exemplar, tile_exemplar

#: (module, class, method) of this tree's changes
CHANGED = [("_place", "_Place", "place"), ("_index", "GrowIndex", "_index_edge"), ("_collide", "_Collide", "too_close_in_kind")]


def _base_module(src: str, name: str):
    spec = importlib.util.spec_from_file_location(f"strew.grow.{name}_base", Path(src) / "strew" / "grow" / f"{name}.py")
    mod = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = mod
    spec.loader.exec_module(mod)
    return mod


def _use(fns) -> None:
    for (mod, cls, meth), f in fns.items():
        setattr(getattr(importlib.import_module(f"strew.grow.{mod}"), cls), meth, f)


def main() -> None:
    src, name = sys.argv[1], sys.argv[2]
    n, rounds, relax = int(sys.argv[3]), int(sys.argv[4]), sys.argv[5] == "1"
    ref = analyze({"stones": stone_exemplar, "tiles": tile_exemplar, "hex": hex_exemplar}[name]())
    fns = {
        "base": {k: getattr(getattr(_base_module(src, k[0]), k[1]), k[2]) for k in CHANGED},
        "this": {k: getattr(getattr(importlib.import_module(f"strew.grow.{k[0]}"), k[1]), k[2]) for k in CHANGED},
    }

    def digest(out):
        return hashlib.sha1(np.ascontiguousarray(out.xy).tobytes() + b"".join(shapely.to_wkb(np.asarray(out.geometry)))).hexdigest()[:12]

    for f in fns.values():
        _use(f)
        grow(ref, count=50, rng=1)
    cpu: dict[str, list[float]] = {"base": [], "this": []}
    dg: dict[str, set[str]] = {"base": set(), "this": set()}
    for r in range(rounds):
        order = ["base", "this"] if r % 2 == 0 else ["this", "base"]
        for lab in order:
            _use(fns[lab])
            c = time.process_time()
            out = grow(ref, count=n, rng=1, relax=relax)
            cpu[lab].append(time.process_time() - c)
            dg[lab].add(digest(out))
    _use(fns["this"])
    ratios = [a / b for a, b in zip(cpu["this"], cpu["base"])]
    mb, mt = statistics.median(cpu["base"]), statistics.median(cpu["this"])
    print(f"{name} {n} relax {'on' if relax else 'off'}, {rounds} rounds: median CPU s base {mb:.3f} ({n / mb:.0f} el/s), "
          f"this {mt:.3f} ({n / mt:.0f} el/s); ratio of medians {mt / mb:.3f}, median ratio {statistics.median(ratios):.3f}; "
          f"outputs equal: {dg['base'] == dg['this'] and len(dg['this']) == 1}")
    print("ratios this/base by round:", " ".join(f"{r:.3f}" for r in ratios))


if __name__ == "__main__":
    main()
