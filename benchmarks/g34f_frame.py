"""g34f: where the flow-mode lattice lags the field (issue 14 point 2): per element, along the
growth, the angle between its placed frame (the reference ring's rotation ``th``) and the
field at its position, the carry and the fit's clamp, and the lattice's own orientation
(six-fold mean of its bonds, hexagonal exemplars) at placement, after the growth (first
relaxation window at the end, before the flow passes) and in the output; binned by the
angle ``phi`` from the start's radius about the quarter circles' centre and by creation
quintile.

    PYTHONPATH=src python benchmarks/g34f_frame.py [--n 20] [--start c|X,Y] [--scales] [--set grow.NAME=V ...] [--npz F]

The held-out case of ``benchmarks/flow14p_heldout.py`` (hexagons, or ``--scales``) over a
square of ``--n`` spacings; ``--set`` sets a GrowParams field (``p.NAME``) or a module
constant (``MODULE.NAME``).
"""

import argparse
import importlib
import math
import sys
from pathlib import Path

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, str(Path(__file__).resolve().parent))

import grow as gb  # noqa: E402

from strew import Region  # noqa: E402
from strew.fields import flow_field  # noqa: E402
from strew.grow import _growth  # noqa: E402
from strew.grow import grow  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument("--n", type=int, default=20)
ap.add_argument("--start", default="c")
ap.add_argument("--scales", action="store_true")
ap.add_argument("--set", nargs="*", default=[])
ap.add_argument("--npz", default="")
a = ap.parse_args()

if a.scales:
    ex = gb._suite_exemplar("scales")
    sp = float(np.median(cKDTree(ex.xy).query(ex.xy, 7)[0][:, 1:]))
else:
    ex = gb._suite_exemplar("hex_lattice", nx=8, ny=8)
    sp = 12.0
n = a.n
aa = n * sp
th = np.linspace(0, np.pi / 2, 30)
region = Region.rectangle(aa, aa)
af = flow_field([np.c_[r * np.cos(th), r * np.sin(th)] for r in (aa / 3, aa * 5 / 6)])
st = None if a.start == "c" else tuple(float(v) * sp for v in a.start.split(","))
start = np.array(st if st is not None else (aa / 2, aa / 2))

gp_over = {}
for kv in a.set:
    k, v = kv.split("=")
    m, k = k.split(".")
    if m == "p":
        gp_over[k] = eval(v, {"inf": math.inf, "None": None})
        continue
    mod = importlib.import_module("strew.grow." + m)
    setattr(mod, k, type(getattr(mod, k))(eval(v, {"inf": math.inf})))
    print("set", mod.__name__, k, getattr(mod, k))
if gp_over:
    import dataclasses

    orig_init = _growth.GrowParams.__init__

    def init(self, *args, **kw):
        orig_init(self, *args, **kw)
        for k, v in gp_over.items():
            object.__setattr__(self, k, v)

    _growth.GrowParams.__init__ = init
    print("set GrowParams", gp_over)

REC = []  # (s, x, y, th, field, n placed nb, lattice angle of bonds to placed nb)
SNAP = {}
G = _growth._Grower
orig_place = G.place
orig_settle = G.settle


def six_angle(v, ref):
    """Six-fold mean angle of bond vectors ``v`` relative to ``ref`` (deg, in -30..30)."""
    if len(v) == 0:
        return math.nan
    t = np.arctan2(v[:, 1], v[:, 0])
    return math.degrees(np.angle(np.exp(6j * (t - ref)).mean())) / 6


def bonds_at(self, s, x, y):
    nb = [o for o in self.adj[s] if self.state[o] == _growth.ELEMENT and o != s]
    bv = np.array([[self.xy[o][0] - x, self.xy[o][1] - y] for o in nb]).reshape(-1, 2)
    if len(bv):
        d = np.hypot(bv[:, 0], bv[:, 1])
        bv = bv[(d > 0.7 * sp) & (d < 1.3 * sp)]
    return bv


def place(self, s, a_, k, th_, reach=None):
    x0_, y0_ = self.xy[s]
    ok = orig_place(self, s, a_, k, th_, reach)
    if ok:
        x, y = self.xy[s]
        v = self.p.flow(np.array([[x, y]]))[0]
        f = math.atan2(v[1], v[0])
        nb = [o for o in self.adj[s] if self.state[o] == _growth.ELEMENT and o != s]
        bv = np.array([[self.xy[o][0] - x, self.xy[o][1] - y] for o in nb]).reshape(-1, 2)
        if len(bv):
            d = np.hypot(bv[:, 0], bv[:, 1])
            bv = bv[(d > 0.7 * sp) & (d < 1.3 * sp)]
        REC.append((s, x, y, th_, f, len(self._last_nb), six_angle(bv, f), six_angle(bonds_at(self, s, x0_, y0_), f),
                    math.hypot(x - x0_, y - y0_) / sp))
    return ok


def settle(self):
    orig_settle(self)
    if "grown" not in SNAP:
        SNAP["grown"] = (list(self.order), np.array([self.xy[o] for o in self.order]))


G.place = place
G.settle = settle

out = grow(ex, region=region, mode="flow", flow=af, rng=1, start=st)
inner = region.distance_to_boundary(out.xy) > 2 * sp
x0, y0, x1, y1 = region.bounds
grid = np.mgrid[x0 + 2 * sp : x1 - 2 * sp : 3.0, y0 + 2 * sp : y1 - 2 * sp : 3.0].reshape(2, -1).T
d = gb.lattice_defects(out.xy, sp, inner, grid)
print(f"case n={n} start={a.start} {'scales' if a.scales else 'hex'}: elements {len(out)} six {gb.hex_share(out.xy, sp, inner):.4f} holes {d['holes']}")


