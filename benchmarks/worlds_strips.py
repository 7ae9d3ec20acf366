"""Border strips of tiled worlds against their interior (issue 19 point 4), with intervals.

For each tiled method (pack, synth, ornament; program's partitions are exact, see
tests/worlds/test_program_tiles.py) a world of several thousand elements per border strip
is made tile by tile (:func:`strew.tiles.tiled`, default halo) for a few seeds, and the
same world untiled (one run of the method, the control: the same statistics on the same
lines, where no border exists).

Definitions (the same for every method):

- spacing ``s = 1 / sqrt(density)`` (the world's mean element spacing);
- the *strips*: centres within ``2 s`` of an inner tile border (a band ``4 s`` wide
  about each border line; also reported at ``1 s``); the *interior*: every other centre.
  Both leave out the world's own edge band (a halo, at least ``3 s``: the world's edge
  is no border);
- the *units*: the tiles of all seeds. A statistic is a ratio of sums over units, and its
  95 % interval is the percentile interval of 2,000 bootstrap resamples of the units
  (so the tile-to-tile and seed-to-seed variation are in it);
- density ratio: (strip count / strip area) / (interior count / interior area);
  kind-fraction ratio of kind k: (strip share of k) / (interior share of k);
- density by phase: each tile's density (strip and interior) by its phase in the 2 x 2
  colouring (phase 0 runs alone, 1-3 around finished neighbours) against all tiles';
- fidelity (:func:`strew.metrics.fidelity`, local map; synth against its exemplar, pack
  and ornament against an untiled run of the method on a square of about one tile): a
  *border window* has a tile border crossing its middle half, an *interior window* lies
  inside one tile; per class the median window score, the mean score and the share of
  failing windows (score > 1), their ratios with bootstrap intervals over the tiles
  holding the windows' centres;
- tiled / untiled: each ratio above over the untiled control's on the same lines (the
  tiles of a tiled world and of its control paired by seed, tile size and position; the
  interval from paired resamples). A strip ratio off 1 in the control is what the lines
  see where no border exists (a world not stationary at the tile's scale, e.g. ornament's
  hierarchy grown from the first-phase tiles' seed points); the double ratio is what the
  seams add (world_stats.strip_ratios_against_control; helper w60d);
- overlaps: pairs of elements whose intersection has area > 1e-9 (shapely, exact
  polygons), all pairs and those across tiles;
- grid: the centres' density folded modulo the tile size across the borders (x and y
  pooled, the inner tiles only, so that the world's edges do not fold onto the
  borders): chi-square against flat (its p-value), and the density of the bins within
  ``s`` of a border against the others.

Run: ``python benchmarks/worlds_strips.py [--methods pack,synth,ornament] [--seeds 1,2]
[--quick] [--no-control] [--raw R] [--synth-exemplar three_sizes] [--widths 3,2,1]
[--ornament-pattern NAME] [--ornament-tiles 120,110,130] [--coverage]``. Writes ``benchmarks/results/worlds_strips.json``.
``--from-raw R [--dedupe]`` summarizes the measurements an earlier ``--raw R`` run kept.
``--ornament-tiles T1,T2,..``: ornament's worlds also at these tile sizes (side 4 tiles,
halo the default T / 4). The flowers pattern draws nothing from the seed and a tile's
result depends only on its grown rectangle's shape and its context, so the seeds give one
world and the inner tiles of one phase repeat each other; another tile size is another
world (issue 19.4: several independent measurements; printed per world as well).
``--overview``: the overview PNG's ink (the grid as the eye sees it), folded modulo the
tile, tiled against untiled (``worlds_strips_overview.json``).
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests" / "worlds"))
sys.path.insert(0, str(HERE.parent / "tests"))

from world_stats import (  # noqa: E402
    border_window_scores,
    bootstrap_ratio,
    folded_profile,
    overlapping_pairs,
    overlapping_pairs_across,
    overview_profile,
    profile_test,
    signed_profile,
    strip_ratios_against_control,
    strip_units,
)

def _configs(quick: bool) -> dict:
    """method -> (input, world side, tile size, params, fidelity exemplar maker)."""
    import strew
    from strew_testing import fidelity_suite

    bar_disc = {"bar": strew.Shape.rectangle(3, 1.5), "disc": strew.Shape.circle(1.0, 16)}
    two = fidelity_suite().make_exemplar("two_sizes")  # frame 220, stones and pebbles

    def pack_ex():
        from strew.pack import pack

        return pack(bar_disc, strew.Region.rectangle(60, 60), rng=0)

    def orn_ex():
        from strew.ornament import grow_ornament

        return grow_ornament("flowers", strew.Region.rectangle(60, 60), rng=0)

    def stones():
        from strew._resources import example_path
        from strew.io import load_shapes

        return load_shapes(example_path("pack", "stones.json"))

    def stones_ex():
        from strew.pack import pack

        return pack(stones(), strew.Region.rectangle(900, 900), scale=(0.55, 0.75), rng=0)

    return {
        # ~1,400 elements a tile (benchmarks/worlds.py's pack world)
        "pack": dict(input=bar_disc, side=400.0 if quick else 800.0, tile=100.0, params={}, exemplar=pack_ex),
        # tiles of 2 exemplar frames (fidelity's window, about a frame, fits inside a tile)
        "synth": dict(input=two, side=1320.0 if quick else 2640.0, tile=440.0, params={"measure": False}, exemplar=lambda: two),
        # flowers: 4 kinds (stem, leaf, flower, bud)
        "ornament": dict(input="flowers", side=360.0 if quick else 480.0, tile=120.0, params={}, exemplar=orn_ex),
        # pack on another input (--methods pack_stones): strew demo's concave stones (a
        # ring with a hole, a hook, a crescent) at its scale 0.55-0.75, ~1,600 elements a tile
        "pack_stones": dict(method="pack", input=stones(), side=3600.0 if quick else 7200.0, tile=900.0,
                            params={"scale": (0.55, 0.75)}, exemplar=stones_ex),
    }


WIDTHS = (2.0, 1.0)
"""Strip half-widths in spacings (``--widths``)."""

COVERAGE = False
"""``--coverage``: also the drawn geometry's amount by kind in strips and interior."""


