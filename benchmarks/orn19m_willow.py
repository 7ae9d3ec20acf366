"""Ornament willow across tile borders: where the border strips' excess comes from (issue 19.4).

``make --tag TAG --tiles 100,104,...`` grows for each tile size T a world of 4 x 4 tiles
(side 4 T, halo the default T / 4, seed 1, as ``benchmarks/worlds_strips.py
--ornament-tiles``) with :func:`strew.tiles.tiled`, or ``--untiled`` one run over the
world (the control; the same lines are measured where no border exists). It saves to
``benchmarks/results/orn19m_<tag>_T<T>.npz`` per element x, y, kind, the tile that placed
it, its rule success (``ornament_group``, numbered per tile) and, for a stem, its chord
length, and the radius of the empty circle its rule success grew into (``goal_r``); and
every element a tile grew and dropped (the cut: ``_keep_groups``' input less its output).
``--overlaps`` counts each world's overlapping pairs as worlds_strips.py does.

``analyze TAG [TAG ...]`` pools the worlds of each tag and prints:

- the +-1 s and +-2 s strips against the interior as worlds_strips.py (density, each
  kind's share; 95 % bootstrap intervals over the tiles of all worlds);
- a profile by signed distance to the nearest inner border in half-spacing bins
  (negative on the earlier, finished tile's side; areas by a lattice of points): the
  density of each kind against |d| > 3 s; the share placed by another tile than the one
  holding the centre (``refill`` on the finished side: a later tile's growth; on the
  later side: the finished tile's successes that straddle); the dropped elements'
  density (what the finished tile grew there and cut); stems' mean chord length;
- the folded profile (worlds_strips.py's grid test: chi-square against flat, the bins
  within 1 s of a border against the others);
- the chord of the stems a later tile placed on a finished side within 3 s (the refill)
  against the stems beyond 3 s: mean and share over 20 units.

``--set NAME=VALUE`` sets a module constant of ``strew.tiles`` or
``strew.ornament._context`` before ``make``.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
RES = HERE / "results"
BINS = np.arange(-3.0, 3.01, 0.5)


def _chord(arr) -> np.ndarray:
    parts = arr.element_parts
    out = np.full(len(arr), np.nan)
    if "stem" not in arr.kinds:
        return out
    k = arr.kinds.index("stem")
    for i in np.flatnonzero(np.asarray(arr.kind) == k):
        p = parts[i][0]
        pts = np.asarray(p["paths"][0]["points"] if isinstance(p, dict) else p.paths[0].points, float)
        out[i] = float(np.hypot(*(pts[-1] - pts[0])))
    return out


def make(args) -> None:
    import strew
    import strew.ornament._context as C
    import strew.tiles as T

    for kv in args.set:
        name, _, val = kv.partition("=")
        mod = T if hasattr(T, name) else C
        setattr(mod, name, type(getattr(mod, name))(val))
    RES.mkdir(exist_ok=True)
    dropped: list = []
    orig_keep = T._keep_groups

    def keep_groups(arr, keep, t, job, links):  # record what each tile cuts
        k = orig_keep(arr, keep, t, job, links)
        d = arr.select(~k)
        if len(d):
            dropped.append((t.index, np.asarray(d.x, float), np.asarray(d.y, float), np.asarray([d.kinds[i] for i in d.kind])))
        return k

    T._keep_groups = keep_groups
    T._public = lambda job, arr: arr.without_columns("ornament_proxies") if "ornament_proxies" in arr.columns else arr
    for tile in [float(v) for v in args.tiles.split(",")]:
        side = 4 * tile
        dropped.clear()
        t0 = time.process_time()
        if args.untiled:
            from strew.ornament import grow_ornament

            arr = grow_ornament(args.pattern, strew.Region.rectangle(side, side), rng=args.seed)
            halo = tile / 4
            tcol = np.full(len(arr), -1)
            grp = np.full(len(arr), -1)
        else:
            arr = T.tiled("ornament", args.pattern, (side, side), tile_size=tile, seed=args.seed)
            halo = float(arr.meta["world"]["halo"])
            tcol = np.asarray(arr["tile"])
            grp = np.asarray(arr["ornament_group"], np.int64)
        gr = np.full(len(arr), np.nan)
        if "ornament_goal" in arr.columns:  # each row's empty circle radius (its success's $goal)
            gr = np.array([v[2] if v is not None else np.nan for v in arr["ornament_goal"]], float)
        cpu = time.process_time() - t0
        ovl = -1
        if args.overlaps:  # pairs of elements that overlap (worlds_strips.py's test)
            sys.path.insert(0, str(HERE.parent / "tests" / "worlds"))
            from world_stats import overlapping_pairs

            ovl = int(overlapping_pairs(arr))
        kinds = list(arr.kinds)
        dx = np.concatenate([d[1] for d in dropped]) if dropped else np.zeros(0)
        dy = np.concatenate([d[2] for d in dropped]) if dropped else np.zeros(0)
        dk = np.concatenate([d[3] for d in dropped]) if dropped else np.zeros(0, str)
        dt = np.concatenate([np.full(len(d[1]), d[0]) for d in dropped]) if dropped else np.zeros(0, int)
        path = RES / f"orn19m_{args.tag}_T{tile:g}.npz"
        np.savez_compressed(
            path, x=np.asarray(arr.x, float), y=np.asarray(arr.y, float), kind=np.asarray(arr.kind), kinds=np.array(kinds),
            tile=tcol, group=grp, chord=_chord(arr), goal_r=gr, dx=dx, dy=dy, dkind=np.array([kinds.index(k) if k in kinds else -1 for k in dk]),
            dtile=dt, meta=np.array([side, tile, halo, cpu]), overlaps=ovl,
        )
        print(f"{args.tag} T {tile:g}: {len(arr):,} el, {len(dx):,} dropped, {cpu:.1f} CPU s, overlaps {ovl} -> {path.name}", flush=True)


def _sd(x, y, side, tile):
    lines = np.arange(1, 4) * tile
    dx = np.min(np.abs(x[:, None] - lines), axis=1)
    dy = np.min(np.abs(y[:, None] - lines), axis=1)
    col, row = np.floor(x / tile).astype(np.int64), np.floor(y / tile).astype(np.int64)
    # negative on the earlier tile's side (2 x 2 phases: the even column / row runs first)
    sgn = np.where(dx <= dy, np.where(col % 2 == 0, -1.0, 1.0), np.where(row % 2 == 0, -1.0, 1.0))
    return np.minimum(dx, dy), sgn * np.minimum(dx, dy)


def _world(path: Path) -> dict:
    z = np.load(path, allow_pickle=False)
    side, tile, halo, cpu = z["meta"]
    x, y = z["x"], z["y"]
    n = len(x)
    s = 1.0 / np.sqrt(n / side**2)
    margin = max(halo, 3.0 * s)

    def inside(a, b):
        return (a >= margin) & (a <= side - margin) & (b >= margin) & (b <= side - margin)

    def unit(a, b):
        return (np.clip(np.floor(b / tile), 0, 3) * 4 + np.clip(np.floor(a / tile), 0, 3)).astype(np.int64)

    d, sd = _sd(x, y, side, tile)
    dd, dsd = _sd(z["dx"], z["dy"], side, tile)
    # bin areas: a lattice of points, 0.25 apart
    g = np.arange(0.125, side, 0.25)
    gx, gy = np.meshgrid(g, g)
    gx, gy = gx.ravel(), gy.ravel()
    ok = inside(gx, gy)
    gd, gsd = _sd(gx[ok], gy[ok], side, tile)
    return dict(x=x, y=y, d=d / s, sd=sd / s, inside=inside(x, y), unit=unit(x, y), kind=z["kind"], kinds=[str(k) for k in z["kinds"]],
                placer=z["tile"], group=z["group"], chord=z["chord"], other=(z["tile"] >= 0) & (z["tile"] != unit(x, y)),
                dd=dd / s, dsd=dsd / s, dinside=inside(z["dx"], z["dy"]), dunit=unit(z["dx"], z["dy"]), dkind=z["dkind"].astype(np.int64),
                gd=gd / s, gsd=gsd / s, gunit=unit(gx[ok], gy[ok]), garea=0.0625, s=s, side=side, tile=tile, margin=margin, cpu=float(cpu))


def _bin(sd, d):
    nb = len(BINS)
    b = np.digitize(sd, BINS) - 1
    b[d >= BINS[-1]] = nb - 1
    return b


def _boot(fn, units: dict, boot: int, rng) -> tuple[float, float, float]:
    n = len(next(iter(units.values())))
    v = fn(units)
    draws = np.empty(boot)
    for b in range(boot):
        pick = rng.integers(0, n, n)
        draws[b] = fn({k: a[pick] for k, a in units.items()})
    lo, hi = np.nanpercentile(draws, [2.5, 97.5])
    return float(v), float(lo), float(hi)


def analyze(args) -> dict:
    rng = np.random.default_rng(0)
    out: dict = {}
    for tag in args.tags:
        worlds = [_world(p) for p in sorted(RES.glob(f"orn19m_{tag}_T*.npz"))]
        if not worlds:
            print(f"{tag}: no worlds")
            continue
        kinds = worlds[0]["kinds"]
        nk = len(kinds)
        res: dict = {"kinds": kinds, "worlds": [w["tile"] for w in worlds], "elements": [int(len(w["x"])) for w in worlds],
                     "cpu_s": [w["cpu"] for w in worlds]}
        tl = ", ".join(f"{w['tile']:g}" for w in worlds)
        print(f"\n== {tag}: {len(worlds)} worlds (tiles {tl}), "
              f"{sum(res['elements']):,} elements, {sum(res['cpu_s']):.0f} CPU s")
        nb = len(BINS)
        # per unit (tile) and bin: area, counts by kind, other-tile counts, dropped counts, stems' chord sum
        P: dict = {k: [] for k in ("area", "cnt", "kind", "other", "okind", "drop", "dkind", "chord", "nstem", "groups")}
        S: dict = {w_: {k: [] for k in ("sc", "ic", "sa", "ia", "sk", "ik")} for w_ in (1.0, 2.0)}
        for w in worlds:
            ins = w["inside"]
            b = _bin(w["sd"], w["d"])
            u = w["unit"]
            area = np.zeros((16, nb))
            np.add.at(area, (w["gunit"], _bin(w["gsd"], w["gd"])), w["garea"])
            cnt, other, drop, chord, nstem, groups = (np.zeros((16, nb)) for _ in range(6))
            kk, ok_, dk = (np.zeros((16, nb, nk)) for _ in range(3))
            np.add.at(cnt, (u[ins], b[ins]), 1)
            np.add.at(kk, (u[ins], b[ins], w["kind"][ins]), 1)
            o = ins & w["other"]
            np.add.at(other, (u[o], b[o]), 1)
            np.add.at(ok_, (u[o], b[o], w["kind"][o]), 1)
            di = w["dinside"] & (w["dkind"] >= 0)
            db = _bin(w["dsd"], w["dd"])
            np.add.at(drop, (w["dunit"][di], db[di]), 1)
            np.add.at(dk, (w["dunit"][di], db[di], w["dkind"][di]), 1)
            st = ins & np.isfinite(w["chord"])
            np.add.at(chord, (u[st], b[st]), w["chord"][st])
            np.add.at(nstem, (u[st], b[st]), 1)
            for k, a in zip(P, (area, cnt, kk, other, ok_, drop, dk, chord, nstem)):
                P[k].append(a)
            for width in (1.0, 2.0):
                near = w["d"] < width
                gnear = w["gd"] < width
                U = S[width]
                U["sc"].append(np.bincount(u[ins & near], minlength=16))
                U["ic"].append(np.bincount(u[ins & ~near], minlength=16))
                U["sa"].append(np.bincount(w["gunit"][gnear], minlength=16) * w["garea"])
                U["ia"].append(np.bincount(w["gunit"][~gnear], minlength=16) * w["garea"])
                sk, ik = np.zeros((16, nk)), np.zeros((16, nk))
                np.add.at(sk, (u[ins & near], w["kind"][ins & near]), 1)
                np.add.at(ik, (u[ins & ~near], w["kind"][ins & ~near]), 1)
                U["sk"].append(sk)
                U["ik"].append(ik)
        P = {k: np.concatenate(v) for k, v in P.items() if v}
        for width in (1.0, 2.0):
            U = {k: np.concatenate(v) for k, v in S[width].items()}
            row = {"density": _boot(lambda u: (u["sc"].sum() / u["sa"].sum()) / (u["ic"].sum() / u["ia"].sum()), U, args.boot, rng)}
            for k, name in enumerate(kinds):
                row[name] = _boot(lambda u, k=k: (u["sk"][:, k].sum() / u["sk"].sum()) / (u["ik"][:, k].sum() / u["ik"].sum()), U, args.boot, rng)
                row[name + "_density"] = _boot(lambda u, k=k: (u["sk"][:, k].sum() / u["sa"].sum()) / (u["ik"][:, k].sum() / u["ia"].sum()), U, args.boot, rng)
            res[f"strips_{width:g}s"] = row
            print(f"  +-{width:g}s: " + "; ".join(f"{k} {v[0]:.3f} [{v[1]:.3f}, {v[2]:.3f}]" for k, v in row.items()))
        ref = P["cnt"][:, -1].sum() / P["area"][:, -1].sum()
        refk = P["kind"][:, -1].sum(0) / P["area"][:, -1].sum()
        prof = {}
        print("  profile: density (all, by kind) against |d|>3s; other-tile share of the bin's elements (by kind);"
              " dropped density; stems' chord")
        print("    bin        density " + " ".join(f"{k:>7s}" for k in kinds) + "   other " + " ".join(f"o_{k:>5s}" for k in kinds)
              + "   drop  chord")
        for bi in range(nb):
            lab = f"{BINS[bi]:+g}..{BINS[bi + 1]:+g}" if bi < nb - 1 else f"|d|>{BINS[-1]:g}"
            a = P["area"][:, bi].sum()
            dens = P["cnt"][:, bi].sum() / a / ref
            kd = P["kind"][:, bi].sum(0) / a / refk
            oth = P["other"][:, bi].sum() / max(P["cnt"][:, bi].sum(), 1)
            ok_ = P["okind"][:, bi].sum(0) / a / refk
            dr = P["drop"][:, bi].sum() / a / ref
            ch = P["chord"][:, bi].sum() / max(P["nstem"][:, bi].sum(), 1)
            prof[lab] = dict(density=dens, kinds=dict(zip(kinds, kd.tolist())), other=oth, other_kinds=dict(zip(kinds, ok_.tolist())),
                             dropped=dr, chord=ch)
            print(f"    {lab:10s} {dens:7.3f} " + " ".join(f"{v:7.3f}" for v in kd) + f"  {oth:6.3f} "
                  + " ".join(f"{v:7.3f}" for v in ok_) + f"  {dr:6.3f} {ch:5.2f}")
        res["profile"] = prof
        # the grid: centres folded modulo the tile across the borders, pooled over the
        # worlds (worlds_strips.py's folded profile and its test)
        sys.path.insert(0, str(HERE.parent / "tests" / "worlds"))
        sys.path.insert(0, str(HERE))
        from world_stats import folded_profile
        from worlds_strips import _pooled_profile

        class _XY:
            def __init__(self, w):
                self.x, self.y = w["x"], w["y"]

        fold = _pooled_profile([folded_profile(_XY(w), (w["side"], w["side"]), w["tile"], w["s"]) for w in worlds])
        res["folded"] = fold
        print(f"  folded profile: chi2/dof {fold['chi2_dof']:.2f} (p {fold['p']:.2f}), within 1 s of a border "
              f"{fold['near_ratio']['value']:.3f} [{fold['near_ratio']['ci'][0]:.3f}, {fold['near_ratio']['ci'][1]:.3f}]")
        # the stems a later tile placed on a finished side within 3 s (the refill) against
        # the stems beyond 3 s: chord length, mean and share over 20 units
        ch = {"refill": [], "interior": []}
        for w in worlds:
            st = w["inside"] & np.isfinite(w["chord"])
            ch["refill"].append(w["chord"][st & w["other"] & (w["sd"] < 0) & (w["sd"] > -3)])
            ch["interior"].append(w["chord"][st & (w["d"] >= 3)])
        res["stem_chord"] = {}
        for k, v in ch.items():
            v = np.concatenate(v)
            res["stem_chord"][k] = dict(n=int(len(v)), mean=float(v.mean()) if len(v) else float("nan"),
                                        over_20=float((v > 20).mean()) if len(v) else float("nan"))
        print("  stems' chord: " + "; ".join(f"{k} n {v['n']} mean {v['mean']:.2f} over 20 {v['over_20']:.3f}"
                                            for k, v in res["stem_chord"].items()))
        out[tag] = res
    if args.out:
        Path(args.out).write_text(json.dumps(out, indent=1))
        print(f"wrote {args.out}")
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = ap.add_subparsers(dest="cmd")
    m = sub.add_parser("make")
    m.add_argument("--tag", required=True)
    m.add_argument("--tiles", default="100,120")
    m.add_argument("--pattern", default="willow")
    m.add_argument("--untiled", action="store_true")
    m.add_argument("--seed", type=int, default=1, help="the world's seed (tiled) or rng (untiled)")
    m.add_argument("--set", action="append", default=[])
    m.add_argument("--overlaps", action="store_true", help="count overlapping pairs (worlds_strips.py's test; -1 without)")
    a = sub.add_parser("analyze")
    a.add_argument("tags", nargs="+")
    a.add_argument("--boot", type=int, default=1000)
    a.add_argument("--out", default=None)
    ap.add_argument("--quick", action="store_true", help="a check of the script: skipped (worlds take a minute each)")
    args = ap.parse_args()
    if args.quick or args.cmd is None:
        print("orn19m_willow: skipped (needs make/analyze)")
        sys.exit(3)
    make(args) if args.cmd == "make" else analyze(args)


if __name__ == "__main__":
    main()
