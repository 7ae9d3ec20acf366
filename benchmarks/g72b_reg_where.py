"""Helper g72b: where a lattice row's regularity misses lie, grow (relax on / off) against the
exemplar's own generator drawn at the output's size (svar13i's oracle): the exemplar's and
result's regularity, the misses by kind (neighbour count fewer / more / offsets off), by
distance to the region's edge (units of s), and their clustering (connected groups of misses
within 1.3 s: isolated defects or a seam).

    PYTHONPATH=src:benchmarks python benchmarks/g72b_reg_where.py bricks:v45 1-6 [--no-relax] [--oracle]
"""
import math
import sys

import numpy as np
import shapely
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from _runner import fidelity_suite
from fresh17_rows import exemplar
from svar13i_oracle import big_params

from strew import Region, _fidelity
from strew.grow import grow
from strew.metrics import fidelity

CALLS = []
_orig = _fidelity._lattice_match


def _spy(sm, tree, s, tpl):
    r = _orig(sm, tree, s, tpl)
    CALLS.append((sm, tree, s, tpl, r))
    return r


_fidelity._lattice_match = _spy


def run_grow(ex, seed, **kw):
    x0, y0, x1, y1 = ex.region.bounds
    scale = 3.5
    for _ in range(2):
        out = grow(ex, region=Region.rectangle(scale * (x1 - x0), scale * (y1 - y0)), mode="fixed", rng=seed, **kw)
        if len(out) >= 10 * len(ex):
            break
        scale *= 1.05 * math.sqrt(10 * len(ex) / max(len(out), 1))
    return out


def describe(tag, ex, out):
    CALLS.clear()
    rep = fidelity(ex, out, eq5=False, local=False)
    m = rep.metrics["regularity"]
    sm, tree, s, tpl, ok = CALLS[-1]
    edge = shapely.distance(sm.region.boundary, shapely.points(sm.xy))
    valid = (edge >= _fidelity.LATTICE_REACH * s + 0.5 * s) & shapely.contains_xy(sm.window, sm.xy[:, 0], sm.xy[:, 1])
    inner = np.flatnonzero(valid)
    bad = inner[~ok[inner]]
    if len(bad):
        loc, cnt = _fidelity._local_offsets(sm, tree, s, tpl[0], bad)
    else:
        loc, cnt = np.zeros((0, tpl[0] + 1, 2)), np.zeros(0, int)
    fewer, more = int(np.sum(cnt < tpl[0])), int(np.sum(cnt > tpl[0]))
    off = len(bad) - fewer - more
    # distance to edge of misses vs all, in s
    eb = edge[bad] / s
    ei = edge[inner] / s
    bins = [0, 3, 6, 10, 1e9]
    hb = np.histogram(eb, bins)[0]
    hi = np.histogram(ei, bins)[0]
    share = " ".join(f"[{bins[k]:g},{bins[k+1]:g})s:{hb[k]}/{hi[k]}={hb[k]/max(hi[k],1):.3f}" for k in range(len(bins) - 1))
    # clusters of misses
    comp = ""
    if len(bad):
        t = cKDTree(sm.xy[bad])
        pairs = t.query_pairs(_fidelity.LATTICE_REACH * s, output_type="ndarray")
        from scipy.sparse import coo_matrix

        g = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(len(bad), len(bad))) if len(pairs) else coo_matrix((len(bad), len(bad)))
        nc, lab = connected_components(g, directed=False)
        sizes = np.sort(np.bincount(lab))[::-1]
        comp = f"groups {nc} sizes {sizes[:8].tolist()}"
    print(f"{tag}: n={len(out)} regularity res {m.result:.4f} ex {m.exemplar:.4f} deficit {m.value:.4f}/{m.tolerance:.3f} {'pass' if m.passed else 'FAIL'}; "
          f"interior {len(inner)} miss {len(bad)}: fewer {fewer} more {more} offsets {off}; {comp}", flush=True)
    print(f"    misses by edge distance: {share}", flush=True)
    # the neighbours of the over-count misses that match no template slot (local frame, units of s)
    extra = []
    for row in loc[cnt > tpl[0]]:
        row = row[np.isfinite(row[:, 0])]
        dd = np.hypot(row[:, None, 0] - tpl[1][None, :, 0], row[:, None, 1] - tpl[1][None, :, 1]).min(axis=1)
        extra.extend((row[dd > _fidelity.LATTICE_MATCH * s] / s).tolist())
    if extra:
        e = np.round(np.array(extra), 2)
        u, c = np.unique(np.round(e, 1), axis=0, return_counts=True)
        top = np.argsort(-c)[:6]
        print(f"    template (count {tpl[0]}, s {s:.2f}) offsets/s {np.round(tpl[1] / s, 2).tolist()}", flush=True)
        print(f"    extra neighbours {len(e)}: commonest offsets/s {[(u[k].tolist(), int(c[k])) for k in top]}", flush=True)
    return sm, s, tpl, bad


def main():
    spec, seeds = sys.argv[1], _variants.ints(sys.argv[2])
    flags = sys.argv[3:]
    mk = fidelity_suite()
    cls, label = spec.split(":")
    ex = exemplar(mk, cls, label)
    for seed in seeds:
        out = run_grow(ex, seed)
        sm, s, tpl, bad = describe(f"grow seed {seed}", ex, out)
        np.save(f"/tmp/g72b/bad_{cls}_{label}_{seed}.npy", sm.xy[bad])
        if "--no-relax" in flags:
            describe(f"grow seed {seed} relax=False", ex, run_grow(ex, seed, relax=False))
    if "--oracle" in flags:
        v = int(label[1:])
        big = big_params(cls, {}, 3.5)
        for d in range(2):
            describe(f"oracle draw {d}", ex, mk.make_exemplar(cls, rng=v + 1000 * d, **big))


if __name__ == "__main__":
    main()
