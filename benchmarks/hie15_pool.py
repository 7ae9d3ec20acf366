"""Tiled hierarchy against its untiled control by side of the border, pooled over worlds
(issue 19.4, helper hie15): one world's +-1 s strip holds too few vines to split by side
(the T94 control alone splits 0.98 | 1.21 at +-1 s).

``python benchmarks/hie15_pool.py TILED:CONTROL [TILED:CONTROL ...] [--seeds 1]
[--tiles 48,52,56,60,64,68] [--boot 4000] [--json F]``

A pair names tags of ``benchmarks/hie15_make.py`` (worlds ``orn19m_TAG_sS_TT.npz``), one
world per seed and tile size. Hierarchy's geometry does not depend on the seed (the
engine grows into the largest empty circle first, §4.1; its rng picks only the flowers'
colours: seeds 1-3 at tile 60 gave the same 3,868 elements, equal x and kind), so its
worlds differ by tile size. Per world, per strip
(+-1 s, +-2 s; s the world's mean spacing, orn19m_willow._world's lines and its world
edge band left out) and per side (``fin``: the earlier, finished tile's side; ``later``;
``both``): the strip's count of each kind per unit area against the interior's (|d| >= 3 s
from every inner border), ``density`` for all kinds together. A kind's share = its
density ratio / the density ratio. Pooled: counts summed over the worlds, then tiled /
control; 95 % interval by a paired bootstrap over worlds (a draw takes a world's tiled
and control together). Also each tree's own ratio (tiled against its own interior, and
the control's) so that a control bias shows, and each kind's mean goal radius (the
empty circle its rule success grew into) in the strip against the interior's.
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
INNER = 3.0  # the interior: at least this many spacings from every inner border
SIDES = ("fin", "later", "both")


def _expand(tag: str, seeds: list[int] | None) -> list[str]:
    return [f"{tag}_s{s}" for s in seeds] if seeds else [tag]


def _seeds(spec: str | None) -> list[int] | None:
    if not spec:
        return None
    out: list[int] = []
    for part in spec.split(","):
        a, _, b = part.partition("-")
        out.extend(range(int(a), int(b or a) + 1))
    return out


def counts(w: dict, width: float, side: str) -> np.ndarray:
    """[strip area, interior area, strip n, interior n, strip per kind..., interior per kind...,
    strip goal-radius sum per kind..., interior goal-radius sum per kind...]."""
    ins = w["inside"]
    sel = {"fin": w["sd"] < 0, "later": w["sd"] > 0, "both": np.ones(len(w["sd"]), bool)}[side]
    gsel = {"fin": w["gsd"] < 0, "later": w["gsd"] > 0, "both": np.ones(len(w["gsd"]), bool)}[side]
    s = ins & (w["d"] < width) & sel
    i = ins & (w["d"] >= INNER)
    nk = len(w["kinds"])
    ks = np.bincount(w["kind"][s], minlength=nk)
    ki = np.bincount(w["kind"][i], minlength=nk)
    gr = np.nan_to_num(w["goal_r"])
    rs = np.bincount(w["kind"][s], weights=gr[s], minlength=nk)
    ri = np.bincount(w["kind"][i], weights=gr[i], minlength=nk)
    ga = ((w["gd"] < width) & gsel).sum() * w["garea"]
    gi = (w["gd"] >= INNER).sum() * w["garea"]
    return np.concatenate([[ga, gi, s.sum(), i.sum()], ks, ki, rs, ri]).astype(float)


def ratios(c: np.ndarray, nk: int) -> np.ndarray:
    """density, each kind's density ratio, each kind's share, each kind's mean goal radius
    in the strip / in the interior (of summed counts c)."""
    sa, ia, sn, i_n = c[:4]
    ks, ki = c[4:4 + nk], c[4 + nk:4 + 2 * nk]
    rs, ri = c[4 + 2 * nk:4 + 3 * nk], c[4 + 3 * nk:]
    dens = (sn / sa) / (i_n / ia)
    with np.errstate(divide="ignore", invalid="ignore"):
        kd = (ks / sa) / (ki / ia)
        gr = (rs / ks) / (ri / ki)
    return np.concatenate([[dens], kd, kd / dens, gr])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("pairs", nargs="+")
    ap.add_argument("--seeds", default="1")
    ap.add_argument("--tiles", default="48,52,56,60,64,68")
    ap.add_argument("--boot", type=int, default=4000)
    ap.add_argument("--json", default=None)
    args = ap.parse_args()
    import orn19m_willow as W

    seeds = _seeds(args.seeds)
    worlds = []
    for pr in args.pairs:
        tt, ct = pr.split(":")
        for tile in args.tiles.split(","):
            for a, b in zip(_expand(tt, seeds), _expand(ct, seeds)):
                p, q = RES / f"orn19m_{a}_T{tile}.npz", RES / f"orn19m_{b}_T{tile}.npz"
                if p.exists() and q.exists():
                    worlds.append((f"{a}/{b} T{tile}", p, q))
                else:
                    print(f"missing {p.name if not p.exists() else q.name}: skipped")
    kinds = None
    rec = {}
    for name, p, q in worlds:
        wt, wc = W._world(p), W._world(q)
        for w, f in ((wt, p), (wc, q)):
            w["goal_r"] = np.load(f)["goal_r"]
        kinds = kinds or wt["kinds"]
        assert wt["kinds"] == kinds and wc["kinds"] == kinds, (name, wt["kinds"], wc["kinds"])
        rec[name] = {(wd, sd): (counts(wt, wd, sd), counts(wc, wd, sd)) for wd in (1.0, 2.0) for sd in SIDES}
        rec[name]["overlaps"] = (int(np.load(p)["overlaps"]), int(np.load(q)["overlaps"]))
        rec[name]["n"] = (len(wt["x"]), len(wc["x"]))
    names = list(rec)
    nk = len(kinds)
    labels = ["density"] + list(kinds) + [f"{k}_share" for k in kinds] + [f"{k}_goal_r" for k in kinds]
    rng = np.random.default_rng(0)
    out: dict = {"worlds": names, "kinds": kinds, "inner_s": INNER, "overlaps": [rec[n]["overlaps"] for n in names],
                 "elements": [rec[n]["n"] for n in names], "pooled": {}}
    print(f"{len(names)} worlds; elements tiled/control {out['elements']}; overlaps {out['overlaps']}")
    # (a pattern without twigs, the vase: its vine share instead; helper wv2)
    show = ["density"] + list(kinds) + [lab for lab in ("vine_share", "vine_goal_r", "twig_goal_r") if lab in labels and (lab != "vine_share" or "twig" not in kinds)]
    for wd in (1.0, 2.0):
        for sd in SIDES:
            T = np.array([rec[n][(wd, sd)][0] for n in names])
            C = np.array([rec[n][(wd, sd)][1] for n in names])
            est_t, est_c = ratios(T.sum(0), nk), ratios(C.sum(0), nk)
            est = est_t / est_c
            bs, bt, bc = [], [], []
            for _ in range(args.boot):
                k = rng.integers(0, len(names), len(names))
                rt, rc = ratios(T[k].sum(0), nk), ratios(C[k].sum(0), nk)
                bs.append(rt / rc)
                bt.append(rt)
                bc.append(rc)
            lo, hi = np.nanpercentile(np.array(bs), [2.5, 97.5], axis=0)
            tlo, thi = np.nanpercentile(np.array(bt), [2.5, 97.5], axis=0)
            clo, chi = np.nanpercentile(np.array(bc), [2.5, 97.5], axis=0)
            key = f"{wd:g}s_{sd}"
            out["pooled"][key] = {lab: {"ratio": float(est[j]), "ci95": [float(lo[j]), float(hi[j])],
                                        "tiled": float(est_t[j]), "tiled_ci95": [float(tlo[j]), float(thi[j])],
                                        "control": float(est_c[j]), "control_ci95": [float(clo[j]), float(chi[j])]}
                                  for j, lab in enumerate(labels)}
            out["pooled"][key]["strip_counts"] = {"tiled": T.sum(0)[4:4 + nk].astype(int).tolist(), "control": C.sum(0)[4:4 + nk].astype(int).tolist()}
            P = out["pooled"][key]
            per = np.array([ratios(T[i], nk) / ratios(C[i], nk) for i in range(len(names))])
            out["per_world"] = out.get("per_world", {})
            out["per_world"][key] = {n: dict(zip(labels, per[i].tolist())) for i, n in enumerate(names)}
            print(f"+-{wd:g}s {sd:5s} tiled/control: " + "; ".join(f"{lab} {P[lab]['ratio']:.3f} [{P[lab]['ci95'][0]:.3f}, {P[lab]['ci95'][1]:.3f}]" for lab in show))
            print(f"{'':14s}tiled/interior: " + "; ".join(f"{lab} {P[lab]['tiled']:.3f}" for lab in show)
                  + " | control/interior: " + "; ".join(f"{lab} {P[lab]['control']:.3f}" for lab in show)
                  + f" | strip counts tiled {P['strip_counts']['tiled']} control {P['strip_counts']['control']}")
    for key in ("1s_both", "2s_both"):
        print(f"per world +-{key}: " + "; ".join(f"{n.rsplit(' ', 1)[1]} " + " ".join(f"{k[0]}{v[k]:.2f}" for k in ["density"] + kinds)
                                          for n, v in out["per_world"][key].items()))
    if args.json:
        Path(args.json).write_text(json.dumps(out, indent=1) + "\n")
        print(f"wrote {args.json}")


if __name__ == "__main__":
    main()
