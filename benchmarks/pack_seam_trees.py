"""Pack's border strips on a third input: strew demo's trees (oak, pine, scale 0.2-1.0,
upright within +-0.15 rad), 2400 x 2400 in tiles of 300 (halo 60, about 4.8 mean
spacings s), seed 1; ratios with tile-bootstrap intervals (tests/worlds/world_stats.py).

Run: ``PYTHONPATH=<src> python benchmarks/pack_seam_trees.py [--quick]`` (about 230 CPU s; ``--quick``:
900 x 900, about 20 s); prints
the strips' density and kind-fraction ratios at +-1 s and +-2 s and the signed profile.
The figures of h/packseam against d66b77e are in benchmarks/results/pack_seam_trees.json.

Tried (h/packtrees, issue 19.4, not kept): a ramp min(halo, 2 s) wide, the later tile
dropping its elements deeper than 1.25 ramp widths into a finished one: +-1s 1.095
[1.071, 1.118], +-2s 1.076 (signed profile, half-s bins from -3 s: 1.01 1.07 1.10 1.09 1.11
1.17 | 0.99 1.04 0.98 0.94 0.95 0.97), worse than 1.070: the later tile's extra 4-9 %
over a finished packing (benchmarks/pack_seam_two_tiles.py --input trees) had raised
the interior too, and the refilled ramp stays 1.09-1.16 whatever its width or area
exponent (the holes take more, smaller trees). Results: pack_seam_two_tiles_trees.json.

h/trees19 (kept, strew.tiles._in_holes): the later tile keeps on a finished side only
its elements in the weighted Voronoi cells of the elements the finished one dropped:
+-1s 1.012 [0.990, 1.033], +-2s 0.984 [0.968, 1.003], pines 0.962 / 0.973, oaks 1.033 /
1.023 (drafts in pack_seam_trees.json; where the surplus was: benchmarks/pack_seam_split.py).
"""
import sys, time, numpy as np
from pathlib import Path
sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests" / "worlds"))
import strew
from strew.tiles import tiled
from strew._resources import example_path
from strew.io import load_shapes
from world_stats import strip_units, bootstrap_ratio, signed_profile, overlapping_pairs_across
tr = load_shapes(example_path("pack", "trees.json"))
W, T = 2400.0, 300.0
if "--quick" in sys.argv[1:]:  # a check of the script: 3 x 3 tiles (wide intervals)
    W = 3 * T
U = {1.0: [], 2.0: []}; SC = 0
t0 = time.process_time()
for seed in (1,):
    a = tiled("pack", tr, (W, W), tile_size=T, seed=seed, scale=(0.2, 1.0), rotation=(-0.15, 0.15))
    s = W / np.sqrt(len(a)); halo = float(a.meta["world"]["halo"])
    print(strew.__file__, "seed", seed, len(a), "el, s", round(s, 2), "halo", halo, "overlaps across", overlapping_pairs_across(a, a["tile"]), flush=True)
    for m in U:
        U[m].append(strip_units(a, (W, W), T, m * s, max(halo, 3 * s)))
    SC = SC + signed_profile(a, (W, W), T, s)["counts"]
print("cpu", round(time.process_time() - t0, 1))
rng = np.random.default_rng(0)
for m, L in U.items():
    u = {k: np.concatenate([x[k] for x in L]) for k in L[0] if k != "kinds"}
    d = bootstrap_ratio([u["strip"], u["strip_area"], u["inner"], u["inner_area"]], lambda s_, sa, i, ia: (s_.sum() / sa.sum()) / (i.sum() / ia.sum()), 1000, rng)
    ks = []
    for k in range(u["strip_kind"].shape[1]):
        r = bootstrap_ratio([u["strip_kind"][:, k], u["strip"], u["inner_kind"][:, k], u["inner"]], lambda sk, s_, ik, i: (sk.sum() / s_.sum()) / (ik.sum() / i.sum()), 1000, rng)
        ks.append(f"{r['value']:.3f} [{r['ci'][0]:.3f}, {r['ci'][1]:.3f}]")
    print(f"+-{m:g}s density {d['value']:.3f} [{d['ci'][0]:.3f}, {d['ci'][1]:.3f}]  kinds oak, pine: {'; '.join(ks)}  strip el {int(u['strip'].sum())}")
c = SC.astype(float); ref = c[0][[0, 1, -2, -1]].mean()
print("signed all", " ".join(f"{v:.2f}" for v in c[0] / ref))
