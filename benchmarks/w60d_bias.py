"""Bias against seam in the tiled-hierarchy strip measure (issue 19.4, helper w60d).

``python benchmarks/w60d_bias.py TILED:CONTROL --tiles 32,32.5,... [--seed 19] [--boot 4000] [--json F]``

Worlds ``benchmarks/results/orn19m_TAG_sS_TT.npz`` (benchmarks/hie15_make.py: the tiled world and
its untiled control, one run seeded at the tiled world's four first-phase seed points). Each
world is measured on the SAME lines (the tiled world's inner borders, orn19m_willow._world's
edge band left out) with two interiors:

- ``own3``: w46d's measure (hie15_pool.INNER): the strip |d| < w s against the interior
  |d| >= 3 s from every inner border. At tiles of 32-48 (s about 3.8) that interior is a
  square of about T - 6 s around each tile's centre, i.e. where the first-phase tiles
  (and the control) start their vines;
- ``rest``: worlds_strips.py's measure (tests/worlds/world_stats.strip_units): the strip
  against every other centre.

For each: density (per area) and each kind's share, strip / interior, pooled over worlds
(counts summed), for the tiled world, the control, and tiled / control (the double ratio:
what the seams add beyond what the lines see in a world without seams); 95 % percentile
intervals by a bootstrap over worlds (paired: a draw takes a world's tiled and control).
Also the interior split by the tile's phase (phase 0: the tiles that hold a seed point)
and the density profile by |d| in 1 s bins for both worlds.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
RES = HERE / "results"
sys.path.insert(0, str(HERE))
INNER = 3.0


def _phase(unit: np.ndarray) -> np.ndarray:
    i, j = unit % 4, unit // 4
    return (j % 2) * 2 + i % 2


def counts(w: dict, width: float, interior: str, phase: int | None = None) -> np.ndarray:
    """[strip area, interior area, strip n, interior n, strip per kind..., interior per kind...]."""
    ins = w["inside"]
    s = ins & (w["d"] < width)
    i = ins & ((w["d"] >= INNER) if interior == "own3" else (w["d"] >= width))
    gs = w["gd"] < width
    gi = (w["gd"] >= INNER) if interior == "own3" else (w["gd"] >= width)
    if phase is not None:  # the interior of the tiles of this phase only
        i = i & (_phase(w["unit"]) == phase)
        gi = gi & (_phase(w["gunit"]) == phase)
    nk = len(w["kinds"])
    ks = np.bincount(w["kind"][s], minlength=nk)
    ki = np.bincount(w["kind"][i], minlength=nk)
    return np.concatenate([[gs.sum() * w["garea"], gi.sum() * w["garea"], s.sum(), i.sum()], ks, ki]).astype(float)


def ratios(c: np.ndarray, nk: int) -> np.ndarray:
    """density, each kind's share (strip / interior) of summed counts c."""
    sa, ia, sn, i_n = c[:4]
    ks, ki = c[4:4 + nk], c[4 + nk:]
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.concatenate([[(sn / sa) / (i_n / ia)], (ks / sn) / (ki / i_n)])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("pair")
    ap.add_argument("--tiles", required=True)
    ap.add_argument("--seed", type=int, default=19)
    ap.add_argument("--boot", type=int, default=4000)
    ap.add_argument("--json", default=None)
    ap.add_argument("--control-only", action="store_true", help="the controls alone (every tile size that has one)")
    args = ap.parse_args()
    import orn19m_willow as W

    tt, ct = args.pair.split(":")
    worlds = []
    for tile in args.tiles.split(","):
        p, q = RES / f"orn19m_{tt}_s{args.seed}_T{tile}.npz", RES / f"orn19m_{ct}_s{args.seed}_T{tile}.npz"
        if q.exists() and (p.exists() or args.control_only):
            worlds.append((tile, W._world(p) if p.exists() and not args.control_only else None, W._world(q),
                           int(np.load(p)["overlaps"]) if p.exists() and not args.control_only else -1, int(np.load(q)["overlaps"])))
        else:
            print(f"T{tile}: missing {'tiled' if not p.exists() else 'control'}: skipped")
    if args.control_only:  # the control stands in for the tiled world: tiled = control, only the control's columns mean anything
        worlds = [(t, c, c, -1, oc) for t, _, c, _, oc in worlds]
    kinds = worlds[0][2]["kinds"]
    nk = len(kinds)
    labels = ["density"] + [f"{k}_share" for k in kinds]
    rng = np.random.default_rng(0)
    out: dict = {"tiles": [w[0] for w in worlds], "kinds": kinds, "inner_s": INNER,
                 "elements": {w[0]: [len(w[1]["x"]), len(w[2]["x"])] for w in worlds},
                 "overlaps": {w[0]: [w[3], w[4]] for w in worlds}, "measures": {}, "per_world": {}}
    if args.control_only:
        print("control only: the 'tiled' columns repeat the control; tiled elements and overlaps read -1 / the control's")
    print(f"{len(worlds)} worlds (tiles {', '.join(out['tiles'])}); elements tiled/control "
          f"{sum(v[0] for v in out['elements'].values())}/{sum(v[1] for v in out['elements'].values())}; "
          f"overlaps tiled {sum(v[0] for v in out['overlaps'].values())}, control {sum(v[1] for v in out['overlaps'].values())}")
    n = len(worlds)
    picks = rng.integers(0, n, (args.boot, n))
    for interior in ("own3", "rest"):
        for width in (1.0, 2.0):
            for phase in (None, 0, 1, 2, 3):
                if phase is not None and not (interior == "own3" and width == 2.0):
                    continue
                T = np.array([counts(w[1], width, interior, phase) for w in worlds])
                C = np.array([counts(w[2], width, interior, phase) for w in worlds])
                et, ec = ratios(T.sum(0), nk), ratios(C.sum(0), nk)
                bt = np.array([ratios(T[k].sum(0), nk) for k in picks])
                bc = np.array([ratios(C[k].sum(0), nk) for k in picks])
                ci = lambda b: np.nanpercentile(b, [2.5, 97.5], axis=0)  # noqa: E731
                (tl, th), (cl, ch), (dl, dh) = ci(bt), ci(bc), ci(bt / bc)
                key = f"{interior}_{width:g}s" + ("" if phase is None else f"_phase{phase}")
                out["measures"][key] = {lab: {"tiled": [float(et[j]), float(tl[j]), float(th[j])],
                                              "control": [float(ec[j]), float(cl[j]), float(ch[j])],
                                              "tiled_over_control": [float(et[j] / ec[j]), float(dl[j]), float(dh[j])]}
                                        for j, lab in enumerate(labels)}
                if phase is None:
                    out["per_world"][key] = {w[0]: {"tiled": ratios(T[i], nk).tolist(), "control": ratios(C[i], nk).tolist()}
                                             for i, w in enumerate(worlds)}
                M = out["measures"][key]
                print(f"\n{key}: strip / interior (95 % CI over worlds)")
                for lab in labels:
                    r = M[lab]
                    print(f"  {lab:14s} tiled {r['tiled'][0]:.3f} [{r['tiled'][1]:.3f}, {r['tiled'][2]:.3f}]   control "
                          f"{r['control'][0]:.3f} [{r['control'][1]:.3f}, {r['control'][2]:.3f}]   tiled/control "
                          f"{r['tiled_over_control'][0]:.3f} [{r['tiled_over_control'][1]:.3f}, {r['tiled_over_control'][2]:.3f}]")
    # the profile: density and kind densities by |d| in 1 s bins against |d| >= 3 s, pooled
    edges = [0, 1, 2, 3, 99]
    prof = {}
    print("\nprofile by |d| (s): density per area / the |d| >= 3 s band's, all and by kind; tiled | control")
    for name, col in (("tiled", 1), ("control", 2)):
        rows = []
        for a, b in zip(edges[:-1], edges[1:]):
            n_, k_, ar = 0, np.zeros(nk), 0.0
            for w in worlds:
                x = w[col]
                m = x["inside"] & (x["d"] >= a) & (x["d"] < b)
                n_ += m.sum()
                k_ += np.bincount(x["kind"][m], minlength=nk)
                ar += ((x["gd"] >= a) & (x["gd"] < b)).sum() * x["garea"]
            rows.append((n_ / ar, k_ / ar))
        ref, refk = rows[-1]
        prof[name] = {f"{a}-{b}": [float(r[0] / ref)] + (r[1] / refk).tolist() for (a, b), r in zip(zip(edges[:-1], edges[1:]), rows)}
    for band in prof["tiled"]:
        print(f"  |d| {band:5s} " + " ".join(f"{v:6.3f}" for v in prof["tiled"][band]) + "  | "
              + " ".join(f"{v:6.3f}" for v in prof["control"][band]))
    print("  (columns: density, " + ", ".join(kinds) + ")")
    out["profile"] = prof
    if args.json:
        Path(args.json).write_text(json.dumps(out, indent=1) + "\n")
        print(f"wrote {args.json}")



