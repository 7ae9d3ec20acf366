"""In-process A/B of grow speed changes to ``_Place.place`` (issue 14 point 5): this
tree's grow with the base tree's ``place`` swapped in, in turns.

The base tree's ``grow/_place.py`` (first argument: its ``src`` folder) is loaded as a
module of this tree's package (``strew.grow._place_base``) and its ``_Place.place``
replaces this tree's for the base rounds. Rounds alternate which goes first; CPU seconds
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

import strew.grow._place as gp
from strew.grow import analyze, grow
from strew.grow._exemplars import hex_exemplar, stone_exemplar, tile_exemplar


def base_place(src: str):
    spec = importlib.util.spec_from_file_location("strew.grow._place_base", Path(src) / "strew" / "grow" / "_place.py")
    mod = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = mod
    spec.loader.exec_module(mod)
    return mod._Place.place


def main() -> None:
    src, name = sys.argv[1], sys.argv[2]
    n, rounds, relax = int(sys.argv[3]), int(sys.argv[4]), sys.argv[5] == "1"
    ref = analyze({"stones": stone_exemplar, "tiles": tile_exemplar, "hex": hex_exemplar}[name]())
    fns = {"base": base_place(src), "this": gp._Place.place}

    def digest(out):
        return hashlib.sha1(np.ascontiguousarray(out.xy).tobytes() + b"".join(shapely.to_wkb(np.asarray(out.geometry)))).hexdigest()[:12]

    for f in fns.values():
        gp._Place.place = f
        grow(ref, count=50, rng=1)
    cpu: dict[str, list[float]] = {"base": [], "this": []}
    dg: dict[str, set[str]] = {"base": set(), "this": set()}
    for r in range(rounds):
        order = ["base", "this"] if r % 2 == 0 else ["this", "base"]
        for lab in order:
            gp._Place.place = fns[lab]
            c = time.process_time()
            out = grow(ref, count=n, rng=1, relax=relax)
            cpu[lab].append(time.process_time() - c)
            dg[lab].add(digest(out))
    gp._Place.place = fns["this"]
    ratios = [a / b for a, b in zip(cpu["this"], cpu["base"])]
    mb, mt = statistics.median(cpu["base"]), statistics.median(cpu["this"])
    print(f"{name} {n} relax {'on' if relax else 'off'}, {rounds} rounds: median CPU s base {mb:.3f} ({n / mb:.0f} el/s), "
          f"this {mt:.3f} ({n / mt:.0f} el/s); ratio of medians {mt / mb:.3f}, median ratio {statistics.median(ratios):.3f}; "
          f"outputs equal: {dg['base'] == dg['this'] and len(dg['this']) == 1}")


if __name__ == "__main__":
    main()