def _synth_exemplar(cfgs: dict, name: str | None) -> dict:
    """``--synth-exemplar NAME``: synth's world on another exemplar of the fidelity suite
    (e.g. three_sizes: small, medium and large stones), the same side and tiles."""
    if not name:
        return cfgs
    from strew_testing import fidelity_suite

    ex = fidelity_suite().make_exemplar(name)
    cfgs["synth"] = dict(cfgs["synth"], input=ex, exemplar=lambda: ex)
    return cfgs


def _ornament_pattern(cfgs: dict, argv: list[str]) -> dict:
    """``--ornament-pattern NAME`` (issue 19.4, another pattern than flowers): ornament's
    world grows NAME, its fidelity exemplar too; the world and tile sizes stay."""
    if "--ornament-pattern" not in argv:
        return cfgs
    name = argv[argv.index("--ornament-pattern") + 1]

    def ex():
        import strew
        from strew.ornament import grow_ornament

        return grow_ornament(name, strew.Region.rectangle(60, 60), rng=0)

    cfgs["ornament"] = dict(cfgs["ornament"], input=name, exemplar=ex)
    return cfgs


def _same(a, b) -> bool:
    """The same elements (meta, which records the seed, aside)."""
    return len(a) == len(b) and all(np.array_equal(np.asarray(getattr(a, f)), np.asarray(getattr(b, f)))
                                    for f in ("x", "y", "kind", "rotation"))


def _cpu() -> float:
    return time.process_time()


def measure_world(arr, size, tile, halo, spacing, exemplar=None) -> dict:
    """Per-unit strip counts (two widths), overlaps, folded profile and border windows of one world."""
    out: dict = {"elements": len(arr)}
    # the world's own edge band: a halo, and at least 3 spacings (an untiled pack's
    # density differs within about 1.5 spacings of the region's edge)
    margin = max(halo, 3.0 * spacing)
    for mult in WIDTHS:
        out[f"units_{mult:g}s"] = strip_units(arr, size, tile, mult * spacing, margin)
    if COVERAGE:
        for mult in WIDTHS:
            out[f"cover_{mult:g}s"] = coverage_units(arr, size, tile, mult * spacing, margin)
    t0 = _cpu()
    out["overlaps"] = overlapping_pairs(arr)
    if "tile" in arr.columns:
        out["overlaps_across_tiles"] = overlapping_pairs_across(arr, arr["tile"])
    out["overlap_cpu_s"] = _cpu() - t0
    out["profile"] = folded_profile(arr, size, tile, spacing)
    out["signed"] = signed_profile(arr, size, tile, spacing)
    if exemplar is not None:
        from strew.metrics import fidelity

        t0 = _cpu()
        rep = fidelity(exemplar, arr, eq5=False, local=True)
        out["fidelity_cpu_s"] = _cpu() - t0
        out["faithful"] = bool(rep.faithful)
        out["windows"] = border_window_scores(rep.local, tile)
    return out


