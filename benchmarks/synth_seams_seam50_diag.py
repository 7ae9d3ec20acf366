"""Helper seam50 diagnostic (issue 13 point 2): synth at 50x the area, local fidelity map,
failing windows with their kind counts, birth iteration, hole fills and the exemplar
region their elements were copied from.

    SEAM50_R=0 python benchmarks/synth_seams_seam50_diag.py three_sizes 1 [render]
"""
import sys, json, time, numpy as np
sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
from _runner import SKIPPED, fidelity_suite
if "--quick" in sys.argv[1:]:
    print("synth_seams_seam50_diag: skipped: a diagnostic of one class and seed given as positional NAME SEED, which have no default")
    sys.exit(SKIPPED)
from strew import Region
from strew.metrics import fidelity
import strew.synth._grow as G, os
G.REPEAT_RADIUS = float(os.environ.get("SEAM50_R", G.REPEAT_RADIUS))
from strew.synth import new_state, fill
name, seed = sys.argv[1], int(sys.argv[2])
render = len(sys.argv) > 3
mk = fidelity_suite()
ex = mk.make_exemplar(name)
x0, y0, x1, y1 = ex.region.bounds
sc = 7.07
region = Region.rectangle(sc * (x1 - x0), sc * (y1 - y0))
st = new_state(ex, region, rng=seed)
hole = {}
orig = G.fill_holes
def fh(state, *a, **k):
    n0 = state.n; r = orig(state, *a, **k); hole['range'] = (n0, state.n); return r
G.fill_holes = fh
t = time.process_time(); fill(st); t = time.process_time() - t
out = st.to_arrangement(keep_voids=False)
from scipy.spatial import cKDTree
_, IDX = cKDTree(st.pos[:st.n]).query(out.xy)
rep = fidelity(ex, out, region, eq5=False)
L = rep.local; S = np.asarray(L["score"], float); W = np.asarray(L["worst_metric"], dtype=object)
allsrc = st.src[:st.n][IDX]; epa = st.prep.pos[allsrc]; print('overall ex pos mean/std', epa.mean(0).round(0), epa.std(0).round(0), 'ex bounds', x0,y0,x1,y1)
born = st._born[:st.n][IDX]; pos = out.xy
hm = np.zeros(st.n, bool); hm[hole['range'][0]:hole['range'][1]] = True; hole_mask = hm[IDX]
c0 = np.array([0.5*sc*(x1-x0), 0.5*sc*(y1-y0)])
print(f"{name} s{seed}: n={st.n} iters={st.iterations} holes={hole_mask.sum()} cpu={t:.0f}s faithful={rep.faithful} fail={np.mean(S[np.isfinite(S)]>1):.3f} worst={L['worst']}")
side, step = L["window"], L["step"]
fails = []
for (i, j), s in np.ndenumerate(S):
    if np.isfinite(s) and s > 0.9:
        wx, wy = L["x0"] + j*step, L["y0"] + i*step
        m = (pos[:,0]>=wx)&(pos[:,0]<wx+side)&(pos[:,1]>=wy)&(pos[:,1]<wy+side)
        kinds = np.bincount(np.asarray(out["kind"])[m], minlength=len(out.shapes))
        d = np.hypot(*(np.array([wx+side/2, wy+side/2]) - c0))
        fails.append((i,j,s))
        srcs = st.src[:st.n][IDX][m]; u = np.unique(srcs)
        ep = st.prep.pos[srcs]
        extra = f" distinct_src {len(u)}/{m.sum()} ex_pos_mean {ep.mean(0).round(0)} ex_pos_std {ep.std(0).round(0)}"
        print(extra)
        print(f"  win ({i},{j}) score {s:.2f} {W[i,j]} at ({wx:.0f},{wy:.0f}) dist_from_seed {d:.0f}/{np.hypot(*c0):.0f} n={m.sum()} kinds {kinds} born med {np.median(born[m]):.0f} (all med {np.median(born):.0f}) holes {hole_mask[m].sum()}")
if render:
    import matplotlib; matplotlib.use("Agg"); import matplotlib.pyplot as plt
    from matplotlib.patches import Rectangle
    fig, ax = plt.subplots(figsize=(12,12))
    kk = np.asarray(out["kind"])
    _, kidx = np.unique(np.asarray(kk), return_inverse=True)
    ax.scatter(pos[:,0], pos[:,1], s=2+6*kidx.max()-6*kidx if kidx.max() else 3, c=born, cmap="viridis")
    ax.scatter(pos[hole_mask,0], pos[hole_mask,1], s=20, c="r", marker="x")
    for i,j,s in fails:
        ax.add_patch(Rectangle((L["x0"]+j*step, L["y0"]+i*step), side, side, fill=False, ec="r" if s>1 else "orange", lw=2))
    ax.set_aspect("equal"); fig.savefig(f"/tmp/seam50/{name}_s{seed}.png", dpi=70)
