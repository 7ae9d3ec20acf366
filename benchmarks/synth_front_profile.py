"""Tiled synth: the density of each kind across the tile borders, out to 6 spacings
(issue 19 point 4; ``worlds_strips.py`` prints the same profile to 3 spacings).

A world of ``--side`` (default 2640) in tiles of 440 (two exemplar frames), synth on a
fidelity-suite exemplar, for each seed; the centres by signed distance to the nearest
inner border, positive into the tile of the later phase (strew.tiles' 2 x 2 colouring),
in bins of half a spacing ``s`` (``s = 1 / sqrt(density)``), along the inner tiles'
part of each border (``tests/worlds/world_stats.signed_profile``). Each kind's count per bin over its mean in the
bins 4-6 s from the border on both sides; and the strips' density and kind-fraction
ratios (centres within 1, 2, 3 s of an inner border against the rest, as
``worlds_strips.py`` defines them, no intervals). ``--untiled``: the same on one
untiled run (the control). CPU time per element of the runs.

    python benchmarks/synth_front_profile.py [--exemplar two_sizes] [--seeds 1,2] [--untiled] [--variant V]

``--variant V`` measures a change of the hand-over made here, at run time (helper
front19d; nothing in ``src`` changes, and the untiled run is never affected):

- ``t4:F``: the finished tile hands over its small elements (bounding radius under half
  the largest) only to centres within ``F D`` + their radius of its rectangle (``D`` the
  band, one element diameter), and the later tile's region starts at ``F D``;
- ``t5:F``: the finished tile keeps each element whose disc reaches into ``D + 2 F r``,
  ``r`` the largest radius under half its own (its large elements out past the small
  ones' envelope, so no dropped large element leaves a pocket in the kept small ones);
- ``killsmall``: the later tile starts with the context's free-space points that only a
  smaller class fills dead;
- ``owed``: the later tile's ``owed_classes`` counts only its own elements (not the
  context's);
- ``front:K``: the later tile starts with only the context elements within ``K``
  radii of its region on the horizon (growth from the front layer);
- ``noopt``: tiles with a context grow without the optimisation (§5.2); the first
  phase's tiles, and so the finished side of every border, keep it.
- ``holes:F[:G]`` (helper holes19e): the finished tile hands over the discs of the
  elements it dropped whose bounding radius is at least ``G`` (default src's) of its
  largest and whose centre lies within ``D + F D`` of its rectangle (``D`` the band) in
  ``meta["synth_holes"]`` (position, radius, kind); the later tile puts a copy of that
  kind at each disc centre before it grows (one at a time, skipped where it would
  collide or lies outside its region), matched to its neighbourhood as the context is
  (Eq. 1) and a seed of the growth like any horizon element (§5.1): its large elements
  get the dropped ones' places before small ones fill them. In ``src`` since 9defcf9
  (``strew.tiles._SYNTH_HOLES_REACH`` = 1 + F = 2, ``_SYNTH_HOLES_LARGE`` = G = 0.5,
  0.35 since helper synth19f): the variant sets those two and counts the discs and copies;
- ``noholes``: no hand-over of dropped large elements (the code before 9defcf9).

Writes ``benchmarks/results/synth_front_profile.json``.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))
sys.path.insert(0, str(HERE.parent / "tests" / "worlds"))

TILE = 440.0
HOLES = {"handed": 0, "seeded": 0}  # --variant holes: discs handed over, copies put there
REACH = 6.0


def apply_variant(variant: str) -> None:
    """Patch strew.tiles / strew.synth in this process for ``--variant`` (see above)."""
    import strew.synth._context as C
    import strew.synth._grow as G
    import strew.tiles as T

    name, _, arg = variant.partition(":")
    if name == "holes":
        _holes_variant(*(float(v) for v in arg.split(":")))
        return
    if name == "noholes":
        _holes_variant(1.0, math.inf)
        return
    if name in ("t4", "t5"):
        f = float(arg)
        within0, outside0 = T._within, T._outside_finished

        def within(arr, rect, d):
            r = T._radii(arr)
            band = float(np.max(np.asarray(d) - r))  # run_tile passes band + radius
            if name == "t4":
                return within0(arr, rect, np.where(r < 0.25 * band, f * band, band) + r)
            u = np.unique(r)
            sm = np.array([float(u[u < 0.5 * v].max()) if (u < 0.5 * v).any() else 0.0 for v in u])
            return within0(arr, rect, band + 2.0 * f * sm[np.searchsorted(u, r)] + r)

        def outside(region, t, job, links, band=0.0):
            return outside0(region, t, job, links, f * band if name == "t4" else band)

        T._within, T._outside_finished = within, outside
        return
    if name == "owed":
        owed0 = G.owed_classes

        def owed(state):
            if not state.fixed.any():
                return owed0(state)
            prep = state.prep
            ncls = int(prep.size_class.max()) + 1
            sel = prep.selected_elements & ~prep.void
            per = np.bincount(prep.source[sel], minlength=len(prep.names)).astype(float)
            unit = prep.weights / np.maximum(per, 1.0)
            ex = np.bincount(prep.size_class[sel], weights=unit[prep.source[sel]], minlength=ncls)
            src = state.src[~state.fixed]
            src = src[sel[src]]
            out = np.bincount(prep.size_class[src], weights=unit[prep.source[src]], minlength=ncls)
            if out.sum() <= 0:
                return np.ones(ncls, bool)
            share = ex / ex.sum()
            se = np.sqrt(share * (1.0 - share) / max(int(sel.sum()), 1))
            return out / out.sum() < share + G.SHARE_MARGIN * se

        G.owed_classes = owed
        return
    if name not in ("killsmall", "front", "noopt"):
        raise SystemExit(f"--variant: unknown {variant!r}")
    grow0 = G.grow

    def grow(state, **kw):
        ctx = np.flatnonzero(state.fixed & ~state.ghost & state.horizon)
        if len(ctx) and not getattr(state, "_front19d", False):
            state._front19d = True
            prep = state.prep
            if name == "noopt":
                import dataclasses

                state.params = dataclasses.replace(state.params, optimize="none")
            elif name == "killsmall":
                _fpos, fr, _fc, flag, _o = state.free_points(ctx)
                big = int(prep.size_class.max())
                state._alive[flag[fr < float(prep.r[prep.size_class == big].min())]] = False
                G.update_free_space(state, ctx)
            else:
                import shapely

                d = shapely.distance(state.region.geometry, shapely.points(state.pos[ctx]))
                state._horizon[ctx[d > float(arg) * prep.r[state.src[ctx]]]] = False
        return grow0(state, **kw)

    G.grow = grow
    assert C  # fill_with_context imports grow from _grow when it runs


def _holes_variant(f: float, g: float | None = None) -> None:
    """``--variant holes:F[:G]`` (see the module's docstring): src's hand-over
    (``strew.tiles._synth_holes_out``, ``strew.synth._context.add_holes``) with reach
    ``1 + F`` bands and size cut ``G``, counting the discs and copies; ``G`` inf
    (``noholes``) hands over none."""
    import strew.synth._context as C
    import strew.tiles as T

    T._SYNTH_HOLES_REACH, T._SYNTH_HOLES_LARGE = 1.0 + f, T._SYNTH_HOLES_LARGE if g is None else g
    out0, add0 = T._synth_holes_out, C.add_holes

    def holes_out(*a):
        h = out0(*a)
        HOLES["handed"] += len(h)
        return h

    def add_holes(*a):
        n = add0(*a)
        HOLES["seeded"] += n
        return n

    T._synth_holes_out, C.add_holes = holes_out, add_holes


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--exemplar", default="two_sizes")
    ap.add_argument("--seeds", default="1,2")
    ap.add_argument("--side", type=float, default=2640.0)
    ap.add_argument("--untiled", action="store_true")
    ap.add_argument("--out", default=str(HERE / "results" / "synth_front_profile.json"))
    ap.add_argument("--variant", default=None, help="a hand-over change measured here (see the module's docstring)")
    ap.add_argument("--quick", action="store_true", help="one seed, a 3 x 3-tile world (a check of the script)")
    args = ap.parse_args()
    if args.quick:
        args.seeds, args.side = args.seeds.split(",")[0], 3 * TILE
    import strew
    from strew.synth import synthesize

    if args.variant:
        apply_variant(args.variant)
    from strew.tiles import tiled
    from strew_testing import fidelity_suite
    from world_stats import signed_profile, strip_units

    ex = fidelity_suite().make_exemplar(args.exemplar)
    side = args.side
    tot, cpu, nel, s, units = None, 0.0, 0, None, {1: [], 2: [], 3: []}
    for seed in (int(v) for v in args.seeds.split(",")):
        t0 = time.process_time()
        if args.untiled:
            arr = synthesize(ex, strew.Region.rectangle(side, side), rng=seed, measure=False)
        else:
            arr = tiled("synth", ex, (side, side), tile_size=TILE, seed=seed, measure=False)
        cpu += time.process_time() - t0
        nel += len(arr)
        s = s or 1.0 / np.sqrt(len(arr) / side**2)
        c = signed_profile(arr, (side, side), TILE, s, REACH)["counts"].astype(float)
        tot = c if tot is None else tot + c
        for m in units:
            units[m].append(strip_units(arr, (side, side), TILE, m * s, max(110.0, 3 * s)))
    far = np.concatenate([tot[:, :4], tot[:, -4:]], axis=1).mean(axis=1)
    rel = tot / far[:, None]
    names = ["all", *arr.kinds]
    mode = "untiled" if args.untiled else "tiled" + (f" variant {args.variant}" if args.variant else "")
    print(f"{args.exemplar} {mode} seeds {args.seeds} side {side:g}: {nel} el, {cpu:.1f} CPU s, {cpu / nel * 1e3:.3f} ms/el, s {s:.2f}")
    edges = (np.arange(-2 * REACH, 2 * REACH) * 0.5).tolist()
    print("bin from (s):", " ".join(f"{v:5.1f}" for v in edges))
    for name, row, f in zip(names, rel, far):
        print(f"{name:8s}", " ".join(f"{v:5.2f}" for v in row), f"(far {f:.0f} a bin)")
    strips = {}
    for m, us in units.items():
        u = {f: np.concatenate([w[f] for w in us]) for f in us[0] if f != "kinds"}
        d = (u["strip"].sum() / u["strip_area"].sum()) / (u["inner"].sum() / u["inner_area"].sum())
        sk, ik = u["strip_kind"].sum(0), u["inner_kind"].sum(0)
        kinds = {n: float((a / sk.sum()) / (b / ik.sum())) for n, a, b in zip(arr.kinds, sk, ik)}
        strips[f"{m}s"] = {"density_ratio": float(d), "kind_fraction_ratio": kinds}
        print(f"strips +-{m}s: density {d:.3f}; kinds " + ", ".join(f"{n} {v:.3f}" for n, v in kinds.items()))
    if args.variant and args.variant.startswith("holes"):
        print(f"holes: {HOLES['handed']} discs handed over, {HOLES['seeded']} copies seeded")
    out = Path(args.out)
    out.parent.mkdir(exist_ok=True)
    res = {"benchmark": "synth_front_profile", "command": " ".join(["python benchmarks/synth_front_profile.py", *sys.argv[1:]]),
           "exemplar": args.exemplar, "mode": mode, "variant": args.variant, "cpu_ms_per_element": cpu / nel * 1e3, "elements": nel, "cpu_s": cpu, "spacing": float(s), "bin_from_s": edges,
           "relative_density": {n: row.tolist() for n, row in zip(names, rel)}, "strips": strips}
    if args.variant and args.variant.startswith("holes"):
        res["holes"] = dict(HOLES)
    out.write_text(json.dumps(res, indent=1) + "\n")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
