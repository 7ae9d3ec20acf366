"""g42f: the dislocations a hexagonal lattice needs to follow the held-out quarter-circle
field exactly (Nye: edge-dislocation density |grad theta| / b, b = one spacing), over the
interior (2 spacings in from the region's edge) of each held-out square, and the six
share that leaves if each dislocation costs its two core sites (a 5 and a 7), for the
lattice turning all of the field's turn or a share of it (main's lattice turns about
0.44-0.56 of it: g34f_frame_lag.md).

    PYTHONPATH=src python benchmarks/g42f_nye.py
"""
import numpy as np
from strew.fields import flow_field

th = np.linspace(0, np.pi / 2, 30)
sp = 1.0
for n in (16, 20, 24):
    aa = n * sp
    af = flow_field([np.c_[r * np.cos(th), r * np.sin(th)] for r in (aa / 3, aa * 5 / 6)])
    h = 0.05
    g = np.arange(2 + h / 2, n - 2, h)
    X, Y = np.meshgrid(g, g, indexing="ij")
    P = np.c_[X.ravel(), Y.ravel()]
    d = np.asarray(af(P)); t = np.arctan2(d[:, 1], d[:, 0]).reshape(X.shape)
    # gradient of the direction (mod pi), by central differences of the unwrapped angle
    tx = np.angle(np.exp(2j * (np.roll(t, -1, 0) - np.roll(t, 1, 0)))) / 2 / (2 * h)
    ty = np.angle(np.exp(2j * (np.roll(t, -1, 1) - np.roll(t, 1, 1)))) / 2 / (2 * h)
    gr = np.hypot(tx, ty)[1:-1, 1:-1]
    nd = float(gr.sum() * h * h)  # dislocations, b = 1 spacing
    nint = (n - 4) ** 2 * 2 / np.sqrt(3)  # interior sites of a hexagonal lattice
    line = " ".join(f"turn {f:.2f}: N {f * nd:5.1f} six <= {1 - 2 * f * nd / nint:.3f}" for f in (1.0, 0.75, 0.5))
    print(f"n={n}: interior sites {nint:.0f}, |grad th| mean {gr.mean():.3f}/sp; {line}")
