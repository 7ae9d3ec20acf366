"""Screen a tiles change on the tiled ornament worlds (issue 19.4, scr19w): which rows differ
between two trees' worlds and the border strips before and after.

``python benchmarks/scr19w_screen.py --pairs OLDTAG:NEWTAG[,...] [--json F]`` reads the
worlds ``benchmarks/results/orn19m_<tag>_T<T>.npz`` written by ``benchmarks/orn19m_willow.py
make --tag TAG --tiles T --overlaps`` on each tree (the same pattern, tiles and seed), and
prints per world:

- elements before / after, and the rows only one world holds (matched on x, y, kind to
  1e-9): their kinds, their distance to the nearest inner border in mean spacings s
  (negative on the earlier, finished tile's side, as orn19m_willow.py's profile) and the
  tile (unit, row-major 0..15) holding their centre; listed one by one when 12 or fewer
  (in the JSON: when 50 or fewer, else their count);
- overlaps (as recorded by make);
- orn19m_willow.py analyze's +-1 s / +-2 s density and kind shares against the interior,
  and the folded chi2/dof, for each tag; rows outside [0.97, 1.03] are flagged.

``PYTHONPATH=TREE/src python benchmarks/scr19w_screen.py direct [--patterns ...] [--tile 60]
[--seed 1] [--json F]`` lists the rows strew.ornament._context.keep_ancestors itself sets in
each tiled world (kind, tile, signed distance to the nearest border).
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


def _rows(z) -> dict:
    kinds = [str(k) for k in z["kinds"]]
    out: dict = {}
    for x, y, k in zip(z["x"], z["y"], z["kind"]):
        key = (round(float(x), 9), round(float(y), 9), kinds[int(k)])
        out[key] = out.get(key, 0) + 1
    return out


def _diff(old: Path, new: Path) -> dict:
    import orn19m_willow as W

    zo, zn = np.load(old), np.load(new)
    ro, rn = _rows(zo), _rows(zn)
    only_old = [k for k, c in ro.items() for _ in range(max(c - rn.get(k, 0), 0))]
    only_new = [k for k, c in rn.items() for _ in range(max(c - ro.get(k, 0), 0))]
    side, tile = float(zn["meta"][0]), float(zn["meta"][1])
    s = 1.0 / np.sqrt(len(zn["x"]) / side**2)

    def where(rows):
        if not rows:
            return []
        x = np.array([r[0] for r in rows])
        y = np.array([r[1] for r in rows])
        _, sd = W._sd(x, y, side, tile)
        u = (np.clip(np.floor(y / tile), 0, 3) * 4 + np.clip(np.floor(x / tile), 0, 3)).astype(int)
        return [dict(x=r[0], y=r[1], kind=r[2], sd_s=round(float(v) / s, 3), unit=int(k)) for r, v, k in zip(rows, sd, u)]

    def summary(rows):
        sd = np.array([abs(r["sd_s"]) for r in rows])
        kinds = sorted({r["kind"] for r in rows})
        return dict(n=len(rows), by_kind={k: sum(r["kind"] == k for r in rows) for k in kinds},
                    by_distance={lab: int(((sd >= lo) & (sd < hi)).sum()) for lab, lo, hi in
                                 (("<1s", 0, 1), ("1-2s", 1, 2), ("2-3s", 2, 3), (">=3s", 3, np.inf))},
                    by_unit={int(u): sum(r["unit"] == u for r in rows) for u in sorted({r["unit"] for r in rows})})

    return dict(tile=tile, side=side, elements_old=int(len(zo["x"])), elements_new=int(len(zn["x"])),
                overlaps_old=int(zo["overlaps"]), overlaps_new=int(zn["overlaps"]), identical=not only_old and not only_new,
                only_old=where(only_old), only_new=where(only_new),
                summary_old=summary(where(only_old)), summary_new=summary(where(only_new)))


def direct(patterns: list[str], tile: float, seed: int) -> dict:
    """The rows keep_ancestors itself sets (``placed`` False -> True) in the tiled world
    ``tiled("ornament", P, (4 tile, 4 tile), tile_size=tile, seed=seed)``: kind, signed
    distance to the nearest inner border (in the world's mean spacing) and whether the
    tile kept them (keep_whole's output)."""
    import strew.ornament._context as C
    import strew.tiles as T
    import orn19m_willow as W

    side = 4 * tile
    out: dict = {}
    for name in patterns:
        rec: list = []
        stash: dict = {}
        orig_k, orig_a = T._keep_groups, C.keep_ancestors

        def keep_groups(arr, keep, t, job, links):
            stash["arr"] = arr
            stash["rows"] = None
            k = orig_k(arr, keep, t, job, links)
            if stash["rows"] is not None:
                a, r = arr, stash["rows"]
                for i in np.flatnonzero(r):
                    rec.append(dict(tile=int(t.index), x=float(a.x[i]), y=float(a.y[i]), kind=a.kinds[int(a.kind[i])], kept=bool(k[i])))
            return k

        def keep_ancestors(element, parent, group, placed, far):
            o = orig_a(element, parent, group, placed, far)
            stash["rows"] = o & ~np.asarray(placed, bool)
            return o

        T._keep_groups, C.keep_ancestors = keep_groups, keep_ancestors
        try:
            arr = T.tiled("ornament", name, (side, side), tile_size=tile, seed=seed)
        finally:
            T._keep_groups, C.keep_ancestors = orig_k, orig_a
        s = 1.0 / np.sqrt(len(arr) / side**2)
        if rec:
            _, sd = W._sd(np.array([r["x"] for r in rec]), np.array([r["y"] for r in rec]), side, tile)
            for r, v in zip(rec, sd):
                r["sd_s"] = round(float(v) / s, 3)
        out[name] = dict(tile=tile, seed=seed, elements=len(arr), rows=rec)
        print(f"{name} T{tile:g} seed {seed}: {len(arr)} el, keep_ancestors set {len(rec)} rows: "
              + "; ".join(f"{r['kind']} tile {r['tile']} sd {r['sd_s']:+.2f} s{'' if r['kept'] else ' (dropped)'}" for r in rec), flush=True)
    return out


def main() -> None:
    import orn19m_willow as W

    if sys.argv[1:2] == ["direct"]:
        ap = argparse.ArgumentParser()
        ap.add_argument("cmd")
        ap.add_argument("--patterns", default="willow,flowers,dots,spirals")
        ap.add_argument("--tile", type=float, default=60.0)
        ap.add_argument("--seed", type=int, default=1)
        ap.add_argument("--json", default=None)
        a = ap.parse_args()
        res = direct(a.patterns.split(","), a.tile, a.seed)
        if a.json:
            Path(a.json).write_text(json.dumps(res, indent=1) + "\n")
        return

    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--pairs", required=True)
    ap.add_argument("--boot", type=int, default=1000)
    ap.add_argument("--json", default=None)
    a = ap.parse_args()
    out: dict = {}
    for pair in a.pairs.split(","):
        old, new = pair.split(":")
        rec: dict = {"worlds": []}
        for pn in sorted(RES.glob(f"orn19m_{new}_T*.npz")):
            po = RES / pn.name.replace(f"orn19m_{new}_", f"orn19m_{old}_")
            if not po.exists():
                continue
            d = _diff(po, pn)
            rec["worlds"].append({k: (v if not k.startswith("only_") or len(v) <= 50 else len(v)) for k, v in d.items()})
            print(f"{old} -> {new} T{d['tile']:g}: elements {d['elements_old']} -> {d['elements_new']}, "
                  f"rows only before {len(d['only_old'])}, only after {len(d['only_new'])}, "
                  f"overlaps {d['overlaps_old']} -> {d['overlaps_new']}")
            for lab in ("old", "new"):
                print(f"    only {lab}: {d['summary_' + lab]}")
            for lab in ("only_old", "only_new"):
                for r in (d[lab] if len(d[lab]) <= 12 else []):
                    print(f"    {lab:8s} {r['kind']:10s} ({r['x']:.2f}, {r['y']:.2f}) signed distance {r['sd_s']:+.2f} s")
        res = W.analyze(argparse.Namespace(tags=[old, new], boot=a.boot, out=None))
        for tag in (old, new):
            if tag not in res:
                continue
            r = res[tag]
            rec[tag] = {k: r[k] for k in ("strips_1s", "strips_2s")}
            rec[tag]["folded_chi2_dof"] = r["folded"]["chi2_dof"]
            rec[tag]["elements"] = r["elements"]
        flags = []
        for tag in (old, new):
            for w in ("strips_1s", "strips_2s"):
                for k, v in rec.get(tag, {}).get(w, {}).items():
                    if k.endswith("_density") and k != "density":
                        continue
                    if not 0.97 <= v[0] <= 1.03:
                        flags.append(f"{tag} {w} {k} {v[0]:.3f}")
        rec["outside_3pct"] = flags
        print(f"  outside 3 %: {flags}")
        out[pair] = rec
    if a.json:
        Path(a.json).write_text(json.dumps(out, indent=1) + "\n")
        print(f"wrote {a.json}")


if __name__ == "__main__":
    main()
