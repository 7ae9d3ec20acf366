"""Helper s70h: where the stones stand relative to the pebbles (issue 13 point 1, nn[pebble>stone]).

For two-size rows (labels as s67h_probe: pIsV --varied, hIsV --harder), seed(s): the
exemplar, synth with s69h's density rule off and on, and the exemplar's own generator at
the output's size (svar13i_oracle's draw). Per arrangement, inside the frame shrunk by
2 s (s: the exemplar's median nn): stone density, pebble->stone nn deciles (Hanisch, in s),
the same with the stone labels drawn at random among all elements (same count: a clump
ratio > 1 means stones stand in fewer, denser places than random labelling), stone->stone
median nn, pebbles within 1.5 s of a stone's edge per stone, and the index of dispersion of
stone counts in cells of 6 s. Then the judge's verdict and its nn[pebble>stone].

    PYTHONPATH=src:benchmarks python benchmarks/s70h_diag.py two_sizes:p2s33,two_sizes:p2s34 1
"""
import sys

import numpy as np
import shapely
from scipy.spatial import cKDTree

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from _runner import fidelity_suite
from grow_variants import _harder_suite
from svar13i_oracle import big_params
from synth_variants import _harder, run

import strew._fidelity as FD
import strew.synth._grow as G
from strew.metrics import fidelity


def params(cls, label):
    i, _, v = label[1:].partition("s")
    if label.startswith("h"):
        return _harder_suite(), _harder()[cls][int(i)], int(v)
    sets = _variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, [])
    return fidelity_suite(), sets[int(i)], int(v)


def describe(arr, s, rng):
    kinds = list(arr.kinds)
    names = np.array(kinds)[arr.kind]
    rad = np.array([arr.shapes[k].radius for k in kinds])[arr.kind] * arr.scale
    big = rad > np.median(rad) * 1.3 if "stone" not in kinds else names == "stone"
    xy = arr.xy
    region = arr.region.geometry if hasattr(arr.region, "geometry") else arr.region
    inner = region.buffer(-2 * s)
    ins = shapely.contains_xy(inner, xy[:, 0], xy[:, 1])
    to_edge = shapely.distance(region.boundary, shapely.points(xy))
    st, pb = np.flatnonzero(big), np.flatnonzero(~big)

    def p2s(stones):
        d = cKDTree(xy[stones]).query(xy[pb])[0]
        ok = ins[pb] & (d <= to_edge[pb])
        return np.quantile(d[ok], np.linspace(0.1, 0.9, 9)) / s

    q = p2s(st)
    qr = np.mean([p2s(rng.choice(len(xy), len(st), replace=False)) for _ in range(10)], axis=0)
    ds = cKDTree(xy[st]).query(xy[st], k=2)[0][:, 1]
    dens = float(np.sum(ins[st])) / inner.area * s * s
    # pebbles near each interior stone (centre within stone radius + 1.5 s)
    tp = cKDTree(xy[pb])
    sti = st[ins[st]]
    near = np.array([len(tp.query_ball_point(xy[i], rad[i] + 1.5 * s)) for i in sti])
    pdens = float(np.sum(ins[pb])) / inner.area
    exp = pdens * np.pi * (rad[sti] + 1.5 * s) ** 2
    x0, y0, x1, y1 = inner.bounds
    c = 6 * s
    ix = ((xy[sti, 0] - x0) // c).astype(int)
    iy = ((xy[sti, 1] - y0) // c).astype(int)
    nx, ny = int((x1 - x0) // c), int((y1 - y0) // c)
    m = (ix < nx) & (iy < ny)
    cnt = np.bincount(iy[m] * nx + ix[m], minlength=nx * ny)
    disp = float(cnt.var() / max(cnt.mean(), 1e-9)) if nx * ny > 1 else float("nan")
    return dict(n=len(xy), nst=len(st), share=len(st) / len(xy), dens=dens, q=q, qr=qr, clump=float(np.median(q / qr)),
                ss=float(np.median(ds)) / s, near=float(np.mean(near) / np.mean(exp)), disp=disp)


def line(tag, d, ex=None):
    extra = ""
    if ex is not None:
        extra = f" dq/s={np.mean(np.abs(d['q'] - ex['q'])):.3f} dens/ex={d['dens'] / ex['dens'] - 1:+.3f}"
    return (f"  {tag:7s} n={d['n']:5d} stones={d['nst']:4d} share={d['share']:.3f} dens={d['dens']:.4f}/s2"
            f" p>s deciles[10,50,90]={d['q'][0]:.2f},{d['q'][4]:.2f},{d['q'][8]:.2f} random-label={d['qr'][0]:.2f},{d['qr'][4]:.2f},{d['qr'][8]:.2f}"
            f" clump={d['clump']:.3f} s>s med={d['ss']:.2f} pebbles-near-stone/exp={d['near']:.3f} disp6s={d['disp']:.2f}{extra}")


if __name__ == "__main__":
    np.set_printoptions(precision=3, suppress=True, linewidth=220)
    modes = (sys.argv[3] if len(sys.argv) > 3 else "off,on,oracle").split(",")
    for spec in sys.argv[1].split(","):
        cls, label = spec.split(":")
        mk, kw, v = params(cls, label)
        ex = mk.make_exemplar(cls, rng=v, **kw)
        vis = FD._visible(ex)
        s = FD._median_nn(ex.xy[vis])
        rng = np.random.default_rng(0)
        e = describe(ex, s, rng)
        print(f"== {spec} s={s:.2f}", flush=True)
        print(line("exemplar", e), flush=True)
        for seed in _variants.ints(sys.argv[2]):
            for mode in modes:
                if mode == "oracle":
                    if seed != _variants.ints(sys.argv[2])[0]:
                        continue
                    out = mk.make_exemplar(cls, rng=v, **big_params(cls, kw, 3.5))
                else:
                    G._TWO_CLASS_AREA = mode == "on"
                    out, _ = run(ex, 3.5, seed, None)
                rep = fidelity(ex, out, eq5=False, local=False)
                m = rep.metrics.get("nn[pebble>stone]")
                fails = [f"{k}={x.value:.3g}/{x.tolerance:.3g}" for k, x in rep.metrics.items() if x.applicable and not x.passed]
                print(line(f"{mode}{'' if mode == 'oracle' else seed}", describe(out, s, rng), e)
                      + f" | judge {'pass' if rep.faithful else 'FAIL'} nn[p>s]={m.value:.3f}/{m.tolerance:.3f} {' '.join(fails)}", flush=True)