def coverage_units(arr, size, tile: float, width: float, margin: float) -> dict:
    """``--coverage``: per tile, how much the elements' drawn geometry lies in the strips
    and in the interior, by kind: its area where it is a polygon, its length where it is
    a line (the outline style draws strokes): ``strip``, ``inner`` (the sets' areas),
    ``strip_kind``, ``inner_kind`` ((tiles, kinds) amounts). A long element (willow's
    stems, which a later tile starts at the cut and runs inward) counts where it lies,
    not at its midpoint."""
    import shapely

    w, h = size
    t = float(tile)
    nx, ny = max(1, int(np.ceil(w / t - 1e-9))), max(1, int(np.ceil(h / t - 1e-9)))
    box = shapely.box(margin, margin, w - margin, h - margin)
    bands = [shapely.box(k * t - width, 0, k * t + width, h) for k in range(1, nx)]
    bands += [shapely.box(0, k * t - width, w, k * t + width) for k in range(1, ny)]
    strip = shapely.intersection(shapely.union_all(bands), box) if bands else shapely.Polygon()
    inner = shapely.difference(box, strip)
    geoms = arr.geometry_of("geometry")
    poly = shapely.area(geoms) > 0
    kind = np.asarray(arr.kind, np.int64)
    tree = shapely.STRtree(geoms)
    n, nk = nx * ny, len(arr.kinds)
    out = {name: np.zeros(n) for name in ("strip", "inner")}
    out.update({f"{name}_kind": np.zeros((n, nk)) for name in ("strip", "inner")})
    for jj in range(ny):
        for ii in range(nx):
            cell = shapely.box(ii * t, jj * t, min(w, (ii + 1) * t), min(h, (jj + 1) * t))
            u = jj * nx + ii
            for name, part in (("strip", strip), ("inner", inner)):
                piece = shapely.intersection(part, cell)
                out[name][u] = shapely.area(piece)
                idx = tree.query(piece, predicate="intersects")
                if not len(idx):
                    continue
                cut = shapely.intersection(geoms[idx], piece)
                amount = np.where(poly[idx], shapely.area(cut), shapely.length(cut))
                np.add.at(out[f"{name}_kind"][u], kind[idx], amount)
    return out


