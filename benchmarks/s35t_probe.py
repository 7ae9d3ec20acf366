"""Helper s35t (issue 13 point 1): per exemplar element of one kind, its depth, parent and output copies.

    PYTHONPATH=src:benchmarks python benchmarks/s35t_probe.py CLASS:H:V SEEDS KIND

For each seed (output 3.5x the exemplar's side, as the audit): counts per kind, and for KIND's
exemplar elements sorted by depth: depth to the frame, parent (index; -3 cut, -1 none), its
follow flag, the parent's depth, and copies in the output; copies per element grouped by depth band.
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
import shapely
from grow_variants import _harder_suite
from synth_variants import _harder

from strew import Region
from strew.synth import new_state, fill

spec, seeds, want = sys.argv[1], [int(x) for x in sys.argv[2].split(",")], sys.argv[3]
name, i, v = spec.split(":")
ex = _harder_suite().make_exemplar(name, rng=int(v), **_harder()[name][int(i)])
kn = np.asarray(ex.kind_names)
xy = np.asarray(ex.xy)
depth = shapely.distance(ex.region.geometry.boundary, shapely.points(xy))
x0, y0, x1, y1 = ex.region.bounds
for seed in seeds:
    st = new_state(ex, Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed)
    p = st.prep
    assert np.allclose(p.pos, xy)
    fill(st)
    src = st._src[: st.n]
    cnt = np.bincount(src, minlength=len(p.kind))
    print(f"seed {seed}: n={st.n}", {k: int(np.sum(kn[src] == k)) for k in sorted(set(kn))},
          "copies/element", {k: round(float(cnt[kn == k].mean()), 2) for k in sorted(set(kn))})
    ids = np.flatnonzero(kn == want)
    ids = ids[np.argsort(depth[ids])]
    rows = [(int(j), round(float(depth[j]), 1), int(p.parent[j]), round(float(depth[p.parent[j]]), 1) if p.parent[j] >= 0 else None, int(cnt[j])) for j in ids]
    print("  (idx, depth, parent, parent depth, copies):", rows)
    for lo, hi in ((0, 15), (15, 30), (30, 60), (60, 1e9)):
        m = (depth[ids] >= lo) & (depth[ids] < hi)
        if m.any():
            print(f"  depth [{lo},{hi}): {m.sum()} elements, copies mean {cnt[ids[m]].mean():.2f}, zero {np.sum(cnt[ids[m]] == 0)}")
    par = p.parent[ids]
    for lab, m in (("parent>=0", par >= 0), ("parent -3", par == -3), ("parent -1", par == -1)):
        if m.any():
            print(f"  {lab}: {m.sum()} elements, copies mean {cnt[ids[m]].mean():.2f}")
    # pebbles per parent stone in exemplar vs output copies of the stone
    sk = np.flatnonzero(p.parent >= 0)
    kids = np.bincount(p.parent[sk], minlength=len(p.kind))
    st_ids = np.flatnonzero(kids > 0)
    print("  children per parent: mean", round(float(kids[st_ids].mean()), 2), "parents", len(st_ids), "of", int(np.sum(kn == kn[st_ids[0]])))
