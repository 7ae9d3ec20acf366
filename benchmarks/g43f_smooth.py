"""g43f: issue 14 point 2 on smooth and sharp flow fields, measured on main's grow.

Fields over a square of ``n`` spacings (``--field``):

- ``qc``: the held-out family of ``benchmarks/flow14p_heldout.py`` (two quarter circles
  about the corner, radii n/3 and 5n/6: a 90 degree turn, the turn per spacing 1/n);
- ``arc``: a gentle arc: two concentric arcs about a centre 2n spacings below the
  square's middle (radii 2n + n/4 and 2n + 3n/4), turning about 28 degrees across it;
- ``sine``: a wave: two strokes y = n/3, 2n/3 + 0.06 n sin(2 pi x / n) (one period
  across the square, the rows swinging +-21 degrees, both ways).

Per case (start: ``c`` = the default, or a corner 2 spacings in): the interior
(over 2 spacings in) six share (``grow.py``'s ``hex_share``), holes
(``lattice_defects``), elements whose shape is not within the region
(``Region.contains_geometry``, tolerance 1e-9), the 5-7 dislocation cores
(``g42f_cores.py``'s count: a Delaunay five with a seven beside, bonds < 1.3
spacings) and how many of them have another core within 2 spacings (clustered), the
largest group of non-six sites (``lattice_defects``), the Nye cap (1 - 2 N / interior
sites, N = the integral of |grad theta| over the interior / b: a lattice following the
field exactly, each dislocation costing its 5 and its 7; ``g42f_nye.py``), whether the
lattice follows the field (``grow.py``'s ``field_misalignment``: the turn of the
lattice's six-fold bond direction from the field, median / 90th percentile, degrees,
wrapped to +-30; with the field's own turn over the interior, degrees) and CPU s.

    PYTHONPATH=src python benchmarks/g43f_smooth.py --field qc --sizes 32 --kind hex --rng 1 [--starts c,2:2] [--json F] [--save DIR]
    PYTHONPATH=src python benchmarks/g43f_smooth.py --nye-only --field qc --sizes 16,20,24,32,40,48
"""
import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import grow as gb  # noqa: E402

from strew import Region  # noqa: E402
from strew.fields import flow_field  # noqa: E402


def make_field(kind: str, n: int, sp: float):
    aa = n * sp
    if kind == "qc":
        th = np.linspace(0, np.pi / 2, 30)
        return flow_field([np.c_[r * np.cos(th), r * np.sin(th)] for r in (aa / 3, aa * 5 / 6)])
    if kind == "arc":
        c = np.array([aa / 2, -2 * aa])
        strokes = []
        for r in (2 * aa + aa / 4, 2 * aa + 3 * aa / 4):
            h = np.arcsin(min(1.0, 0.75 * aa / r))  # the arc spans the square's width and a bit
            th = np.linspace(np.pi / 2 + h, np.pi / 2 - h, 30)
            strokes.append(c + np.c_[r * np.cos(th), r * np.sin(th)])
        return flow_field(strokes)
    if kind == "sine":
        x = np.linspace(-0.1 * aa, 1.1 * aa, 60)
        A = 0.06 * aa
        return flow_field([np.c_[x, y0 + A * np.sin(2 * np.pi * x / aa)] for y0 in (aa / 3, 2 * aa / 3)])
    raise SystemExit(f"unknown field {kind}")


def nye_cap(kind: str, n: int) -> tuple[float, float]:
    """(N, six cap) over the interior for a hexagonal lattice of spacing 1 (g42f_nye.py)."""
    af = make_field(kind, n, 1.0)
    h = 0.05
    g = np.arange(2 + h / 2, n - 2, h)
    X, Y = np.meshgrid(g, g, indexing="ij")
    d = np.asarray(af(np.c_[X.ravel(), Y.ravel()]))
    t = np.arctan2(d[:, 1], d[:, 0]).reshape(X.shape)
    tx = np.angle(np.exp(2j * (np.roll(t, -1, 0) - np.roll(t, 1, 0)))) / 2 / (2 * h)
    ty = np.angle(np.exp(2j * (np.roll(t, -1, 1) - np.roll(t, 1, 1)))) / 2 / (2 * h)
    gr = np.hypot(tx, ty)[1:-1, 1:-1]
    nd = float(gr.sum() * h * h)
    nint = (n - 4) ** 2 * 2 / np.sqrt(3)
    return nd, 1 - 2 * nd / nint


