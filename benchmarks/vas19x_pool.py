"""The tiled vase's kind shares in the border strips against its untiled control, pooled
over many worlds (issue 19.4, vas19x): one world's +-1 s strip holds 3-24 vines.

``python benchmarks/vas19x_pool.py TILED:CONTROL[:T] ... [--boot 4000] [--json F]``

Each pair names the tags of ``benchmarks/orn19m_willow.py make --pattern vase --tag TILED``
(and ``--tag CONTROL --untiled``, the same seed); with ``:T`` only tile size T, else every
tile size both hold. Per world and strip (+-1 s, +-2 s; vas19s_compare.py's lines: the world's
edge band left out) it counts the elements and each kind in the strip and in the interior.
Pooled over the worlds: density = (strip elements / strip area) / (interior elements /
interior area), a kind's share = (strip kind / strip elements) / (interior kind / interior
elements), tiled / control; 95 % interval by a paired bootstrap over the worlds (each draw
takes a world's tiled and control together).
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


def _counts(w: dict, width: float) -> np.ndarray:
    """[strip area, interior area, strip n, interior n, strip n per kind..., interior per kind...]."""
    ins = w["inside"]
    near = w["d"] < width
    gnear = w["gd"] < width
    s, i = ins & near, ins & ~near
    nk = len(w["kinds"])
    ks = np.bincount(w["kind"][s], minlength=nk)
    ki = np.bincount(w["kind"][i], minlength=nk)
    return np.concatenate([[gnear.sum() * w["garea"], (~gnear).sum() * w["garea"], s.sum(), i.sum()], ks, ki]).astype(float)


def _ratios(c: np.ndarray, nk: int) -> np.ndarray:
    """density, then each kind's share, of summed counts c."""
    sa, ia, sn, i_n = c[:4]
    ks, ki = c[4:4 + nk], c[4 + nk:]
    dens = (sn / sa) / (i_n / ia)
    with np.errstate(divide="ignore", invalid="ignore"):
        share = (ks / sn) / (ki / i_n)
    return np.concatenate([[dens], share])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("pairs", nargs="+")
    ap.add_argument("--boot", type=int, default=4000)
    ap.add_argument("--json", default=None)
    args = ap.parse_args()
    from orn19m_willow import _world

    worlds = []
    for pr in args.pairs:
        parts = pr.split(":")
        tt, ct = parts[0], parts[1]
        for p in sorted(RES.glob(f"orn19m_{tt}_T*.npz")):
            T = p.name.rsplit("_T", 1)[1][:-4]
            if len(parts) > 2 and T != parts[2]:
                continue
            q = RES / f"orn19m_{ct}_T{T}.npz"
            if q.exists():
                worlds.append((f"{tt}/{ct} T{T}", p, q))
    kinds = None
    rec = {}
    for name, p, q in worlds:
        wt, wc = _world(p), _world(q)
        kinds = kinds or wt["kinds"]
        assert wt["kinds"] == kinds and wc["kinds"] == kinds, (name, wt["kinds"], wc["kinds"])
        rec[name] = {f"{wd:g}s": (_counts(wt, wd), _counts(wc, wd)) for wd in (1.0, 2.0)}
        ov = (int(np.load(p)["overlaps"]), int(np.load(q)["overlaps"]))
        rec[name]["overlaps"] = ov
        # the vines by line: the world's central cross (x or y = 2 T: the untiled control's
        # seed, at the world's centre, grows its first vines along these axes) and the other
        # inner borders (T, 3 T)
        lines = {}
        for nm, w in (("tiled", wt), ("control", wc)):
            z = np.load(p if nm == "tiled" else q)
            x, y, tile, s = z["x"], z["y"], w["tile"], w["s"]
            v = (w["kind"] == w["kinds"].index("vine")) & w["inside"]
            dc = np.minimum(abs(x - 2 * tile), abs(y - 2 * tile)) / s
            do = np.minimum(np.minimum(abs(x - tile), abs(x - 3 * tile)), np.minimum(abs(y - tile), abs(y - 3 * tile))) / s
            lines[nm] = {f"{wd:g}s": [int((v & (dc < wd)).sum()), int((v & (do < wd) & (dc >= wd)).sum())] for wd in (1.0, 2.0)}
        rec[name]["lines"] = lines
        # every vine by its distance to the nearest inner border, 1 s bins (0-1, ..., 7-8 s)
        rec[name]["vine_d"] = {nm: np.histogram(w["d"][(w["kind"] == w["kinds"].index("vine")) & w["inside"]], np.arange(0, 9.0))[0].tolist()
                               for nm, w in (("tiled", wt), ("control", wc))}
    names = list(rec)
    nk = len(kinds)
    labels = ["density"] + list(kinds)
    rng = np.random.default_rng(0)
    out = {"worlds": names, "kinds": kinds, "per_world": {}, "pooled": {}}
    print(f"{len(names)} worlds; overlaps {[rec[n]['overlaps'] for n in names]}")
    for wd in ("1s", "2s"):
        T = np.array([rec[n][wd][0] for n in names])
        C = np.array([rec[n][wd][1] for n in names])
        per = {n: (_ratios(T[i], nk) / _ratios(C[i], nk)).tolist() for i, n in enumerate(names)}
        vk = kinds.index("vine")
        print(f"+-{wd}: per world vine share tiled / control (vines in strip tiled / control): "
              + ", ".join(f"{n.split('/')[0]}:{per[n][1 + vk]:.2f} ({int(T[i][4 + vk])}/{int(C[i][4 + vk])})" for i, n in enumerate(names)))
        est = _ratios(T.sum(0), nk) / _ratios(C.sum(0), nk)
        bs = []
        for _ in range(args.boot):
            k = rng.integers(0, len(names), len(names))
            bs.append(_ratios(T[k].sum(0), nk) / _ratios(C[k].sum(0), nk))
        lo, hi = np.nanpercentile(np.array(bs), [2.5, 97.5], axis=0)
        pooled = {lab: {"ratio": float(est[j]), "ci95": [float(lo[j]), float(hi[j])]} for j, lab in enumerate(labels)}
        pooled["vines_in_strip"] = [int(T[:, 4 + vk].sum()), int(C[:, 4 + vk].sum())]
        lc = {nm: np.array([rec[n]["lines"][nm][wd] for n in names]).sum(0).tolist() for nm in ("tiled", "control")}
        pooled["vines_central_other"] = lc
        out["pooled"][wd] = pooled
        out["per_world"][wd] = per
        print(f"+-{wd} pooled tiled / control: " + "; ".join(f"{lab} {pooled[lab]['ratio']:.3f} [{pooled[lab]['ci95'][0]:.3f}, {pooled[lab]['ci95'][1]:.3f}]"
                                                       for lab in labels) + f"; vines in strip tiled / control {pooled['vines_in_strip']}; on the central cross / the other borders "
              f"tiled {lc['tiled']} control {lc['control']}")
    vd = {nm: np.array([rec[n]["vine_d"][nm] for n in names]).sum(0).tolist() for nm in ("tiled", "control")}
    out["vines_by_distance_1s_bins"] = vd
    print(f"vines by distance to the nearest inner border (0-1, 1-2, ..., 7-8 s): tiled {vd['tiled']} control {vd['control']}")
    if args.json:
        Path(args.json).write_text(json.dumps(out, indent=1) + "\n")
        print(f"wrote {args.json}")


if __name__ == "__main__":
    main()