def summarize(worlds: list[dict], boot: int, rng: np.random.Generator, kinds: list[str]) -> dict:
    """Ratios and intervals pooled over the worlds' tiles."""
    res: dict = {}
    for key in [k for k in worlds[0] if k.startswith("units_")]:
        units = {f: np.concatenate([w[key][f] for w in worlds]) for f in worlds[0][key] if f != "kinds"}
        # density: (sum strip / sum strip area) / (sum interior / sum interior area)
        dens = bootstrap_ratio([units["strip"], units["strip_area"], units["inner"], units["inner_area"]],
                               lambda s, sa, i, ia: (s.sum() / sa.sum()) / (i.sum() / ia.sum()), boot, rng)
        kd = {}
        for k, name in enumerate(kinds):
            kd[name] = bootstrap_ratio([units["strip_kind"][:, k], units["strip"], units["inner_kind"][:, k], units["inner"]],
                                       lambda sk, s, ik, i: (sk.sum() / s.sum()) / (ik.sum() / max(i.sum(), 1)), boot, rng)
        # a tile's density by its phase (strew.tiles: phase 0 runs alone, 1-3 around
        # finished neighbours): a stationary world has the same in every phase
        by_phase = {}
        for p in range(4):
            by_phase[str(p)] = bootstrap_ratio(
                [units["strip"] + units["inner"], units["strip_area"] + units["inner_area"], units["phase"]],
                lambda c, a, ph, p=p: (c[ph == p].sum() / max(a[ph == p].sum(), 1e-300)) / (c.sum() / a.sum()), boot, rng)
        res[key] = {"density_by_phase": by_phase, "strip_elements": int(units["strip"].sum()), "interior_elements": int(units["inner"].sum()),
                    "units": int(len(units["strip"])), "density_ratio": dens, "kind_fraction_ratio": kd}
    for key in [k for k in worlds[0] if k.startswith("cover_")]:
        u = {f: np.concatenate([w[key][f] for w in worlds]) for f in worlds[0][key]}
        cov = {"all": bootstrap_ratio([u["strip_kind"].sum(1), u["strip"], u["inner_kind"].sum(1), u["inner"]],
                                      lambda sk, s, ik, i: (sk.sum() / s.sum()) / (ik.sum() / i.sum()), boot, rng)}
        for k, name in enumerate(kinds):
            cov[name] = bootstrap_ratio([u["strip_kind"][:, k], u["strip"], u["inner_kind"][:, k], u["inner"]],
                                        lambda sk, s, ik, i: (sk.sum() / s.sum()) / (ik.sum() / max(i.sum(), 1)), boot, rng)
        res[key] = {"covered_area_ratio": cov, "interior_covered": float(u["inner_kind"].sum() / u["inner"].sum())}
    prof = [w["profile"] for w in worlds]
    if len({len(p["counts"]) for p in prof}) == 1:
        counts = np.sum([p["counts"] for p in prof], axis=0)
        res["profile"] = profile_test(counts, prof[0]["exposure"], prof[0]["near_bins"])
    else:  # worlds of several tile sizes (--ornament-tiles): bins differ, tests pooled
        res["profile"] = _pooled_profile(prof)
    if len({tuple(w.get("world", [0, 0])) for w in worlds}) > 1:
        res["per_world"] = [_world_points(w, kinds) for w in worlds]
    sc = np.sum([w["signed"]["counts"] for w in worlds], axis=0).astype(float)
    outer = sc[0][[0, 1, -2, -1]].mean()  # the bins 2-3 spacings from the border
    res["signed_profile"] = {"edges_in_spacings": [float(v) for v in worlds[0]["signed"]["edges"]],
                             "relative_density": {name: [float(v) for v in row / outer]
                                                  for name, row in zip(["all", *kinds], sc)},
                             "note": "positive into the later tile; density relative to the bins 2-3 spacings out (all kinds)"}
    res["overlaps"] = int(sum(w["overlaps"] for w in worlds))
    if "overlaps_across_tiles" in worlds[0]:
        res["overlaps_across_tiles"] = int(sum(w["overlaps_across_tiles"] for w in worlds))
    if "windows" in worlds[0]:
        win = {c: {f: np.concatenate([w["windows"][c][f] for w in worlds]) for f in ("score", "unit")} for c in ("border", "interior")}
        # units: (world, tile) pairs, so that resampling keeps a tile's windows together
        for c in win:
            win[c]["unit"] = np.concatenate([w["windows"][c]["unit"] + 1_000_000 * i for i, w in enumerate(worlds)])
        res["fidelity"] = fidelity_summary(win, boot, rng)
        res["faithful"] = [w["faithful"] for w in worlds]
    return res


def _pooled_profile(prof: list[dict]) -> dict:
    """profile_test over worlds whose folded profiles have different bins: chi-square and
    degrees of freedom summed, the near / far counts and expectations summed."""
    from scipy import stats

    chi2 = dof = 0.0
    cn = cf = en = ef = 0.0
    for p in prof:
        c = np.asarray(p["counts"], float)
        e = c.sum() * np.asarray(p["exposure"], float)
        chi2 += float(((c - e) ** 2 / e).sum())
        dof += len(c) - 1
        near = np.asarray(p["near_bins"], bool)
        cn, cf, en, ef = cn + c[near].sum(), cf + c[~near].sum(), en + e[near].sum(), ef + e[~near].sum()
    r = (cn / en) / (cf / ef)
    se = np.sqrt(1 / cn + 1 / cf)
    return {"bins": int(dof + len(prof)), "chi2_dof": chi2 / dof, "p": float(stats.chi2.sf(chi2, dof)),
            "near_ratio": {"value": float(r), "ci": [float(r * np.exp(-1.96 * se)), float(r * np.exp(1.96 * se))]}}


