"""Issue 14 point 2 (helper flow14k): render a flow case's defects.

Grows one flow case of ``benchmarks/grow.py --structure`` and draws its elements,
the interior sites failing the six-neighbour test (red: fewer than six within 1.15
spacings, blue: more or one too near) and the Delaunay 5s and 7s; writes a PNG.

    python benchmarks/flow14k_render.py corner /tmp/flow14k/corner.png [flow_densify_rounds=None ...]

(``corner``: 90 degrees, 30 x 20 spacings, start 2,18; ``centre90``, ``bottom90``,
``big90``, ``qc30``, ``qc45``, ``qc_a``, ``qc_b``, ``scales90``: see ``case``; the
optional ``name=value`` pairs replace GrowParams fields.)
"""

from __future__ import annotations

import ast
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))


def case(name: str):
    from grow import _suite_exemplar

    from strew import Region
    from strew.fields import flow_field

    ex = _suite_exemplar("hex_lattice", nx=8, ny=8)
    sp = 12.0
    th = np.linspace(0, np.pi / 2, 30)

    def turning(deg, w):
        def field(p):
            a = np.radians(deg) * np.clip(np.asarray(p)[:, 0] / w, 0, 1)
            return np.c_[np.cos(a), np.sin(a)]
        return field

    if name in ("corner", "centre90", "bottom90", "t90"):
        w, h = 30 * sp, 20 * sp
        start = {"corner": (2 * sp, 18 * sp), "centre90": None, "bottom90": (15 * sp, 2 * sp), "t90": None}[name]
        return ex, sp, Region.rectangle(w, h), turning(90.0, w), start
    if name == "big90":
        w, h = 45 * sp, 30 * sp
        return ex, sp, Region.rectangle(w, h), turning(90.0, w), None
    if name in ("qc45", "qc30", "qc_a", "qc_b"):
        f = 1.5 if name == "qc45" else 1.0
        a = 30 * sp * f
        af = flow_field([np.c_[r * np.cos(th), r * np.sin(th)] for r in (a / 3, a * 5 / 6)])
        start = {"qc45": None, "qc30": None, "qc_a": (a - 2 * sp, a - 2 * sp), "qc_b": (2 * sp, 2 * sp)}[name]
        return ex, sp, Region.rectangle(a, a), af, start
    if name == "scales90":
        from scipy.spatial import cKDTree
        sc = _suite_exemplar("scales")
        s = float(np.median(cKDTree(sc.xy).query(sc.xy, 7)[0][:, 1:]))
        return sc, s, Region.rectangle(30 * s, 20 * s), turning(90.0, 30 * s), None
    raise SystemExit(f"unknown case {name}")


def grow_with(ex, region, field, start, **over):
    """grow in flow mode with ``over`` replacing GrowParams fields (experiments)."""
    import dataclasses

    import strew.grow as sg
    from strew.grow import _growth

    orig = _growth.grow_reference

    def patched(ref, params, **kw):
        return orig(ref, dataclasses.replace(params, **over), **kw)

    sg.grow_reference = patched
    try:
        return sg.grow(ex, region=region, mode="flow", flow=field, rng=1, start=start)
    finally:
        sg.grow_reference = orig


def render(out, region, sp, path, title=""):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from scipy.spatial import Delaunay, cKDTree

    xy = out.xy
    inner = region.distance_to_boundary(xy) > 2 * sp
    t = cKDTree(xy)
    hi = np.asarray(t.query_ball_point(xy, 1.15 * sp, return_length=True)) - 1
    lo = np.asarray(t.query_ball_point(xy, 0.85 * sp, return_length=True)) - 1
    ok = (hi == 6) & (lo == 0)
    s = Delaunay(xy).simplices
    e = np.unique(np.sort(np.r_[s[:, [0, 1]], s[:, [1, 2]], s[:, [0, 2]]], axis=1), axis=0)
    ln = np.hypot(*(xy[e[:, 0]] - xy[e[:, 1]]).T)
    e = e[ln < 1.6 * sp]
    deg = np.bincount(e.ravel(), minlength=len(xy))
    fig, ax = plt.subplots(figsize=(14, 14 * (np.ptp(xy[:, 1]) + 1) / (np.ptp(xy[:, 0]) + 1)))
    ln = np.hypot(*(xy[e[:, 0]] - xy[e[:, 1]]).T)
    for (a, b), l in zip(e, ln):
        c = "0.8" if 0.85 * sp <= l <= 1.15 * sp else ("orange" if l > 1.15 * sp else "purple")
        ax.plot(xy[[a, b], 0], xy[[a, b], 1], color=c, lw=0.6)
    col = np.where(~inner, "0.6", np.where(ok, "k", np.where(hi < 6, "red", "blue")))
    ax.scatter(xy[:, 0], xy[:, 1], c=col, s=8)
    m5 = inner & (deg == 5)
    m7 = inner & (deg == 7)
    ax.scatter(xy[m5, 0], xy[m5, 1], facecolors="none", edgecolors="green", s=60)
    ax.scatter(xy[m7, 0], xy[m7, 1], facecolors="none", edgecolors="magenta", s=60, marker="s")
    ax.set_aspect("equal")
    ax.set_title(f"{title} six {ok[inner].mean():.3f}")
    print(f"six {ok[inner].mean():.3f}, stretched {((hi < 6) & (lo == 0) & inner).sum()}, 5s {(m5).sum()}, 7s {(m7).sum()}")
    fig.savefig(path, dpi=80, bbox_inches="tight")


if __name__ == "__main__":
    from strew.grow import grow

    name, path = sys.argv[1], sys.argv[2]
    kw = dict(a.split("=") for a in sys.argv[3:])
    kw = {k: ast.literal_eval(v) for k, v in kw.items()}
    ex, sp, region, field, start = case(name)
    t0 = time.process_time()
    out = grow_with(ex, region, field, start, **kw)
    print(f"{name}: {len(out)} elements, {time.process_time() - t0:.1f} s cpu")
    render(out, region, sp, path, f"{name} {kw}")
