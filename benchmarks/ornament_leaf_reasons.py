"""Why leaves are short along ornament's tile borders (issue 19.4; helper orn19b).

Flowers' leaves fall short within 1 s of a tile border (0.90x the interior's share,
benchmarks/worlds_strips.py --ornament-tiles 120,110,130,115). This wraps the flowers
pattern's rule ``flower --> stem flower * x leaf`` with a copy that records, per
success, why it has a leaf or not: ``short`` (the new flower at most 8 units away:
Appendix A adds no leaf), ``hit`` (the leaf would overlap the ornament), ``outside``
(it would leave the panel), ``leaf``; and whether its parent is a context element (a
finished neighbour's flower a later tile grows on from). The successes kept in the world
(matched by stem midpoint) are split into the +-1 s / +-2 s strips and the interior,
and by signed distance into the later tile.

Run: ``python benchmarks/ornament_leaf_reasons.py [TILE] [tiled|untiled]`` (side 4 tiles,
seed 1). At 7c83aee, tile 60: tiled +-1s strips 50 % short stems against 31 % inside
(untiled 31 % / 37 %); no leaf refused (hit, outside: none).
"""
import dataclasses, math, sys
import numpy as np
import strew
from strew.ornament import load_pattern, FAILURE, SUCCESS, distance, offset, angle_of
from strew.ornament.patterns import flowers as F
import strew.tiles as T

REC = []
CUR = {"tile": -1}
pat = load_pattern("flowers")

def body(ctx, parent, stem, flower):
    to_goal = ctx.goal.center - parent.proxy.center
    dist = min(distance(ctx.goal.center, parent.proxy.center), F.MAX_STEM)
    if dist < parent.proxy.radius + F.FLOWER_RADIUS + F.MIN_STEM_SHOWN - 1e-9:
        return FAILURE
    flower.proxy.set(offset(parent.proxy.center, to_goal, dist), F.FLOWER_RADIUS)
    if ctx.intersects(flower):
        return FAILURE
    if F._stem_crosses(ctx, parent.proxy.center, parent.proxy.radius, flower.proxy.center, F.FLOWER_RADIUS):
        return FAILURE
    flower.color = (parent.color + 1) % len(F.COLORS)
    stem.proxy.set(parent.proxy.center, flower.proxy.center)
    why = "short"
    if dist > F.LEAF_MIN_STEM:
        leaf_base = (flower.proxy.center + parent.proxy.center) / 2
        leaf_dir = angle_of(to_goal) + math.pi / 2
        leaf_tip = offset(leaf_base, leaf_dir, F.LEAF_LENGTH)
        leaf = ctx.new_child("leaf")
        leaf.proxies[0].set(leaf_base, leaf_dir + math.pi / 4, 0.6, leaf_tip, leaf_dir, 0.4)
        leaf.proxies[1].set(leaf_base, leaf_dir - math.pi / 4, 0.6, leaf_tip, leaf_dir, 0.4)
        hit, ins = ctx.intersects(leaf), ctx.inside(leaf)
        why = "leaf" if not hit and ins else ("hit" if hit else "outside")
        if hit or not ins:
            ctx.dynamic.remove(leaf)
    ctx.state.flowers += 1
    m = (flower.proxy.center + parent.proxy.center) / 2
    REC.append((CUR["tile"], float(m[0]), float(m[1]), dist, why, bool(getattr(parent, "context", False)), float(ctx.goal.radius), float(distance(ctx.goal.center, parent.proxy.center))))
    return SUCCESS

pat.rules[:] = [dataclasses.replace(r, body=body) if r.body is F.flower_to_flower else r for r in pat.rules]
orig = T.run_tile
def rt(job, t, *n):
    CUR["tile"] = t.index
    return orig(job, t, *n)
T.run_tile = rt

