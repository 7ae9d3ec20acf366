"""Pack's density across tile borders by scale and by the tile that placed each element (issue 19.4).

strew demo's trees (oak, pine, scale 0.2-1.0, rotation +-0.15; ``--side 2400`` in tiles of
300 as ``benchmarks/pack_seam_kinds.py --input trees``) made with :func:`strew.tiles.tiled`
(or, ``--untiled``, one pack run over the world: the control), each seed's world saved to
``benchmarks/results/pack_seam_profile_<tag>_s<seed>.npz`` (x, y, kind, scale, tile, the
finished tiles' dropped elements), so that ``--analyze TAG [TAG ...]`` re-reads them.

Printed per tag, pooled over its seeds: the signed profile (centres by signed distance
to the nearest inner border, in half-spacing bins, negative on the earlier tile's side;
tests/worlds/world_stats.py ``signed_profile``: bins of equal area) as density over the
bins beyond 2.5 s, for all elements and per scale quartile of 0.2-1.0 and per kind, and
split into ``own`` (kept by the tile holding the centre) and ``refill`` (placed by the
later tile on a finished side); and the border strips (centres within 1 s and 2 s of an
inner border against the interior, tile-bootstrap 95 % intervals, as
``benchmarks/worlds_strips.py``), density, kinds and mean scale.

Findings (issue 19.4, trees, 550ea99, seed 1): the +-1 s excess (1.032 [1.020, 1.042] over
seeds 1-4) was small trees in place of large ones: within half a spacing past a border
(the later tile's own side) trees of scale 0.6-0.8 at 0.48 and 0.8-1.0 at 0.25 of the
interior, the strips' mean scale 0.966 and their scale^2 cover 0.916. The later tile's
Step 1 (the sparse placements at random scales, where the large trees come from) samples
its free region shrunk by the largest radius, so none next to the finished packing.
The finished side from -2.5 s to 0 is at 0.90-0.93 (in the 2 s band, corners included, refilled by count to 0.47
of what was dropped, by scale^2 to 0.40). With strew.tiles._RAMP_PAST 0.25 (the finished
tile keeps its large trees just past the border; tag past25, seeds 1-4): +-1 s 1.001
[0.986, 1.014], oaks 1.015, pines 0.982; +-2 s 0.986 [0.974, 0.997], 1.006, 0.993; mean
scale 0.990.

Run: ``python benchmarks/pack_seam_profile.py --seeds 1,2 --tag base`` (about 150 CPU s a
seed), ``... --untiled --tag untiled``, then ``--analyze base untiled``.
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
SCALE_BINS = np.array([0.2, 0.4, 0.6, 0.8, 1.0 + 1e-9])


def make(args) -> None:
    import strew.tiles as T
    from strew._resources import example_path
    from strew.io import load_shapes

    for kv in args.set:
        name, _, val = kv.partition("=")
        setattr(T, name, type(getattr(T, name))(val))
    lib = load_shapes(example_path("pack", "trees.json"))
    kw = {"scale": (0.2, 1.0), "rotation": (-0.15, 0.15)}
    side, tile = args.side, args.tile
    rec: list[np.ndarray] = []
    orig = T._hole_discs

    def spy(arr, dropped):
        h = orig(arr, dropped)
        rec.append(np.c_[h, np.asarray(arr.kind, float)[np.flatnonzero(dropped)]] if len(h) else np.zeros((0, 4)))
        return h

    T._hole_discs = spy
    for seed in [int(s) for s in args.seeds.split(",")]:
        rec.clear()
        t0 = time.process_time()
        if args.untiled:
            from strew.pack import pack

            a = pack(lib, (side, side), rng=seed, **kw)
            tl = np.full(len(a), -1)
        else:
            a = T.tiled("pack", lib, (side, side), tile_size=tile, seed=seed, **kw)
            tl = np.asarray(a["tile"], np.int64)
        cpu = time.process_time() - t0
        names = list(a.kinds)
        kmap = np.array([sorted(names).index(n) for n in names])
        sc = np.abs(np.asarray(a.scale, float).reshape(len(a), -1))[:, 0]
        holes = np.concatenate(rec) if rec else np.zeros((0, 4))
        if len(holes):
            holes[:, 3] = kmap[holes[:, 3].astype(int)]
        path = RES / f"pack_seam_profile_{args.tag}_s{seed}.npz"
        RES.mkdir(parents=True, exist_ok=True)
        np.savez(path, x=np.asarray(a.x, float), y=np.asarray(a.y, float), kind=kmap[np.asarray(a.kind, np.int64)],
                 scale=sc, tile=tl, holes=holes, cpu=cpu, side=side, tilesize=tile, names=np.array(sorted(names)))
        print(f"{args.tag} seed {seed}: {len(a)} elements, {cpu:.1f} CPU s ({cpu / len(a) * 1e3:.2f} ms/element) -> {path.name}", flush=True)
    T._hole_discs = orig


class _A:
    """The saved world as an arrangement-like for world_stats (x, y, kind, kinds)."""

    def __init__(self, z, m=None):
        m = slice(None) if m is None else m
        self.x, self.y, self.kind = z["x"][m], z["y"][m], z["kind"][m]
        self.kinds = list(z["names"])

    def __len__(self):
        return len(self.x)


def signed(x, y, side, tile):
    """Signed distance (units) to the nearest inner border line, < 0 on the earlier phase's
    side, and a mask of centres next to an inner part of a border (as signed_profile)."""
    nx = int(round(side / tile))
    sd = np.full(len(x), np.inf)
    ok = np.zeros(len(x), bool)
    for v, o, is_x in ((x, y, True), (y, x, False)):
        k = np.round(v / tile)
        d = v - k * tile
        oi = np.floor(o / tile).astype(np.int64)
        okk = (k >= 1) & (k <= nx - 1) & (oi >= 1) & (oi <= nx - 2)
        lo, hi = (k - 1).astype(np.int64), k.astype(np.int64)
        p_lo = (oi % 2) * 2 + lo % 2 if is_x else (lo % 2) * 2 + oi % 2
        p_hi = (oi % 2) * 2 + hi % 2 if is_x else (hi % 2) * 2 + oi % 2
        s = np.where(p_hi > p_lo, d, -d)
        use = okk & (np.abs(s) < np.abs(sd))
        sd = np.where(use, s, sd)
        ok |= use
    return sd, ok


def analyze(tags: list[str]) -> None:
    sys.path.insert(0, str(HERE.parent / "tests" / "worlds"))
    from world_stats import bootstrap_ratio, signed_profile, strip_units

    out = {}
    for tag in tags:
        files = sorted(RES.glob(f"pack_seam_profile_{tag}_s*.npz"))
        if not files:
            print(f"{tag}: no worlds")
            continue
        reach = 4.0
        edges = None
        prof = {}
        units = {1.0: [], 2.0: []}
        n_el, cpu = 0, 0.0
        for f in files:
            z = np.load(f)
            side, tile = float(z["side"]), float(z["tilesize"])
            n = len(z["x"])
            n_el += n
            cpu += float(z["cpu"])
            s = side / np.sqrt(n)
            halo = 60.0
            margin = max(halo, 3 * s)
            own = z["tile"] < 0
            if not own.all():
                nx = int(round(side / tile))
                ix = np.clip(np.floor(z["x"] / tile), 0, nx - 1).astype(int)
                iy = np.clip(np.floor(z["y"] / tile), 0, nx - 1).astype(int)
                own = (iy * nx + ix) == z["tile"]
            else:
                own = np.ones(n, bool)
            sb = np.searchsorted(SCALE_BINS, z["scale"], side="right") - 1
            groups = {"all": np.ones(n, bool)}
            for q in range(len(SCALE_BINS) - 1):
                groups[f"sc{SCALE_BINS[q]:.1f}"] = sb == q
            for q, nm in enumerate(z["names"]):
                groups[str(nm)] = z["kind"] == q
            for g, m in list(groups.items()):
                for part, pm in (("", None), (":own", own), (":refill", ~own)):
                    mm = m if pm is None else m & pm
                    p = signed_profile(_A(z, mm), (side, side), tile, s, reach)
                    prof[g + part] = prof.get(g + part, 0) + p["counts"][0]
                    edges = p["edges"]
            # the finished side within 2 s: dropped elements (holes, scale = r / 30, the
            # trees' bounding radius) against the later tile's refill, by scale bin
            if len(z["holes"]):
                hsd, hok = signed(z["holes"][:, 0], z["holes"][:, 1], side, tile)
                esd, eok = signed(z["x"], z["y"], side, tile)
                hm = hok & (hsd < 0) & (hsd > -2 * s)
                em = eok & (esd < 0) & (esd > -2 * s)
                hb = np.histogram(z["holes"][hm, 2] / 30.0, SCALE_BINS)[0]
                rb = np.histogram(z["scale"][em & ~own], SCALE_BINS)[0]
                ob = np.histogram(z["scale"][em & own], SCALE_BINS)[0]
                hr = (z["holes"][hm, 2] / 30.0) ** 2
                prof["_finished_2s"] = prof.get("_finished_2s", 0) + np.array([hb, rb, ob])
                prof["_finished_2s_cover"] = prof.get("_finished_2s_cover", 0) + np.array(
                    [hr.sum(), (z["scale"][em & ~own] ** 2).sum(), (z["scale"][em & own] ** 2).sum()])
            for m_ in units:
                u = strip_units(_A(z), (side, side), tile, m_ * s, margin)
                # scale sums in strips/interior per tile: mean scale ratio
                x, y = z["x"], z["y"]
                lx = np.arange(1, int(round(side / tile))) * tile
                near = (np.min(np.abs(x[:, None] - lx), 1) < m_ * s) | (np.min(np.abs(y[:, None] - lx), 1) < m_ * s)
                inside = (x >= margin) & (x <= side - margin) & (y >= margin) & (y <= side - margin)
                nx = int(round(side / tile))
                unit = np.clip(np.floor(y / tile), 0, nx - 1).astype(int) * nx + np.clip(np.floor(x / tile), 0, nx - 1).astype(int)
                u["strip_sc"] = np.bincount(unit[inside & near], z["scale"][inside & near], nx * nx)
                u["inner_sc"] = np.bincount(unit[inside & ~near], z["scale"][inside & ~near], nx * nx)
                u["strip_a"] = np.bincount(unit[inside & near], z["scale"][inside & near] ** 2, nx * nx)
                u["inner_a"] = np.bincount(unit[inside & ~near], z["scale"][inside & ~near] ** 2, nx * nx)
                units[m_].append(u)
        names = [str(v) for v in np.load(files[0])["names"]]
        res = {"edges": edges.tolist(), "profile": {}, "strips": {}}
        print(f"== {tag}: {len(files)} seeds, {n_el} elements, {cpu:.0f} CPU s ({cpu / n_el * 1e3:.2f} ms/element)")
        print("bins (s)        " + " ".join(f"{e:+5.1f}" for e in edges[:-1]))
        far = np.abs(0.5 * (edges[:-1] + edges[1:])) > 2.5
        if "_finished_2s" in prof:
            fb, fc = prof.pop("_finished_2s"), prof.pop("_finished_2s_cover")
            print("finished side within 2 s, by scale bin " + " ".join(f"{v:.1f}" for v in SCALE_BINS[:-1])
                  + f": dropped {fb[0].tolist()}, refill {fb[1].tolist()}, kept {fb[2].tolist()};"
                  f" refill/dropped {fb[1].sum() / max(fb[0].sum(), 1):.3f}, scale^2 cover {fc[1] / max(fc[0], 1e-9):.3f}")
            res["finished_2s"] = {"dropped": fb[0].tolist(), "refill": fb[1].tolist(), "kept": fb[2].tolist(), "cover": fc.tolist()}
        for g in prof:
            base = g.split(":")[0]
            ref = prof[base][far].mean()
            v = prof[g] / max(ref, 1e-9)
            res["profile"][g] = v.tolist()
            print(f"{g:15s} " + " ".join(f"{x:5.2f}" for x in v))
        brng = np.random.default_rng(0)
        for m_, L in units.items():
            u = {k: np.concatenate([x[k] for x in L]) for k in L[0] if k != "kinds"}
            d = bootstrap_ratio([u["strip"], u["strip_area"], u["inner"], u["inner_area"]],
                                lambda s_, sa, i, ia: (s_.sum() / sa.sum()) / (i.sum() / ia.sum()), 1000, brng)
            ks = {}
            for j in range(u["strip_kind"].shape[1]):
                ks[names[j]] = bootstrap_ratio([u["strip_kind"][:, j], u["strip"], u["inner_kind"][:, j], u["inner"]],
                                               lambda sk, s_, ik, i: (sk.sum() / s_.sum()) / (ik.sum() / i.sum()), 1000, brng)
            msc = bootstrap_ratio([u["strip_sc"], u["strip"], u["inner_sc"], u["inner"]],
                                  lambda a, b, c, e: (a.sum() / b.sum()) / (c.sum() / e.sum()), 1000, brng)
            cov = bootstrap_ratio([u["strip_a"], u["strip_area"], u["inner_a"], u["inner_area"]],
                                  lambda a, b, c, e: (a.sum() / b.sum()) / (c.sum() / e.sum()), 1000, brng)
            res["strips"][f"{m_:g}s"] = {"density": d, "kinds": ks, "mean_scale": msc, "cover": cov, "strip_elements": int(u["strip"].sum())}
            print(f"+-{m_:g}s density {d['value']:.3f} [{d['ci'][0]:.3f}, {d['ci'][1]:.3f}]  "
                  + "; ".join(f"{k} {r['value']:.3f} [{r['ci'][0]:.3f}, {r['ci'][1]:.3f}]" for k, r in ks.items())
                  + f"; mean scale {msc['value']:.3f} [{msc['ci'][0]:.3f}, {msc['ci'][1]:.3f}]"
                  + f"; scale^2 cover {cov['value']:.3f} [{cov['ci'][0]:.3f}, {cov['ci'][1]:.3f}]  strip el {int(u['strip'].sum())}")
        out[tag] = res
    path = RES / f"pack_seam_profile_{'_'.join(tags)}.json"
    path.write_text(json.dumps(out, indent=1))
    print(f"wrote {path}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", default="1,2")
    ap.add_argument("--side", type=float, default=2400.0)
    ap.add_argument("--tile", type=float, default=300.0)
    ap.add_argument("--tag", default="base")
    ap.add_argument("--untiled", action="store_true")
    ap.add_argument("--set", action="append", default=[], help="NAME=VALUE: set strew.tiles.NAME (a variant)")
    ap.add_argument("--analyze", nargs="+", default=None, help="tags of saved worlds to print")
    ap.add_argument("--quick", action="store_true", help="seed 1, a 3 x 3-tile world, tag quick, then its analysis (a check of the script)")
    args = ap.parse_args()
    if args.quick and not args.analyze:
        args.seeds, args.side, args.tag = "1", 3 * args.tile, "quick"
        make(args)
        analyze([args.tag])
    elif args.analyze:
        analyze(args.analyze)
    else:
        make(args)


if __name__ == "__main__":
    main()
