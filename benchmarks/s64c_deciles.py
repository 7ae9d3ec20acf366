"""Helper s64c: signed nn deciles (output minus exemplar, in units of s), density ratios and the
clusters' ring shape (dots per disc, ring radii, stray dots) for ``--varied`` rows of synth (labels pIsV),
to tell too near / too far and what the rings look like; optionally renders exemplar and output as PNG.

    PYTHONPATH=src:benchmarks python benchmarks/s64c_deciles.py clusters:p4s38 1,2 [--png PREFIX]
"""
import sys

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
import strew._fidelity as F
from _runner import fidelity_suite
from fresh17_rows import exemplar
from synth_variants import run
from strew.metrics import fidelity

CAP = []
_orig = F._discrepancies


def _wrap(a, b, kinds, s, **kw):
    CAP.append((a, b, kinds, s))
    return _orig(a, b, kinds, s, **kw)


F._discrepancies = _wrap


def ring_shape(arr, tag):
    """Per disc: dots within 1.6 ring radii assigned to their nearest disc; ring radii, dots per ring, stray dots."""
    P = np.c_[arr.x, arr.y]
    disc, dot = P[arr.kind == 0], P[arr.kind == 1]
    td = cKDTree(disc)
    d, j = td.query(dot)
    hubs_nn = cKDTree(disc).query(disc, k=2)[0][:, 1]
    per = np.bincount(j[d < 25.0], minlength=len(disc))
    tdot = cKDTree(dot)
    dd = tdot.query(dot, k=2)[0][:, 1]
    print(f"   {tag}: discs {len(disc)} dots {len(dot)}  dot-to-nearest-disc deciles {np.percentile(d, np.arange(0, 101, 10)).round(2)}")
    print(f"   {tag}: stray dots (> 25 from any disc) {int(np.sum(d >= 25.0))}; dots per disc hist {np.bincount(per).tolist()}")
    print(f"   {tag}: dot nn deciles {np.percentile(dd, np.arange(0, 101, 10)).round(2)}")
    print(f"   {tag}: disc nn deciles {np.percentile(hubs_nn, np.arange(0, 101, 10)).round(2)}")
    return d, dd


def render(arr, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PatchCollection
    from matplotlib.patches import Circle

    P = np.c_[arr.x, arr.y]
    x0, y0, x1, y1 = arr.region.bounds
    fig, ax = plt.subplots(figsize=(8, 8 * (y1 - y0) / (x1 - x0)), dpi=110)
    radii = {0: arr.shapes[arr.kinds[0]].radius, 1: arr.shapes[arr.kinds[1]].radius}
    for k, col in ((0, "#c0504d"), (1, "#d9a21b")):
        pc = PatchCollection([Circle(p, radii[k] * (s if np.ndim(arr.scale) else 1.0)) for p, s in zip(P[arr.kind == k], np.asarray(arr.scale)[arr.kind == k])], facecolor=col, edgecolor="none")
        ax.add_collection(pc)
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def main():
    np.set_printoptions(precision=2, suppress=True, linewidth=200)
    png = sys.argv[sys.argv.index("--png") + 1] if "--png" in sys.argv else None
    mk = fidelity_suite()
    for spec in sys.argv[1].split(","):
        cls, label = spec.split(":")
        ex = exemplar(mk, cls, label)
        print(f"== {spec} exemplar counts", {k: int(np.sum(ex.kind == j)) for j, k in enumerate(ex.kinds)}, "frame", ex.region.bounds, flush=True)
        ring_shape(ex, "exemplar")
        if png:
            render(ex, f"{png}_exemplar.png")
        for seed in _variants.ints(sys.argv[2]):
            CAP.clear()
            out, _ = run(ex, 3.5, seed, None)
            rep = fidelity(ex, out, eq5=False, local=False)
            a, b, kinds, s = CAP[0]
            print(f" seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} s={s:.2f} counts", {k: int(np.sum(out.kind == j)) for j, k in enumerate(out.kinds)})
            for k, name in enumerate(kinds):
                print(f"   density[{name}] out/ex = {a.density[k] / b.density[k]:.3f}")
            for p in range(len(kinds)):
                for q in range(len(kinds)):
                    m = rep.metrics[f"nn[{kinds[p]}>{kinds[q]}]"]
                    print(f"   nn[{kinds[p]}>{kinds[q]}] {m.value:.3f}/{m.tolerance:.3f}  ex deciles/s {b.nn[p, q] / s}  out-ex {(a.nn[p, q] - b.nn[p, q]) / s}", flush=True)
            ring_shape(out, f"output s{seed}")
            if png:
                render(out, f"{png}_out_s{seed}.png")


if __name__ == "__main__":
    main()