def _world_points(w: dict, kinds: list[str]) -> dict:
    """One world's point ratios (density and kind fractions, strips against interior)."""
    out: dict = {"world": w.get("world"), "elements": w["elements"]}
    for key in [k for k in w if k.startswith("units_")]:
        u = w[key]
        s, i = u["strip"].sum(), u["inner"].sum()
        row = {"density": float((s / u["strip_area"].sum()) / (i / u["inner_area"].sum()))}
        for k, name in enumerate(kinds):
            row[name] = float((u["strip_kind"][:, k].sum() / s) / max(u["inner_kind"][:, k].sum() / max(i, 1), 1e-300))
        out[key[6:]] = row
    for key in [k for k in w if k.startswith("cover_")]:
        u = w[key]
        row = {"covered": float((u["strip_kind"].sum() / u["strip"].sum()) / (u["inner_kind"].sum() / u["inner"].sum()))}
        for k, name in enumerate(kinds):
            row[name] = float((u["strip_kind"][:, k].sum() / u["strip"].sum()) / max(u["inner_kind"][:, k].sum() / u["inner"].sum(), 1e-300))
        out["cover " + key[6:]] = row
    return out


def fidelity_summary(win: dict, boot: int, rng: np.random.Generator) -> dict:
    """Median / mean score and failing share of border vs interior windows, ratios with
    intervals from resampling the tiles (a tile's windows together)."""
    b, i = win["border"], win["interior"]
    units = np.union1d(b["unit"], i["unit"])
    bi = {u: np.flatnonzero(b["unit"] == u) for u in units}
    ii = {u: np.flatnonzero(i["unit"] == u) for u in units}

    def stats(sb, si):
        return {"median": (np.median(sb), np.median(si)), "mean": (np.mean(sb), np.mean(si)),
                "failing": (np.mean(sb > 1), np.mean(si > 1))}

    point = stats(b["score"], i["score"])
    draws: dict = {k: [] for k in point}
    for _ in range(boot):
        pick = rng.choice(units, len(units))
        sb = b["score"][np.concatenate([bi[u] for u in pick])]
        si = i["score"][np.concatenate([ii[u] for u in pick])]
        if not (len(sb) and len(si)):
            continue
        for k, (x, y) in stats(sb, si).items():
            draws[k].append((x, y))
    out = {"border_windows": int(len(b["score"])), "interior_windows": int(len(i["score"]))}
    for k, (x, y) in point.items():
        d = np.array(draws[k])
        row = {"border": float(x), "interior": float(y), "border_ci": [float(v) for v in np.percentile(d[:, 0], [2.5, 97.5])],
               "interior_ci": [float(v) for v in np.percentile(d[:, 1], [2.5, 97.5])]}
        if k != "failing":
            r = d[:, 0] / d[:, 1]
            row.update(ratio=float(x / y), ratio_ci=[float(v) for v in np.percentile(r, [2.5, 97.5])])
        else:
            diff = d[:, 0] - d[:, 1]
            row.update(difference=float(x - y), difference_ci=[float(v) for v in np.percentile(diff, [2.5, 97.5])])
        out[k] = row
    return out


def _fmt(r: dict) -> str:
    return f"{r['value']:.3f} [{r['ci'][0]:.3f}, {r['ci'][1]:.3f}]"


