"""Ornament outputs byte for byte: untiled panels and small tiled worlds, per pattern (issue 19.4).

``PYTHONPATH=TREE/src python benchmarks/spi19p_identity.py --json F [--untiled willow,flowers,spirals]
[--tiled willow,flowers,dots,hierarchy,vase] [--side 240 --tile 60]`` hashes (sha256, 16 hex) every
element's x, y, rotation, kind and the public columns (element, parent, type, phase) and
its parts' points: ``grow_ornament(NAME, 120 x 120, rng=1)`` untiled, and
``strew.tiles.tiled("ornament", NAME, (side, side), tile_size=tile, seed=1)``. Run it on
two trees and compare the JSON files.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import time

import numpy as np


def digest(arr) -> str:
    h = hashlib.sha256()
    for a in (arr.x, arr.y, arr.rotation):
        h.update(np.ascontiguousarray(np.asarray(a, float)).tobytes())
    h.update("|".join(arr.kinds[int(k)] for k in np.asarray(arr.kind)).encode())
    for c in ("element", "parent", "type", "phase"):
        if c in arr.columns:
            h.update(repr(np.asarray(arr[c]).tolist()).encode())
    if "parts" in arr.columns:
        for parts in arr["parts"]:
            for s in parts:
                for p in (s["paths"] if isinstance(s, dict) else s.paths):
                    pts = p["points"] if isinstance(p, dict) else p.points
                    h.update(np.ascontiguousarray(np.asarray(pts, float)).tobytes())
    h.update(repr(sorted(arr.columns)).encode())
    return h.hexdigest()[:16]


def main() -> None:
    import strew
    from strew.ornament import grow_ornament
    from strew.tiles import tiled

    ap = argparse.ArgumentParser()
    ap.add_argument("--json", required=True)
    ap.add_argument("--untiled", default="willow,flowers,spirals")
    ap.add_argument("--tiled", default="willow,flowers,dots,hierarchy,vase")
    ap.add_argument("--side", type=float, default=240.0)
    ap.add_argument("--tile", type=float, default=60.0)
    ap.add_argument("--strips", action="store_true", help="also worlds_strips.py's +-2 s / +-1 s strips of each tiled world (one small world: a screen)")
    a = ap.parse_args()
    out: dict = {"tree": strew.__file__, "untiled": {}, "tiled": {}}
    for name in [p for p in a.untiled.split(",") if p]:
        t0 = time.process_time()
        arr = grow_ornament(name, strew.Region.rectangle(120, 120), rng=1)
        out["untiled"][name] = [len(arr), digest(arr)]
        print(f"untiled {name}: {len(arr)} el {out['untiled'][name][1]} ({time.process_time() - t0:.1f} CPU s)", flush=True)
    for name in [p for p in a.tiled.split(",") if p]:
        t0 = time.process_time()
        arr = tiled("ornament", name, (a.side, a.side), tile_size=a.tile, seed=1)
        out["tiled"][name] = [len(arr), digest(arr)]
        if a.strips:
            import sys
            from pathlib import Path

            sys.path.insert(0, str(Path(__file__).resolve().parent))
            import worlds_strips as W

            size = (a.side, a.side)
            halo = float(arr.meta["world"]["halo"]) if "world" in arr.meta else a.tile / 4
            w = W.measure_world(arr, size, a.tile, halo, 1.0 / np.sqrt(len(arr) / (a.side * a.side)))
            sm = W.summarize([w], 1000, np.random.default_rng(0), list(arr.kinds))
            row = {}
            for key in ("units_2s", "units_1s"):
                u = sm[key]
                row[key] = {"density": [u["density_ratio"]["value"], *u["density_ratio"]["ci"]],
                            **{k: [v["value"], *v["ci"]] for k, v in u["kind_fraction_ratio"].items()}}
                print(f"  {name} {key}: " + "; ".join(f"{k} {v[0]:.3f} [{v[1]:.3f}, {v[2]:.3f}]" for k, v in row[key].items()), flush=True)
            row["overlaps"] = int(w["overlaps"])
            out.setdefault("strips", {})[name] = row
        print(f"tiled {name} {a.side:g}/{a.tile:g}: {len(arr)} el {out['tiled'][name][1]} ({time.process_time() - t0:.1f} CPU s)", flush=True)
    with open(a.json, "w") as f:
        json.dump(out, f, indent=1)


if __name__ == "__main__":
    main()
