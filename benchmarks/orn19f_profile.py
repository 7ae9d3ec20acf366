"""Ornament flowers' leaves and stems across tile borders, pooled over many worlds (issue 19.4).

The flowers pattern draws nothing from the seed: a tiled world depends only on its tile
size, so independent measurements come from other tile sizes (``--tiles``; the world is 4
x 4 tiles, halo the default T / 4, as ``benchmarks/worlds_strips.py --ornament-tiles``).
``make`` grows each world with :func:`strew.tiles.tiled` (or, ``--untiled``, one run over
the world: the control) and saves per element x, y, kind, element, parent, phase, tile and
a stem's length to ``benchmarks/results/orn19f_<tag>_T<T>.npz``; ``analyze TAG [TAG ...]``
re-reads them and prints, pooled over the worlds of each tag:

- the border strips as worlds_strips.py (centres within 1 s and 2 s of an inner border,
  the world's edge band of max(halo, 3 s) left out; s the world's mean spacing): density
  and each kind's share against the interior's, with 95 % bootstrap intervals over the
  tiles of all worlds (the units);
- a profile by distance to the nearest inner border in half-spacing bins (0-0.5 s, ...,
  2.5-3 s, and beyond 3 s as the reference): each kind's share, the flower-phase stems'
  leaves per stem, their share too short for a leaf (Appendix A: a leaf only when the new
  flower lies farther than 8 units), and their mean length; the bins by signed distance,
  negative on the earlier (finished) tile's side; ``refill``: the stems placed by another
  tile than the one holding their centre (a later tile's, on a finished side).

``--set NAME=VALUE`` sets a module constant before ``make`` (``strew.tiles.NAME`` or
``strew.ornament._context.NAME``), so that variants are measured in one tree.

``analyze A B``: also B's change against A of the +-1 s leaf share and of the leaves per
stem within 1 s, with a 95 % interval (the two tags' tiles resampled independently), and
when both tags hold the same worlds a paired one (``_paired``: the same tiles drawn in
both; a world depends only on its tile size, so a pair differs only by the change).

Findings (issue 19.4; 11 worlds, tiles 100, 104, ..., 140; orn19f_pooled.md): at e1d86dd
+-1 s leaf 0.887 [0.847, 0.929], leaves per flower stem within 1 s 0.897 [0.866, 0.928] of
the far interior's; the leaf share is 1.08-1.12x from -2.5 to -0.5 s (the finished side)
and 0.73-0.85x from -0.5 to +1 s, where half the stems are too short for a leaf (0.36
inside). orn19d's hand-over of a finished tile's small cut successes (its
orn19d_cut_small.patch): +-1 s leaf 0.939 [0.900, 0.978] (change +0.052 [-0.003, +0.111]),
leaves per stem 0.960 (change +0.062 [+0.022, +0.105]). About 20 worlds a variant give
+-3 % on the +-1 s leaf share; a world costs 45-85 CPU s.

Run: ``python benchmarks/orn19f_profile.py make --tag base --tiles 100,104,...`` then
``python benchmarks/orn19f_profile.py analyze base [new ...]``.
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
LEAF_MIN_STEM = 8.0  # strew.ornament.patterns.flowers
BINS = np.arange(-3.0, 3.01, 0.5)  # signed distance in spacings; |d| beyond 3: the reference


def _stem_lengths(arr) -> np.ndarray:
    """(n,) the length of each element's first part's first path (a stem's segment), NaN for others."""
    parts = arr.element_parts
    names = arr.kinds
    out = np.full(len(arr), np.nan)
    k_stem = names.index("stem")
    for i in np.flatnonzero(np.asarray(arr.kind) == k_stem):
        pts = np.asarray(parts[i][0]["paths"][0]["points"], float) if isinstance(parts[i][0], dict) else None
        if pts is None:
            sh = parts[i][0]
            pts = np.asarray(sh.paths[0].points, float)
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
    for tile in [float(v) for v in args.tiles.split(",")]:
        side = 4 * tile
        t0 = time.process_time()
        if args.untiled:
            from strew.ornament import grow_ornament

            arr = grow_ornament("flowers", strew.Region.rectangle(side, side), rng=1)
            halo = tile / 4
            tcol = np.full(len(arr), -1)
        else:
            arr = T.tiled("ornament", "flowers", (side, side), tile_size=tile, seed=1)
            halo = float(arr.meta["world"]["halo"])
            tcol = np.asarray(arr["tile"])
        cpu = time.process_time() - t0
        path = RES / f"orn19f_{args.tag}_T{tile:g}.npz"
        np.savez_compressed(
            path, x=np.asarray(arr.x, float), y=np.asarray(arr.y, float), kind=np.asarray(arr.kind),
            kinds=np.array(arr.kinds), element=np.asarray(arr["element"]), parent=np.asarray(arr["parent"]),
            flowers_phase=np.asarray(arr["phase"]) == "flowers", tile=tcol, stem_len=_stem_lengths(arr),
            meta=np.array([side, tile, halo, cpu]),
        )
        print(f"{args.tag} T {tile:g}: {len(arr):,} el in {cpu:.1f} CPU s -> {path.name}", flush=True)


def _world(path: Path) -> dict:
    z = np.load(path, allow_pickle=False)
    side, tile, halo, cpu = z["meta"]
    kinds = [str(k) for k in z["kinds"]]
    x, y = z["x"], z["y"]
    n = len(x)
    s = 1.0 / np.sqrt(n / side**2)
    margin = max(halo, 3.0 * s)
    inside = (x >= margin) & (x <= side - margin) & (y >= margin) & (y <= side - margin)
    lines = np.arange(1, 4) * tile
    dx = np.min(np.abs(x[:, None] - lines), axis=1)
    dy = np.min(np.abs(y[:, None] - lines), axis=1)
    d = np.minimum(dx, dy) / s
    # signed: negative on the earlier tile's side of the nearest border (strew.tiles'
    # 2 x 2 phases: across a vertical border the even column runs first, across a
    # horizontal one the even row)
    col, row = np.floor(x / tile).astype(np.int64), np.floor(y / tile).astype(np.int64)
    sd = np.where(dx <= dy, np.where(col % 2 == 0, -1.0, 1.0), np.where(row % 2 == 0, -1.0, 1.0)) * d
    unit = (np.clip(np.floor(y / tile), 0, 3) * 4 + np.clip(np.floor(x / tile), 0, 3)).astype(np.int64)
    kind = z["kind"]
    # a flower-phase stem has a leaf when the element two after it is a leaf of the same
    # parent (a rule success commits stem, flower, leaf in that order)
    el = z["element"]
    par = z["parent"]
    k_stem, k_leaf = kinds.index("stem"), kinds.index("leaf")
    # (element numbers restart in each tile's run: keyed by the placing tile too; by
    # (element, parent) alone 3 % of a world's rows matched a row of another tile)
    tl = z["tile"]
    leaf_of = {(int(t), int(e), int(p)) for t, e, p, k in zip(tl, el, par, kind) if k == k_leaf}
    stem = (kind == k_stem) & z["flowers_phase"]
    has_leaf = np.array([(int(t), int(e) + 2, int(p)) in leaf_of for t, e, p in zip(tl, el, par)]) & stem
    # placed by another tile than the one holding the centre (a later tile's refill on a
    # finished side); False in an untiled world
    other = (z["tile"] >= 0) & (z["tile"] != unit)
    return dict(other=other, x=x, y=y, d=d, sd=sd, inside=inside, unit=unit, kind=kind, kinds=kinds, stem=stem, has_leaf=has_leaf,
                stem_len=z["stem_len"], s=s, side=side, tile=tile, margin=margin, cpu=float(cpu))


def _areas(w: dict, width: float) -> tuple[np.ndarray, np.ndarray]:
    """Per tile: the area of the strips (within ``width`` of an inner border) and the rest, less the edge band."""
    t, side, m = w["tile"], w["side"], w["margin"]
    sa, ia = np.zeros(16), np.zeros(16)
    for j in range(4):
        for i in range(4):
            def span(a0, a1, lo, hi):
                c0, c1 = max(a0, m), min(a1, side - m)
                e0, e1 = max(a0 + (width if lo else 0.0), m), min(a1 - (width if hi else 0.0), side - m)
                return max(c1 - c0, 0.0), max(e1 - e0, 0.0)

            fx, ex = span(i * t, (i + 1) * t, i > 0, i < 3)
            fy, ey = span(j * t, (j + 1) * t, j > 0, j < 3)
            ia[j * 4 + i] = ex * ey
            sa[j * 4 + i] = fx * fy - ex * ey
    return sa, ia


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
    units: dict = {}  # (tag, width) -> strip units; (tag, "profile") -> profile units
    for tag in args.tags:
        paths = sorted(RES.glob(f"orn19f_{tag}_T*.npz"))
        worlds = [_world(p) for p in paths]
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
        # -- strips against the interior, bootstrap over the tiles of all worlds
        for width in (1.0, 2.0):
            U: dict = {k: [] for k in ("sc", "ic", "sa", "ia", "sk", "ik")}
            for w in worlds:
                near = w["d"] < width
                ins = w["inside"]
                sa, ia = _areas(w, width * w["s"])
                U["sc"].append(np.bincount(w["unit"][ins & near], minlength=16))
                U["ic"].append(np.bincount(w["unit"][ins & ~near], minlength=16))
                sk, ik = np.zeros((16, nk)), np.zeros((16, nk))
                np.add.at(sk, (w["unit"][ins & near], w["kind"][ins & near]), 1)
                np.add.at(ik, (w["unit"][ins & ~near], w["kind"][ins & ~near]), 1)
                U["sk"].append(sk)
                U["ik"].append(ik)
                U["sa"].append(sa)
                U["ia"].append(ia)
            U = {k: np.concatenate(v) for k, v in U.items()}
            row = {"density": _boot(lambda u: (u["sc"].sum() / u["sa"].sum()) / (u["ic"].sum() / u["ia"].sum()), U, args.boot, rng)}
            for k, name in enumerate(kinds):
                row[name] = _boot(lambda u, k=k: (u["sk"][:, k].sum() / u["sk"].sum()) / (u["ik"][:, k].sum() / u["ik"].sum()), U, args.boot, rng)
            res[f"strips_{width:g}s"] = row
            units[(tag, width)] = U
            print(f"  +-{width:g}s: " + "; ".join(f"{k} {v[0]:.3f} [{v[1]:.3f}, {v[2]:.3f}]" for k, v in row.items()))
        # -- profile by distance to the nearest inner border (half-spacing bins), per tile units
        nb = len(BINS)  # bins 0..nb-2, and nb-1 the reference beyond BINS[-1]
        P: dict = {k: [] for k in ("cnt", "kind", "stems", "leaves", "short", "slen", "ostems", "oshort")}
        for w in worlds:
            ins = w["inside"]
            b = np.digitize(w["sd"], BINS) - 1
            b[w["d"] >= BINS[-1]] = nb - 1
            u = w["unit"]
            cnt = np.zeros((16, nb))
            kk = np.zeros((16, nb, nk))
            np.add.at(cnt, (u[ins], b[ins]), 1)
            np.add.at(kk, (u[ins], b[ins], w["kind"][ins]), 1)
            st = ins & w["stem"]
            stems, leaves, short, slen = (np.zeros((16, nb)) for _ in range(4))
            np.add.at(stems, (u[st], b[st]), 1)
            np.add.at(leaves, (u[st], b[st]), w["has_leaf"][st].astype(float))
            np.add.at(short, (u[st], b[st]), (w["stem_len"][st] <= LEAF_MIN_STEM).astype(float))
            np.add.at(slen, (u[st], b[st]), w["stem_len"][st])
            ost = st & w["other"]
            ostems, oshort = np.zeros((16, nb)), np.zeros((16, nb))
            np.add.at(ostems, (u[ost], b[ost]), 1)
            np.add.at(oshort, (u[ost], b[ost]), (w["stem_len"][ost] <= LEAF_MIN_STEM).astype(float))
            for k, a in zip(P, (cnt, kk, stems, leaves, short, slen, ostems, oshort)):
                P[k].append(a)
        P = {k: np.concatenate(v) for k, v in P.items()}
        prof: dict = {}
        print(f"  profile (signed distance to the nearest border in s, negative on the earlier tile's side;"
              f" kind shares as ratios to |d| > {BINS[-1]:g} s; per-stem figures absolute):")
        print("    bin        " + " ".join(f"{k:>7s}" for k in kinds) + "   stems  leaf/stem  short   len  refill(short)")
        for bi in range(nb):
            lab = f"{BINS[bi]:+g}..{BINS[bi + 1]:+g}" if bi < nb - 1 else f"|d|>{BINS[-1]:g}"
            kshare = [(P["kind"][:, bi, k].sum() / P["cnt"][:, bi].sum()) / (P["kind"][:, -1, k].sum() / P["cnt"][:, -1].sum()) for k in range(nk)]
            ns = P["stems"][:, bi].sum()
            lps = P["leaves"][:, bi].sum() / ns
            sh = P["short"][:, bi].sum() / ns
            ml = P["slen"][:, bi].sum() / ns
            no = P["ostems"][:, bi].sum()
            osh = P["oshort"][:, bi].sum() / no if no else float("nan")
            prof[lab] = dict(kind_share_ratio=dict(zip(kinds, kshare)), stems=int(ns), leaf_per_stem=lps, short=sh, mean_len=ml,
                             refill_stems=int(no), refill_short=osh)
            print(f"    {lab:10s} " + " ".join(f"{v:7.3f}" for v in kshare) + f"  {int(ns):6d}  {lps:8.3f}  {sh:6.3f} {ml:5.2f}  {int(no):5d} ({osh:.2f})")
        i1 = [i for i in range(nb - 1) if abs(BINS[i]) <= 1.0 and abs(BINS[i + 1]) <= 1.0]  # within 1 s
        lps1 = _boot(lambda u: (u["leaves"][:, i1].sum() / u["stems"][:, i1].sum()) / (u["leaves"][:, -1].sum() / u["stems"][:, -1].sum()),
                     P, args.boot, rng)
        units[(tag, "profile")] = (P, i1)
        res["profile"] = prof
        res["leaf_per_stem_1s_ratio"] = lps1
        print(f"  leaves per stem within 1 s / beyond 3 s: {lps1[0]:.3f} [{lps1[1]:.3f}, {lps1[2]:.3f}]")
        out[tag] = res
    # each later tag against the first: the change of the +-1 s leaf share and of the
    # leaves per stem within 1 s, with a 95 % interval (the two tags' tiles resampled
    # independently)
    tags = [t for t in args.tags if t in out]
    leaf = None
    for t in tags[1:]:
        a, b = tags[0], t
        def share(u, k_leaf):
            return (u["sk"][:, k_leaf].sum() / u["sk"].sum()) / (u["ik"][:, k_leaf].sum() / u["ik"].sum())

        def lps(pi):
            p, i1 = pi
            return lambda u: (u["leaves"][:, i1].sum() / u["stems"][:, i1].sum()) / (u["leaves"][:, -1].sum() / u["stems"][:, -1].sum())

        leaf = out[a]["kinds"].index("leaf")
        stats = {
            "leaf_1s": (lambda u: share(u, leaf), units[(a, 1.0)], units[(b, 1.0)]),
            "leaf_per_stem_1s": (lps(units[(a, "profile")]), units[(a, "profile")][0], units[(b, "profile")][0]),
        }
        diff: dict = {}
        # the same worlds in both tags: also a paired interval (the same tiles drawn in
        # both; a world depends only on its tile size, so the pairs differ only by the change)
        paired = out[a]["worlds"] == out[b]["worlds"]
        prng = np.random.default_rng(1)
        for name, (fn, ua, ub) in stats.items():
            na, nb_ = len(next(iter(ua.values()))), len(next(iter(ub.values())))
            v = fn(ub) - fn(ua)
            draws = np.empty(args.boot)
            pdraws = np.empty(args.boot)
            for i in range(args.boot):
                pa, pb = rng.integers(0, na, na), rng.integers(0, nb_, nb_)
                draws[i] = fn({q: w[pb] for q, w in ub.items()}) - fn({q: w[pa] for q, w in ua.items()})
                if paired:  # its own stream: the unpaired intervals stay as before
                    pp = prng.integers(0, na, na)
                    pdraws[i] = fn({q: w[pp] for q, w in ub.items()}) - fn({q: w[pp] for q, w in ua.items()})
            lo, hi = np.nanpercentile(draws, [2.5, 97.5])
            diff[name] = (float(v), float(lo), float(hi))
            if paired:
                plo, phi = np.nanpercentile(pdraws, [2.5, 97.5])
                diff[name + "_paired"] = (float(v), float(plo), float(phi))
        out[b][f"change_vs_{a}"] = diff
        print(f"\n{b} - {a}: " + "; ".join(f"{q} {v[0]:+.3f} [{v[1]:+.3f}, {v[2]:+.3f}]" for q, v in diff.items()))
    if args.out:
        Path(args.out).write_text(json.dumps(out, indent=1))
        print(f"wrote {args.out}")
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = ap.add_subparsers(dest="cmd")
    m = sub.add_parser("make")
    m.add_argument("--tag", required=True)
    m.add_argument("--tiles", default="120,110,130,115")
    m.add_argument("--untiled", action="store_true")
    m.add_argument("--set", action="append", default=[])
    a = sub.add_parser("analyze")
    a.add_argument("tags", nargs="+")
    a.add_argument("--boot", type=int, default=2000)
    a.add_argument("--out", default=None)
    ap.add_argument("--quick", action="store_true", help="a check of the script: one small world")
    args = ap.parse_args()
    if args.quick or args.cmd is None:
        print("orn19f_profile: skipped (needs make/analyze; worlds take about a minute of CPU each)")
        sys.exit(3)
    if args.cmd == "make":
        make(args)
    else:
        analyze(args)


if __name__ == "__main__":
    main()
