"""Helper seam13d diagnostic (issue 13 point 2): synth at 50x the area, the local
fidelity map's failing windows with their class counts, worst metric and the distance
from each small element to its nearest large one (against the exemplar's quantiles).

    python benchmarks/seam13d_diag.py three_sizes 1,2 [--set NAME=VALUE ...] [--render DIR]
"""
import argparse, os, sys, time

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _runner import SKIPPED, fidelity_suite  # noqa: E402

import strew.synth._grow as G  # noqa: E402
from strew import Region  # noqa: E402
from strew.metrics import fidelity  # noqa: E402
from strew.synth import fill, new_state  # noqa: E402


def main() -> None:
    if "--quick" in sys.argv[1:]:
        print("seam13d_diag: skipped: a diagnostic of one class and seeds given as positional NAME SEEDS, which have no default")
        sys.exit(SKIPPED)
    ap = argparse.ArgumentParser()
    ap.add_argument("name")
    ap.add_argument("seeds")
    ap.add_argument("--set", action="append", default=[])
    ap.add_argument("--render", default=None)
    ap.add_argument("--scale", type=float, default=7.07)
    ap.add_argument("--quick", action="store_true", help="run_all.py's check: skips (the positional arguments have no default)")
    a = ap.parse_args()
    for kv in a.set:
        k, v = kv.split("=")
        setattr(G, k, type(getattr(G, k))(float(v)) if not isinstance(getattr(G, k), bool) else v == "1")
    mk = fidelity_suite()
    ex = mk.make_exemplar(a.name)
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(a.scale * (x1 - x0), a.scale * (y1 - y0))
    tot = 0
    for seed in [int(s) for s in a.seeds.split(",")]:
        st = new_state(ex, region, rng=seed)
        hole = {}
        orig = G.fill_holes

        def fh(state, *aa, **kk):
            n0 = state.n
            r = orig(state, *aa, **kk)
            hole["range"] = (n0, state.n)
            return r
        G.fill_holes = fh
        t = time.process_time()
        fill(st)
        t = time.process_time() - t
        G.fill_holes = orig
        out = st.to_arrangement(keep_voids=False)
        _, idx = cKDTree(st.pos[: st.n]).query(out.xy)
        prep = st.prep
        cls = prep.size_class[st.src[: st.n][idx]]
        hm = np.zeros(st.n, bool)
        if "range" in hole:
            hm[hole["range"][0] : hole["range"][1]] = True
        hm = hm[idx]
        rep = fidelity(ex, out, region, eq5=False)
        L = rep.local
        S = np.asarray(L["score"], float)
        W = np.asarray(L["worst_metric"], dtype=object)
        ok = np.isfinite(S)
        nf = int((S[ok] > 1).sum())
        tot += nf
        pos = out.xy
        ncls = int(cls.max()) + 1
        # exemplar: small->nearest large distances
        sel = prep.selected_elements & ~prep.void
        ecls = prep.size_class[sel]
        epos = prep.pos[sel]
        big = ncls - 1
        de = cKDTree(epos[ecls == big]).query(epos[ecls == 0])[0]
        qe = np.quantile(de, [0.5, 0.8, 0.9, 0.95, 1.0])
        do = cKDTree(pos[cls == big]).query(pos[cls == 0])[0]
        print(f"{a.name} s{seed}: n={len(out)} cpu={t:.0f}s holes={hm.sum()} failing {nf}/{ok.sum()} worst={L['worst']}")
        print(f"  small->large nn: exemplar q50/80/90/95/max {np.round(qe, 1)}; output share > ex q90 {np.mean(do > qe[2]):.3f} > max {np.mean(do > qe[4]):.4f}")
        side, step = L["window"], L["step"]
        counts = []
        for (i, j), s in np.ndenumerate(S):
            if not np.isfinite(s):
                continue
            wx, wy = L["x0"] + j * step, L["y0"] + i * step
            m = (pos[:, 0] >= wx) & (pos[:, 0] < wx + side) & (pos[:, 1] >= wy) & (pos[:, 1] < wy + side)
            c = np.bincount(cls[m], minlength=ncls)
            counts.append(c)
            if s > 1:
                ms = m & (cls == 0)
                far = np.mean(do[ms[cls == 0]] > qe[1]) if ms.any() else 0
                print(f"  win({i},{j}) {s:.2f} {W[i, j]} counts {c} holes {hm[m].sum()} small>exq80 {far:.2f}")
        counts = np.array(counts)
        print(f"  counts mean {counts.mean(0).round(1)} sd {counts.std(0).round(2)}")
        if a.render:
            import matplotlib
            matplotlib.use("Agg")
            import matplotlib.pyplot as plt
            from matplotlib.patches import Rectangle
            os.makedirs(a.render, exist_ok=True)
            fig, ax = plt.subplots(figsize=(14, 14))
            col = np.array(["tab:blue", "tab:green", "tab:red", "k"])[cls]
            ax.scatter(pos[:, 0], pos[:, 1], s=2 + 8 * cls ** 2, c=col)
            ax.scatter(pos[hm, 0], pos[hm, 1], s=30, facecolors="none", edgecolors="m")
            for (i, j), s in np.ndenumerate(S):
                if np.isfinite(s) and s > 1:
                    ax.add_patch(Rectangle((L["x0"] + j * step, L["y0"] + i * step), side, side, fill=False, ec="r", lw=1.5))
                    ax.text(L["x0"] + j * step + 3, L["y0"] + i * step + 3, f"{s:.2f} {W[i, j]}", fontsize=7, color="r")
            ax.set_aspect("equal")
            fig.savefig(f"{a.render}/{a.name}_s{seed}.png", dpi=60)
            plt.close(fig)
    print("total failing", tot)


if __name__ == "__main__":
    main()
