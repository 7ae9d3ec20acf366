"""Helper fspeed14j: profile and hash of grow's ``hexflow`` case (benchmarks/grow.py --against).

Run: ``python benchmarks/fspeed14j_profile.py [profile|hash] [relax 0|1]``. ``hash`` prints the
sha256 of the output positions and angles, CPU seconds and elements/CPU-s; ``profile`` prints the
top 30 cProfile entries by cumulative and by own time.
"""

from __future__ import annotations

import cProfile
import hashlib
import pstats
import sys
import time

import numpy as np

from strew import Region
from strew.grow import analyze, grow
from strew.grow._exemplars import hex_exemplar, stone_exemplar, tile_exemplar


def case(name: str, relax: bool):
    ex = {"stones": stone_exemplar, "tiles": tile_exemplar, "hex": hex_exemplar, "hexflow": hex_exemplar}[name]()
    ref = analyze(ex)
    grow(ref, count=50, rng=1)
    kw = dict(count=2000)
    if name == "hexflow":
        sp = ref.mean_edge
        w = 30 * sp

        def field(p):
            a = np.radians(90.0) * np.clip(np.asarray(p)[:, 0] / w, 0, 1)
            return np.c_[np.cos(a), np.sin(a)]

        kw = dict(region=Region.rectangle(w, 20 * sp), mode="flow", flow=field)
    return lambda: grow(ref, rng=1, relax=relax, **kw)


def digest(out) -> str:
    h = hashlib.sha256()
    for a in (out.xy, out.rotation, out.scale, out.kind):
        h.update(np.ascontiguousarray(np.asarray(a)).tobytes())
    return h.hexdigest()[:16]


if __name__ == "__main__":
    what = sys.argv[1] if len(sys.argv) > 1 else "hash"
    relax = (sys.argv[2] if len(sys.argv) > 2 else "1") == "1"
    names = sys.argv[3].split(",") if len(sys.argv) > 3 else ["hexflow"]
    for name in names:
        fn = case(name, relax)
        if what == "profile":
            pr = cProfile.Profile(time.process_time)
            pr.enable()
            out = fn()
            pr.disable()
            st = pstats.Stats(pr)
            st.sort_stats("cumulative").print_stats(35)
            st.sort_stats("tottime").print_stats(25)
        else:
            c = time.process_time()
            out = fn()
            c = time.process_time() - c
            print(name, "relax", int(relax), len(out), digest(out), f"{c:.3f}s", f"{len(out) / c:.0f} el/cpu-s")
