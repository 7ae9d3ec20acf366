"""cProfile of one ``strew.grow`` run with relaxation (task g28s, issue 14 point 5).

Cases: ``fixed`` -- CASE exemplar (stones, tiles, hex), ``count`` elements, fixed mode;
``hexflow`` -- the hexagonal lattice in flow mode along a field turning 90 degrees over a
region ``W`` spacings wide (two thirds as high), as ``benchmarks/grow.py --against``.
The numba kernels are compiled or loaded by a small growth before the profile.

Run: ``PYTHONPATH=src python benchmarks/g28s_profile.py fixed stones 3000 OUT.txt``
or ``PYTHONPATH=src python benchmarks/g28s_profile.py hexflow hex 30 OUT.txt``
(writes the top 30 by cumulative and by own CPU time to OUT.txt).
"""

from __future__ import annotations

import cProfile
import io
import pstats
import sys
import time

import numpy as np


def main() -> None:
    from strew import Region
    from strew.grow import analyze, grow
    from strew.grow._exemplars import hex_exemplar, stone_exemplar, tile_exemplar

    mode, name, n, path = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
    ex = {"stones": stone_exemplar, "tiles": tile_exemplar, "hex": hex_exemplar}[name]()
    ref = analyze(ex)
    grow(ref, count=50, rng=1)
    if mode == "hexflow":
        sp = ref.mean_edge
        w = n * sp

        def field(p):
            a = np.radians(90.0) * np.clip(np.asarray(p)[:, 0] / w, 0, 1)
            return np.c_[np.cos(a), np.sin(a)]

        kw = dict(region=Region.rectangle(w, 2 * n / 3 * sp), mode="flow", flow=field)
    else:
        kw = dict(count=n)
    pr = cProfile.Profile(time.process_time)  # CPU time: the machine is shared
    c = time.process_time()
    pr.enable()
    out = grow(ref, rng=1, relax=True, **kw)
    pr.disable()
    cpu = time.process_time() - c
    s = io.StringIO()
    s.write(f"{mode} {name} {n}: {len(out)} elements, {cpu:.2f} CPU s under the profiler\n")
    for key in ("cumulative", "tottime"):
        pstats.Stats(pr, stream=s).sort_stats(key).print_stats(30)
    with open(path, "w") as f:
        f.write(s.getvalue())
    print(s.getvalue()[:200])


if __name__ == "__main__":
    main()