def offsets_main() -> None:
    """``python benchmarks/w60d_bias.py offsets CONTROL --tiles ... [--seed 19]``: the control's strip
    measure (own3, +-2 s and +-1 s) on lines shifted by o T (o = 0, 1/4, 1/2, 3/4: the lines x, y = o T + k T
    inside the world): a stationary world gives 1 on any lines; a world whose structure is tied to the seed
    points (hierarchy grown from the first-phase tiles' seeds, at 0.625 T and 2.5 T) gives ratios that move
    with o."""
    ap = argparse.ArgumentParser()
    ap.add_argument("cmd")
    ap.add_argument("control")
    ap.add_argument("--tiles", required=True)
    ap.add_argument("--seed", type=int, default=19)
    ap.add_argument("--boot", type=int, default=2000)
    ap.add_argument("--json", default=None)
    args = ap.parse_args()
    rng = np.random.default_rng(0)
    res: dict = {}
    zs = []
    for tile in args.tiles.split(","):
        q = RES / f"orn19m_{args.control}_s{args.seed}_T{tile}.npz"
        if q.exists():
            zs.append(np.load(q))
    kinds = [str(k) for k in zs[0]["kinds"]]
    nk = len(kinds)
    for o in (0.0, 0.25, 0.5, 0.75):
        for width in (2.0, 1.0):
            rows = []
            for z in zs:
                side, tile, halo, _ = z["meta"]
                x, y, kind = z["x"], z["y"], z["kind"].astype(np.int64)
                s = side / np.sqrt(len(x))
                margin = max(halo, 3.0 * s)
                lines = o * tile + tile * np.arange(0, 5)
                lines = lines[(lines > 0) & (lines < side)]

                def dist(a, b):
                    return np.minimum(np.min(np.abs(a[:, None] - lines), 1), np.min(np.abs(b[:, None] - lines), 1))

                ins = (x >= margin) & (x <= side - margin) & (y >= margin) & (y <= side - margin)
                d = dist(x, y) / s
                g = np.arange(0.125, side, 0.25)
                gx, gy = (v.ravel() for v in np.meshgrid(g, g))
                gok = (gx >= margin) & (gx <= side - margin) & (gy >= margin) & (gy <= side - margin)
                gd = dist(gx[gok], gy[gok]) / s
                st, it = ins & (d < width), ins & (d >= INNER)
                rows.append(np.concatenate([[(gd < width).sum() * 0.0625, (gd >= INNER).sum() * 0.0625, st.sum(), it.sum()],
                                            np.bincount(kind[st], minlength=nk), np.bincount(kind[it], minlength=nk)]))
            C = np.array(rows, float)
            est = ratios(C.sum(0), nk)
            b = np.array([ratios(C[k].sum(0), nk) for k in rng.integers(0, len(C), (args.boot, len(C)))])
            lo, hi = np.nanpercentile(b, [2.5, 97.5], axis=0)
            labels = ["density"] + [f"{k}_share" for k in kinds]
            res[f"o{o:g}_{width:g}s"] = {lab: [float(est[j]), float(lo[j]), float(hi[j])] for j, lab in enumerate(labels)}
            print(f"control lines at ({o:g} + k) T, +-{width:g}s / >= 3 s, {len(C)} worlds: "
                  + "; ".join(f"{lab} {est[j]:.3f} [{lo[j]:.3f}, {hi[j]:.3f}]" for j, lab in enumerate(labels)))
    if args.json:
        Path(args.json).write_text(json.dumps(res, indent=1) + "\n")
        print(f"wrote {args.json}")


if __name__ == "__main__" and len(sys.argv) > 1 and sys.argv[1] == "offsets":
    offsets_main()
    sys.exit(0)


if __name__ == "__main__":
    main()
