"""Helper seam13f diagnostic (issue 13 point 2): three sizes at 50x the exemplar's area,
each window of the local fidelity map with its size-class counts, score and worst metric,
next to the same figures for fresh draws of the exemplar's generator at 50x (the judge's
calibration, ``benchmarks/fidelity_calibration.py``), which pass every window.

    python benchmarks/seam13f_diag.py [--seeds 1,2,3,4] [--set NAME=VALUE ...]
        [--calib 0,11] [--render DIR] [--name three_sizes] [--json PATH]
        [--gen 7 --params '{"counts": [220, 50, 26]}']   (a variant of the class)

``--set`` sets a module constant of ``strew.synth._grow`` (as ``seam13d_diag.py``).
Printed per seed: failing windows, worst, each failing window's counts and metric, the
windows' mean and standard deviation of each class's count, and the correlation of the
large count with the nn[small>large] discrepancy.
"""
import argparse
import json
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _runner import SKIPPED, fidelity_suite  # noqa: E402

import strew.synth._grow as G  # noqa: E402
from strew import Region  # noqa: E402
from strew.metrics import fidelity  # noqa: E402
from strew.synth import synthesize  # noqa: E402


def windows(ex, out, region):
    rep = fidelity(ex, out, region, eq5=False)
    L = rep.local
    S = np.asarray(L["score"], float)
    W = np.asarray(L["worst_metric"], dtype=object)
    kinds = list(ex.kinds)
    pos = out.xy
    kind = np.asarray(out.kind)
    side, step = L["window"], L["step"]
    rows = []
    for (i, j), s in np.ndenumerate(S):
        if not np.isfinite(s):
            continue
        wx, wy = L["x0"] + j * step, L["y0"] + i * step
        m = (pos[:, 0] >= wx) & (pos[:, 0] < wx + side) & (pos[:, 1] >= wy) & (pos[:, 1] < wy + side)
        rows.append(dict(i=i, j=j, score=float(s), metric=str(W[i, j]), counts=np.bincount(kind[m], minlength=len(kinds)).tolist(),
                         bounds=(wx, wy, wx + side, wy + side)))
    return rep, rows


def summary(tag, rows, kinds):
    c = np.array([r["counts"] for r in rows], float)
    sc = np.array([r["score"] for r in rows])
    nf = int((sc > 1).sum())
    print(f"{tag}: failing {nf}/{len(rows)} worst {sc.max():.3f}; counts mean {c.mean(0).round(1)} sd {c.std(0).round(2)}")
    for r in rows:
        if r["score"] > 1:
            print(f"   win({r['i']},{r['j']}) {r['score']:.2f} {r['metric']} counts {r['counts']}")
    return nf


def render(path, ex, out, rows, title):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Circle, Rectangle

    fail = [r for r in rows if r["score"] > 1]
    if not fail:
        return
    kind = np.asarray(out.kind)
    rad = np.array([out.shapes[k].radius for k in out.kinds])[kind] * np.asarray(out.scale)
    col = np.array(["tab:blue", "tab:green", "tab:red", "k"])
    fig, axes = plt.subplots(1, len(fail), figsize=(6 * len(fail), 6), squeeze=False)
    for ax, r in zip(axes[0], fail):
        x0, y0, x1, y1 = r["bounds"]
        pad = 0.25 * (x1 - x0)
        m = (out.xy[:, 0] > x0 - pad) & (out.xy[:, 0] < x1 + pad) & (out.xy[:, 1] > y0 - pad) & (out.xy[:, 1] < y1 + pad)
        for p, rr, k in zip(out.xy[m], rad[m], kind[m]):
            ax.add_patch(Circle(p, rr, color=col[k]))
        ax.add_patch(Rectangle((x0, y0), x1 - x0, y1 - y0, fill=False, ec="k", lw=2))
        ax.set_xlim(x0 - pad, x1 + pad)
        ax.set_ylim(y0 - pad, y1 + pad)
        ax.set_aspect("equal")
        ax.set_title(f"({r['i']},{r['j']}) {r['score']:.2f} {r['metric']} {r['counts']}", fontsize=9)
    fig.suptitle(title)
    fig.savefig(path, dpi=50)
    plt.close(fig)


def main() -> None:
    if "--quick" in sys.argv[1:]:
        print("seam13f_diag: skipped: a diagnostic run at 50x (minutes)")
        sys.exit(SKIPPED)
    ap = argparse.ArgumentParser()
    ap.add_argument("--name", default="three_sizes")
    ap.add_argument("--seeds", default="1,2,3,4")
    ap.add_argument("--set", action="append", default=[])
    ap.add_argument("--calib", default="")
    ap.add_argument("--calib-k", type=float, default=50.0, help="--calib: the draws' area over the exemplar's")
    ap.add_argument("--render", default=None)
    ap.add_argument("--scale", type=float, default=7.07)
    ap.add_argument("--json", default=None)
    ap.add_argument("--gen", type=int, default=None, help="the exemplar's generator seed (a variant, as synth_variants.py's p<i>s<seed>)")
    ap.add_argument("--params", default=None, help="the generator's parameters as JSON (synth_variants.py's params)")
    ap.add_argument("--quick", action="store_true")
    a = ap.parse_args()
    for kv in a.set:
        k, v = kv.split("=")
        cur = getattr(G, k)
        setattr(G, k, (v == "1") if isinstance(cur, bool) else type(cur)(float(v)))
    mk = fidelity_suite()
    ex = mk.make_exemplar(a.name, rng=a.gen, **(json.loads(a.params) if a.params else {}))
    kinds = list(ex.kinds)
    print("exemplar counts", np.bincount(np.asarray(ex.kind), minlength=len(kinds)).tolist(), kinds)
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(a.scale * (x1 - x0), a.scale * (y1 - y0))
    res = {}
    tot = 0
    for seed in [int(s) for s in a.seeds.split(",") if s]:
        t = time.process_time()
        out = synthesize(ex, region, rng=seed, measure=False)
        t = time.process_time() - t
        rep, rows = windows(ex, out, region)
        tot += summary(f"synth s{seed} n={len(out)} cpu={t:.0f}s", rows, kinds)
        res[f"synth_s{seed}"] = rows
        if a.render:
            os.makedirs(a.render, exist_ok=True)
            render(f"{a.render}/{a.name}_s{seed}.png", ex, out, rows, f"synth seed {seed}")
    if a.calib:
        sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
        from fidelity_calibration import larger

        for seed in [int(s) for s in a.calib.split(",")]:
            draw = larger(a.name, seed, a.calib_k)
            rep, rows = windows(ex, draw, None)
            summary(f"calibration draw seed {seed} n={len(draw)}", rows, kinds)
            res[f"calib_s{seed}"] = rows
    print("total failing (synth)", tot)
    if a.json:
        with open(a.json, "w") as f:
            json.dump(res, f)


if __name__ == "__main__":
    main()
