"""g60f: hexflow cases of grow_hashes.py (90 degree field, relax on/off) one by one: element
count, digest, CPU s (process time), after a warm-up (the 20-spacing case, relax on).
Run from a tree's root: PYTHONPATH=src:benchmarks python benchmarks/g60f_hexflow.py [REPEATS]"""
import sys
import time

import numpy as np

from grow_hashes import digest
from strew import Region
from strew.grow import analyze
from strew.grow._exemplars import hex_exemplar


def main():
    reps = int(sys.argv[1]) if len(sys.argv) > 1 else 1
    ref = analyze(hex_exemplar())
    sp = ref.mean_edge

    def run(W, relax):
        w = W * sp

        def field(p, w=w):
            a = np.radians(90.0) * np.clip(np.asarray(p)[:, 0] / w, 0, 1)
            return np.c_[np.cos(a), np.sin(a)]

        from strew.grow import grow
        t = time.process_time()
        out = grow(ref, rng=1, relax=relax, region=Region.rectangle(w, W * 2 / 3 * sp), mode="flow", flow=field)
        return len(out), digest(out), time.process_time() - t

    run(20, True)
    for W in (20, 30, 45):
        for relax in (True, False):
            ts = []
            for _ in range(reps):
                n, h, c = run(W, relax)
                ts.append(c)
            print(f"hexflow {W} relax {relax}: n={n} {h} cpu min {min(ts):.2f} all {' '.join(f'{x:.2f}' for x in ts)}", flush=True)


main()