tile = float(sys.argv[1]) if len(sys.argv) > 1 else 60.0
side = 4 * tile
mode = sys.argv[2] if len(sys.argv) > 2 else "tiled"
if mode == "tiled":
    arr = T.tiled("ornament", "flowers", (side, side), tile_size=tile, seed=1, workers=1)
else:
    from strew.ornament import grow_ornament
    arr = grow_ornament("flowers", strew.Region.rectangle(side, side), rng=1)
n = len(arr)
s = 1 / math.sqrt(n / side**2)
kinds = list(arr.kinds)
typ = np.array(kinds)[arr.kind]
# final stems: match records by midpoint
sx, sy = np.asarray(arr.x)[typ == "stem"], np.asarray(arr.y)[typ == "stem"]
final = {(round(x, 6), round(y, 6)) for x, y in zip(sx, sy)}
rec = [r for r in REC if (round(r[1], 6), round(r[2], 6)) in final]
print(f"{mode} tile {tile}: {n} el, spacing {s:.2f}; successes recorded {len(REC)}, kept {len(rec)}; stems {len(sx)}")
lines = np.arange(1, 4) * tile
margin = max(tile / 4, 3 * s)
def dist_border(x, y):
    return min(np.min(np.abs(x - lines)), np.min(np.abs(y - lines)))
for w in (1.0, 2.0):
    rows = {"strip": [], "inner": []}
    for r in rec:
        x, y = r[1], r[2]
        if not (margin <= x <= side - margin and margin <= y <= side - margin):
            continue
        rows["strip" if dist_border(x, y) < w * s else "inner"].append(r)
    for k, rr in rows.items():
        c = {}
        for r in rr:
            c[r[4]] = c.get(r[4], 0) + 1
        tot = len(rr)
        ctxp = sum(r[5] for r in rr)
        for cp in (True, False):
            sub = [r for r in rr if r[5] == cp]
            if sub:
                gr = np.array([r[6] for r in sub]); gd = np.array([r[7] for r in sub])
                print(f"     ctx parent {cp}: n {len(sub)} short {np.mean([r[4]=='short' for r in sub]):.3f} goal r median {np.median(gr):.2f} q25 {np.percentile(gr,25):.2f}; goal dist median {np.median(gd):.2f} q25 {np.percentile(gd,25):.2f}")
        print(f"  +-{w:g}s {k:5s}: {tot} stems, " + ", ".join(f"{kk} {v/tot:.3f}" for kk, v in sorted(c.items())) + f"; context parent {ctxp/tot:.3f}")
# signed side: positive into the later tile (phase by 2x2 colouring)
def phase(i, j):
    return (j % 2) * 2 + i % 2
print("by signed distance (s units) into the later tile, +-1.5s, inner lines only:")
buck = {}
for r in rec:
    x, y = r[1], r[2]
    if not (margin <= x <= side - margin and margin <= y <= side - margin):
        continue
    kx, ky = np.round(x / tile), np.round(y / tile)
    dx, dy = x - kx * tile, y - ky * tile
    if abs(dx) < abs(dy) and 1 <= kx <= 3:
        j = int(y // tile); lo, hi = phase(int(kx) - 1, j), phase(int(kx), j); d = dx if hi > lo else -dx
    elif 1 <= ky <= 3:
        i = int(x // tile); lo, hi = phase(i, int(ky) - 1), phase(i, int(ky)); d = dy if hi > lo else -dy
    else:
        continue
    d /= s
    if abs(d) >= 1.5:
        continue
    b = int(np.floor(d / 0.5))
    own = r[0] == int(y // tile) * 4 + int(x // tile)
    key = (b, r[5], own)
    buck.setdefault(key, []).append(r[4] == "short")
for k in sorted(buck):
    v = buck[k]
    print(f"  bin {k[0]*0.5:+.1f}..{k[0]*0.5+0.5:+.1f}s ctxparent {k[1]!s:5s} placed-by-own-tile {k[2]!s:5s}: n {len(v):3d} short {np.mean(v):.2f}")
