"""Helper s34p (issue 13 point 1): where a rare kind's copies go missing in synth's output.

    PYTHONPATH=src:benchmarks python benchmarks/s34p_probe.py CLASS:H:V SEEDS RARE

Prints the exemplar's size classes, anchors and parents per kind; for each seed the output's
count per kind against the exemplar's share (kind count / all), and for the RARE kind: which
exemplar elements (by source index, with their distance to the frame) its output copies come
from, and how many output elements copy each exemplar element of each kind.
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
import shapely
from grow_variants import _harder_suite
from synth_variants import _harder

from strew import Region
from strew.synth import new_state, fill

spec, seeds, rare = sys.argv[1], [int(x) for x in sys.argv[2].split(",")], sys.argv[3]
name, i, v = spec.split(":")
ex = _harder_suite().make_exemplar(name, rng=int(v), **_harder()[name][int(i)])
kn = np.asarray(ex.kind_names)
xy = np.asarray(ex.xy)
g = ex.region.geometry
depth = shapely.distance(g.boundary, shapely.points(xy))
x0, y0, x1, y1 = ex.region.bounds
for seed in seeds:
    st = new_state(ex, Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed)
    p = st.prep
    assert np.allclose(p.pos, xy), "prep order differs from the exemplar's"
    if seed == seeds[0]:
        names = list(p.shapes) if not hasattr(p, "kind_names") else p.kind_names
        print("exemplar counts", {k: int((kn == k).sum()) for k in sorted(set(kn))})
        print("size_class", np.unique(p.size_class, return_counts=True), "anchors", int(np.sum(getattr(__import__('strew.synth._grow', fromlist=['anchors']), 'anchors')(p))))
        for k in range(int(p.kind.max()) + 1):
            m = p.kind == k
            print(f" kind {k}: n={m.sum()} r={np.median(p.r[m]):.2f} rc={np.median(p.rc[m]):.2f} rbar={np.median(p.rbar[m]):.1f} cls={np.unique(p.size_class[m])} parent>=0 {np.sum(p.parent[m]>=0)} parent-3 {np.sum(p.parent[m]==-3)}")
    fill(st)
    src = st._src[: st.n]
    kk = p.kind[src]
    print(f"seed {seed}: n={st.n}", {int(k): int((kk == k).sum()) for k in np.unique(kk)})
    rk = int(np.bincount(p.kind).argmin())
    ids = np.flatnonzero(p.kind == rk)
    cnt = np.bincount(src, minlength=len(p.kind))
    print("  rare exemplar elements: idx, depth, copies:", [(int(j), round(float(depth[j]) if j < len(depth) else -1, 1), int(cnt[j])) for j in ids])
    for k in np.unique(p.kind):
        c = cnt[p.kind == k]
        print(f"  kind {k}: copies per exemplar element mean {c.mean():.2f} median {np.median(c):.1f} zero {np.sum(c == 0)}/{len(c)}")