def cores(xy: np.ndarray, sp: float, inner: np.ndarray) -> dict:
    """5-7 cores as g42f_cores.py counts them, and their clustering within 2 spacings."""
    from scipy.spatial import Delaunay, cKDTree

    tri = Delaunay(xy)
    ind, nb = tri.vertex_neighbor_vertices
    nbrs = [[j for j in nb[ind[i]:ind[i + 1]] if np.hypot(*(xy[j] - xy[i])) < 1.3 * sp] for i in range(len(xy))]
    cnt = np.array([len(v) for v in nbrs])
    five = np.flatnonzero(inner & (cnt == 5))
    seven = np.flatnonzero(inner & (cnt == 7))
    other = int((inner & (cnt != 6) & (cnt != 5) & (cnt != 7)).sum())
    P = []
    for i in five:
        for j in nbrs[i]:
            if cnt[j] == 7:
                P.append(0.5 * (xy[i] + xy[j]))
                break
    P = np.array(P).reshape(-1, 2)
    lone_five = len(five) - len(P)
    if len(P) > 1:
        d, _ = cKDTree(P).query(P, 2)
        clustered = int((d[:, 1] < 2 * sp).sum())
    else:
        clustered = 0
    return dict(fives=len(five), sevens=len(seven), other_deg=other, cores=len(P), lone_fives=lone_five, clustered_cores=clustered)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--field", default="qc", choices=("qc", "arc", "sine"))
    ap.add_argument("--sizes", default="32")
    ap.add_argument("--kind", default="hex", choices=("hex", "scales"))
    ap.add_argument("--rng", type=int, default=1)
    ap.add_argument("--starts", default="", help="comma list of c or i:j (spacings); default the five")
    ap.add_argument("--json", default="")
    ap.add_argument("--save", default="", help="folder for the outputs' xy (.npy)")
    ap.add_argument("--nye-only", action="store_true")
    a = ap.parse_args()
    sizes = [int(s) for s in a.sizes.split(",")]
    if a.nye_only:
        for n in sizes:
            nd, cap = nye_cap(a.field, n)
            print(f"{a.field} n={n}: N {nd:5.1f} six cap {cap:.3f}", flush=True)
        return
    from strew.grow import grow

    if a.kind == "scales":
        from scipy.spatial import cKDTree

        ex = gb._suite_exemplar("scales")
        sp = float(np.median(cKDTree(ex.xy).query(ex.xy, 7)[0][:, 1:]))
    else:
        ex = gb._suite_exemplar("hex_lattice", nx=8, ny=8)
        sp = 12.0
    res = {}
    for n in sizes:
        aa = n * sp
        region = Region.rectangle(aa, aa)
        af = make_field(a.field, n, sp)
        nd, cap = nye_cap(a.field, n)
        if a.starts:
            sts = [None if s == "c" else tuple(int(v) for v in s.split(":")) for s in a.starts.split(",")]
        else:
            sts = [None, (2, 2), (n - 2, n - 2), (2, n - 2), (n - 2, 2)]
        for st in sts:
            s = None if st is None else (st[0] * sp, st[1] * sp)
            t0 = time.process_time()
            out = grow(ex, region=region, mode="flow", flow=af, rng=a.rng, start=s)
            dt = time.process_time() - t0
            xy = out.xy
            inner = region.distance_to_boundary(xy) > 2 * sp
            x0, y0, x1, y1 = region.bounds
            grid = np.mgrid[x0 + 2 * sp : x1 - 2 * sp : 3.0, y0 + 2 * sp : y1 - 2 * sp : 3.0].reshape(2, -1).T
            d = gb.lattice_defects(xy, sp, inner, grid)
            across = int((~np.asarray(region.contains_geometry(out.geometry, tolerance=1e-9))).sum())
            c = cores(xy, sp, inner)
            c.update(gb.field_misalignment(ex, xy, sp, inner, af))
            fa = np.asarray(af(xy[inner]))
            fa = np.degrees(np.unwrap(2 * np.arctan2(fa[:, 1], fa[:, 0])) / 2)
            c["field_turn_deg"] = float(np.ptp(fa))
            name = f"{a.field}{n}_{'c' if st is None else '%d,%d' % st}_{a.kind}_r{a.rng}"
            res[name] = dict(n=len(out), inner=int(inner.sum()), six=gb.hex_share(xy, sp, inner), holes=d["holes"], across=across,
                             largest_defect_group=d["largest_defect_group"], isolated_defect_share=d["isolated_defect_share"],
                             nye_N=nd, nye_cap=cap, cpu=dt, **c)
            r = res[name]
            print(f"{name:22s} n={r['n']} six={r['six']:.4f} cap={cap:.3f} holes={r['holes']} across={across} "
                  f"cores={c['cores']} clustered={c['clustered_cores']} 5/7/other={c['fives']}/{c['sevens']}/{c['other_deg']} "
                  f"largest_grp={r['largest_defect_group']} iso={r['isolated_defect_share']:.2f} "
                  f"lag med/p90={c['misalign_deg_median']:.1f}/{c['misalign_deg_p90']:.1f} field_turn={c['field_turn_deg']:.0f} cpu={dt:.1f}", flush=True)
            if a.save:
                Path(a.save).mkdir(parents=True, exist_ok=True)
                np.save(Path(a.save) / f"{name}.npy", xy)
            if a.json:
                json.dump(res, open(a.json, "w"), indent=1)


if __name__ == "__main__":
    main()