def wrap(x, per):
    return (x + per / 2) % per - per / 2


def lattice_of(xy):
    """Six-fold orientation of each point's bonds (0.85-1.15 sp) minus the field there (deg)."""
    t = cKDTree(xy)
    dd, ii = t.query(xy, 7)
    v = af(xy)
    fa = np.arctan2(v[:, 1], v[:, 0])
    out_ = np.full(len(xy), np.nan)
    for q in range(len(xy)):
        ok = (dd[q, 1:] < 1.15 * sp) & (dd[q, 1:] > 0.85 * sp)
        if ok.sum() < 4:
            continue
        b = xy[ii[q, 1:][ok]] - xy[q]
        out_[q] = six_angle(b, fa[q])
    return out_


R = np.array(REC, dtype=float)
xy = R[:, 1:3]
frame = np.degrees(wrap(R[:, 3] - R[:, 4], math.pi))  # th - field (a line field: mod 180)
lat_place = R[:, 6]
lat_seed = R[:, 7]  # the same bonds from where the seed stood, before _fit_position / _nudge
ring_lag = wrap(frame, 60.0)  # the frame as a hexagon's orientation
phi0 = math.degrees(math.atan2(start[1], start[0]))
phi = np.degrees(np.arctan2(xy[:, 1], xy[:, 0])) - phi0
inn = region.distance_to_boundary(xy) > 2 * sp
order_s, grown_xy = SNAP.get("grown", ([], np.zeros((0, 2))))
lat_grown_all = lattice_of(grown_xy) if len(grown_xy) else np.zeros(0)
pos_in_grown = {o: q for q, o in enumerate(order_s)}
lat_grown = np.array([lat_grown_all[pos_in_grown[int(s)]] if int(s) in pos_in_grown else np.nan for s in R[:, 0]])
lat_out = lattice_of(np.asarray(out.xy))
# the output's elements matched to the placements by nearest position (passes add/move elements)
tq = cKDTree(np.asarray(out.xy))
dq, iq = tq.query(grown_xy if len(grown_xy) else xy)
print(f"placements {len(R)}; clamped (|th - field| >= max_turn - 0.01 deg): {np.mean(np.abs(frame) >= 9.99):.3f}")
print("columns: frame = th - field at the element (deg); lat@place = its bonds to placed neighbours at placement,"
      " lat@grown = after the growth (before flow passes), lat@out = output; all minus the field, six-fold, mean (|p90|)")
bins = [(-50, -30), (-30, -15), (-15, -5), (-5, 5), (5, 15), (15, 30), (30, 50)]
if st is not None and min(st) < 3 * sp:
    bins = [(-50, -30), (-30, -15), (-15, -5), (-5, 5), (5, 15), (15, 30), (30, 50)]


def cell(v):
    v = v[np.isfinite(v)]
    if len(v) == 0:
        return "      -       "
    return f"{np.mean(v):6.1f} ({np.percentile(np.abs(v), 90):4.1f})"


print(f"{'phi bin':>11s} {'n':>4s}  {'frame':>13s}  {'lat@seed':>13s}  {'lat@place':>13s}  {'lat@grown':>13s}  fit move (sp)")
for lo, hi in bins:
    m = inn & (phi >= lo) & (phi < hi)
    print(f"{lo:5d}..{hi:4d} {m.sum():4d}  {cell(frame[m])}  {cell(lat_seed[m])}  {cell(lat_place[m])}  {cell(lat_grown[m])}  {np.mean(R[m, 8]) if m.any() else 0:.3f}")
mo = (region.distance_to_boundary(out.xy) > 2 * sp)
pho = np.degrees(np.arctan2(np.asarray(out.xy)[:, 1], np.asarray(out.xy)[:, 0])) - phi0
print("output:", "  ".join(f"{lo}..{hi}: {cell(lat_out[mo & (pho >= lo) & (pho < hi)])}" for lo, hi in bins))
qs = np.array_split(np.arange(len(R)), 5)
print("by creation quintile (inner):")
for k, q in enumerate(qs):
    m = np.zeros(len(R), bool)
    m[q] = True
    m &= inn
    print(f"  q{k + 1}: frame {cell(frame[m])}  lat@place {cell(lat_place[m])}  lat@grown {cell(lat_grown[m])}  nb {np.mean(R[m, 5]):.1f}")
# lag as a share of the field's turn: regress the lattice's angle against phi
for name, v in (("frame", frame), ("lat@seed", lat_seed), ("lat@place", lat_place), ("lat@grown", lat_grown)):
    m = inn & np.isfinite(v) & (np.abs(phi) < 50)
    if m.sum() > 5:
        slope = np.polyfit(phi[m], v[m], 1)[0]
        print(f"  {name:10s}: d(angle - field)/d(phi) = {slope:+.3f} (lattice turns {1 + slope:.2f} of the field's turn)")
m = mo & np.isfinite(lat_out) & (np.abs(pho) < 50)
print(f"  {'output':10s}: d(angle - field)/d(phi) = {np.polyfit(pho[m], lat_out[m], 1)[0]:+.3f}")
if a.npz:
    np.savez(a.npz, rec=R, grown=grown_xy, out=np.asarray(out.xy), sp=sp, aa=aa, start=start)