def report(method: str, mode: str, s: dict) -> None:
    for key in [k for k in s if k.startswith("units_")]:
        v = s[key]
        kinds = ", ".join(f"{k} {_fmt(r)}" for k, r in v["kind_fraction_ratio"].items())
        if key == "units_2s":
            print(f"  {method:8s} {mode:8s} tile density by phase / all: "
                  + ", ".join(f"phase {p} {_fmt(r)}" for p, r in v["density_by_phase"].items()), flush=True)
        print(f"  {method:8s} {mode:8s} strips +-{key[6:]}: {v['strip_elements']:,} strip / {v['interior_elements']:,} interior el, "
              f"{v['units']} tiles: density ratio {_fmt(v['density_ratio'])}; kind-fraction ratios {kinds}", flush=True)
    for key in [k for k in s if k.startswith("cover_")]:
        c = s[key]["covered_area_ratio"]
        print(f"  {method:8s} {mode:8s} drawn geometry +-{key[6:]} per area, strip / interior: "
              + ", ".join(f"{k} {_fmt(r)}" for k, r in c.items()), flush=True)
    for pw in s.get("per_world", []):
        print(f"  {method:8s} {mode:8s} world seed {pw['world'][0]} tile {pw['world'][1]:g} ({pw['elements']:,} el): "
              + "; ".join(f"+-{k}: " + " ".join(f"{n} {v:.3f}" for n, v in pw[k].items()) for k in pw if k not in ("world", "elements")),
              flush=True)
    sp = s["signed_profile"]
    for name, row in sp["relative_density"].items():
        print(f"  {method:8s} {mode:8s} signed profile {name:7s} (s/2 bins, -3s..+3s into the later tile): "
              + " ".join(f"{v:.2f}" for v in row), flush=True)
    p = s["profile"]
    print(f"  {method:8s} {mode:8s} folded profile ({p['bins']} bins of the tile): chi2/dof {p['chi2_dof']:.2f} (p {p['p']:.3f}); "
          f"bins within 1 s of a border {_fmt(p['near_ratio'])} x the others; overlaps {s['overlaps']}"
          + (f" (across tiles {s['overlaps_across_tiles']})" if "overlaps_across_tiles" in s else ""), flush=True)
    if "fidelity" in s:
        f = s["fidelity"]
        print(f"  {method:8s} {mode:8s} fidelity windows: {f['border_windows']} border / {f['interior_windows']} interior; "
              f"median score {f['median']['border']:.3f} / {f['median']['interior']:.3f} = {f['median']['ratio']:.3f} "
              f"[{f['median']['ratio_ci'][0]:.3f}, {f['median']['ratio_ci'][1]:.3f}]; mean {f['mean']['ratio']:.3f} "
              f"[{f['mean']['ratio_ci'][0]:.3f}, {f['mean']['ratio_ci'][1]:.3f}]; failing {f['failing']['border']:.3f} / "
              f"{f['failing']['interior']:.3f} (difference {f['failing']['difference']:+.3f} [{f['failing']['difference_ci'][0]:+.3f}, "
              f"{f['failing']['difference_ci'][1]:+.3f}]); faithful {s['faithful']}", flush=True)


def against_control(per: dict, kinds: list[str], boot: int, rng: np.random.Generator) -> dict:
    """Per strip width: the strip-to-interior ratios of the tiled worlds over the untiled
    controls' on the same lines (world_stats.strip_ratios_against_control), the units
    (tiles) paired by world (seed and tile size) and position; worlds without a partner
    (a seed counted once, --dedupe) are left out."""
    ctl = {tuple(w.get("world", [0, 0])): w for w in per["untiled"]}
    pairs = [(w, ctl[tuple(w.get("world", [0, 0]))]) for w in per["tiled"] if tuple(w.get("world", [0, 0])) in ctl]
    out: dict = {"worlds": len(pairs)}
    for key in [k for k in per["tiled"][0] if k.startswith("units_")]:
        cat = [{f: np.concatenate([p[i][key][f] for p in pairs]) for f in ("strip", "inner", "strip_area", "inner_area", "strip_kind", "inner_kind")}
               for i in (0, 1)]
        r = strip_ratios_against_control(cat[0], cat[1], boot, rng)
        out[key] = {"density": r["density"], "kind_share": dict(zip(kinds, r["kind_share"]))}
    return out


def report_against_control(method: str, r: dict) -> None:
    for key in [k for k in r if k.startswith("units_")]:
        v = r[key]
        rows = [("density", v["density"])] + list(v["kind_share"].items())
        print(f"  {method:8s} strips +-{key[6:]}, tiled / untiled on the same lines ({r['worlds']} world pairs): "
              + "; ".join(f"{n} {_fmt(e['tiled'])} / {_fmt(e['control'])} = {_fmt(e['tiled_over_control'])}" for n, e in rows), flush=True)


def _summarize_method(result: dict, method: str, meta: dict, per: dict, args: argparse.Namespace, out_path: Path, t_all: float) -> None:
    rng = np.random.default_rng(0)
    mres = {"world": meta}
    for mode in per:
        s = summarize(per[mode], args.boot, rng, meta["kinds"])
        s["elements"] = [w["elements"] for w in per[mode]]
        s["cpu_s"] = [w["cpu_s"] for w in per[mode]]
        mres[mode] = s
        report(method, mode, s)
    if "tiled" in per and "untiled" in per:  # the same lines in both: what the seams add (issue 19.4, w60d)
        mres["tiled_over_untiled"] = against_control(per, meta["kinds"], args.boot, rng)
        report_against_control(method, mres["tiled_over_untiled"])
    result["methods"][method] = mres
    result["total_s"] = time.perf_counter() - t_all
    out_path.write_text(json.dumps(result, indent=1, default=float) + "\n")  # after each method


