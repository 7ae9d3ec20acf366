"""Elements of tiled ornament worlds (benchmarks/hie15_make.py) by the phase of the tile
holding them (2 x 2 phases) and distance to the nearest tile line (bins 0-4-8-12-16-20-25),
summed over seeds: benchmarks/w26_phase_bins.py for any tile size (helper w27h).

``python benchmarks/w27h_phase_bins.py TAG,TAG,... SEED,SEED,... [TILE]`` (TILE default 48)
"""
import sys

import numpy as np

R = "benchmarks/results/orn19m_%s.npz"
bins = [0, 4, 8, 12, 16, 20, 25]
T = float(sys.argv[3]) if len(sys.argv) > 3 else 48.0
for tag in sys.argv[1].split(","):
    tot = np.zeros((4, 6), int)
    for s in sys.argv[2].split(","):
        d = np.load(R % f"{tag}_s{s}_T{T:g}")
        x, y = np.asarray(d["x"]), np.asarray(d["y"])
        i = np.clip((x // T).astype(int), 0, 3)
        j = np.clip((y // T).astype(int), 0, 3)
        ph = (j % 2) * 2 + i % 2
        dd = np.minimum(np.abs((x + T / 2) % T - T / 2), np.abs((y + T / 2) % T - T / 2))
        for p in range(4):
            tot[p] += np.histogram(dd[ph == p], bins=bins)[0]
    print(tag, len(x), " | ".join(f"ph{p} {tot[p].sum()} {tot[p].tolist()}" for p in range(4)))