def overview(args: argparse.Namespace) -> None:
    """``--ornament-tiles T1,T2,..``: ornament's worlds also at these tile sizes (side 4 tiles,
halo the default T / 4). The flowers pattern draws nothing from the seed and a tile's
result depends only on its grown rectangle's shape and its context, so the seeds give one
world and the inner tiles of one phase repeat each other; another tile size is another
world (issue 19.4: several independent measurements; printed per world as well).
``--overview``: the overview PNG's ink folded modulo the tile (world_stats.overview_profile),
    tiled against untiled, first seed; writes ``worlds_strips_overview.json``."""
    import strew
    from strew._method import spec
    from strew.tiles import tiled

    cfgs = _ornament_pattern(_configs(args.quick), sys.argv)
    seed = int(args.seeds.split(",")[0])
    res: dict = {"benchmark": "worlds_strips --overview", "command": " ".join(["python benchmarks/worlds_strips.py", *sys.argv[1:]]),
                 "note": "ink: non-white pixels of strew.io._overview.Overview (2048 px on the longer side); near: within one "
                         "mean spacing s of a border, folded over the inner tiles", "methods": {}}
    for method in args.methods.split(","):
        c = cfgs[method]
        size = (c["side"], c["side"])
        row = {}
        for mode in ("tiled", "untiled"):
            if mode == "tiled":
                arr = tiled(c.get("method", method), c["input"], size, tile_size=c["tile"], seed=seed, **c["params"])
            else:
                arr = spec(c.get("method", method)).function()(c["input"], strew.Region.rectangle(*size), rng=seed, **c["params"])
            s = 1.0 / np.sqrt(len(arr) / (size[0] * size[1]))
            r = overview_profile(arr, size, c["tile"], s)
            prof = r.pop("profile")
            r.update(folded_sd=float(prof.std() / prof.mean()), folded_max=float(prof.max() / prof.mean()),
                     folded_min=float(prof.min() / prof.mean()), elements=len(arr))
            row[mode] = r
            print(f"  {method:8s} {mode:8s} overview ink within 1 s of a border {r['near']:.4f}, elsewhere {r['far']:.4f}: "
                  f"ratio {r['ratio']:.4f}; folded columns sd {r['folded_sd']:.4f}, range {r['folded_min']:.3f}-{r['folded_max']:.3f} "
                  f"({r['pixels_per_unit']:.2f} px per unit)", flush=True)
        res["methods"][method] = row
        out = HERE / "results" / "worlds_strips_overview.json"
        out.write_text(json.dumps(res, indent=1) + "\n")
    print(f"wrote {out}")


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--methods", default="pack,synth,ornament")
    ap.add_argument("--seeds", default="1,2")
    ap.add_argument("--quick", action="store_true", help="smaller worlds (a check of the script, wide intervals)")
    ap.add_argument("--no-control", action="store_true", help="skip the untiled control runs")
    ap.add_argument("--no-fidelity", action="store_true")
    ap.add_argument("--boot", type=int, default=2000)
    ap.add_argument("--out", default=str(HERE / "results" / "worlds_strips.json"))
    ap.add_argument("--raw", default=None, help="also pickle the per-world measurements here")
    ap.add_argument("--from-raw", default=None, help="only summarize the measurements pickled by an earlier --raw run")
    ap.add_argument("--dedupe", action="store_true", help="--from-raw: drop worlds with the first seed's element count")
    ap.add_argument("--ornament-pattern", default=None, help="ornament grows this pattern [default: flowers]")
    ap.add_argument("--ornament-tiles", default=None, help="ornament: worlds at these tile sizes too (side 4 tiles), e.g. 120,110,130")
    ap.add_argument("--overview", action="store_true", help="only the overview's ink folded modulo the tile (worlds_strips_overview.json)")
    ap.add_argument("--synth-exemplar", default=None, help="synth on this exemplar of the fidelity suite instead of two_sizes (e.g. three_sizes)")
    ap.add_argument("--widths", default="2,1", help="strip half-widths in spacings s (e.g. 3,2,1)")
    ap.add_argument("--coverage", action="store_true",
                    help="also the drawn geometry (area of polygons, length of lines) by kind in strips and interior")
    args = ap.parse_args()
    global WIDTHS, COVERAGE
    WIDTHS = tuple(float(v) for v in args.widths.split(","))
    COVERAGE = bool(args.coverage)
    if args.overview:
        overview(args)
        return
    import strew
    from strew._method import spec
    from strew.tiles import tiled

    t_all = time.perf_counter()
    seeds = [int(v) for v in args.seeds.split(",")]
    cfgs = _ornament_pattern(_synth_exemplar(_configs(args.quick), args.synth_exemplar), sys.argv)
    result: dict = {"benchmark": "worlds_strips", "command": " ".join(["python benchmarks/worlds_strips.py", *sys.argv[1:]]),
                    "definitions": __doc__.split("Definitions (the same for every method):")[1].split("Run:")[0].strip(),
                    "methods": {}}
    out_path = Path(args.out)
    out_path.parent.mkdir(exist_ok=True)
    for method in args.methods.split(","):
        if args.from_raw:  # summaries again from the per-world measurements of an earlier run
            import pickle

            with open(f"{args.from_raw}.{method}.pkl", "rb") as fh:
                raw = pickle.load(fh)
            meta, per = raw["world"], raw["per"]
            for mode, seed in meta.get("same_as_first_seed", []):
                print(f"  {method} {mode} seed {seed}: the same world as the first seed: counted once", flush=True)
            if args.dedupe:  # worlds whose element counts repeat the first seed's (an older run's duplicates)
                for mode in per:
                    per[mode] = [w for k, w in enumerate(per[mode]) if k == 0 or w["elements"] != per[mode][0]["elements"]]
            _summarize_method(result, method, meta, per, args, out_path, t_all)
            continue
        c = cfgs[method]
        size = (c["side"], c["side"])
        ex = None if args.no_fidelity else c["exemplar"]()
        modes = ("tiled",) if args.no_control else ("tiled", "untiled")
        per: dict = {m: [] for m in modes}
        meta: dict = {"side": c["side"], "tile": c["tile"], "seeds": seeds}
        last: dict = {}
        variants = [(c["side"], c["tile"])]
        if method == "ornament" and args.ornament_tiles:  # several worlds (see --ornament-tiles)
            variants = [(4 * float(v), float(v)) for v in args.ornament_tiles.split(",")]
            meta["variants"] = variants
        for seed, (side, tile) in [(s, v) for s in seeds for v in variants]:
            c = dict(c, side=side, tile=tile)
            size = (side, side)
            for mode in modes:
                t0 = _cpu()
                if mode == "tiled":
                    arr = tiled(c.get("method", method), c["input"], size, tile_size=c["tile"], seed=seed, **c["params"])
                    halo = float(arr.meta["world"]["halo"])
                    meta["halo"] = halo
                else:
                    arr = spec(c.get("method", method)).function()(c["input"], strew.Region.rectangle(*size), rng=seed, **c["params"])
                    halo = meta["halo"]
                cpu = _cpu() - t0
                if mode in last and last[mode][2] == tile and _same(last[mode][1], arr):  # ornament's flowers draw nothing from the seed
                    print(f"  {method} {mode} seed {seed}: the same world as seed {last[mode][0]} (the method draws "
                          "nothing from the seed): counted once", flush=True)
                    meta.setdefault("same_as_first_seed", []).append([mode, seed])
                    continue
                last[mode] = (seed, arr, tile)
                spacing = 1.0 / np.sqrt(len(arr) / (size[0] * size[1]))
                meta.setdefault("spacing", spacing)
                meta.setdefault("spacings", {}).setdefault(str(tile), spacing)  # the first (tiled) world's at this tile
                meta["kinds"] = list(arr.kinds)
                w = measure_world(arr, size, c["tile"], halo, meta["spacings"][str(tile)], ex)
                w["cpu_s"] = cpu
                w["world"] = [seed, tile]
                per[mode].append(w)
                print(f"  {method} {mode} seed {seed} tile {tile:g}: {len(arr):,} el in {cpu:.1f} CPU s (spacing {spacing:.2f}, halo {halo:g}); "
                      f"overlaps {w['overlaps']}" + (f", fidelity map {w['fidelity_cpu_s']:.1f} CPU s" if 'fidelity_cpu_s' in w else ""), flush=True)
        if args.raw:
            import pickle

            with open(f"{args.raw}.{method}.pkl", "wb") as fh:
                pickle.dump({"world": meta, "per": per}, fh)
        _summarize_method(result, method, meta, per, args, out_path, t_all)
    print(f"wrote {out_path} ({time.perf_counter() - t_all:.0f} s)")


if __name__ == "__main__":
    main()
