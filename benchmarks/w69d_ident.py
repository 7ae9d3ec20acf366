"""w69d: small worlds as bytes, with strew.tiles._VINES_FIRST on or off (issue 19.4 point 4; after w68d_ident.py).

``PYTHONPATH=TREE/src python benchmarks/w69d_ident.py OUT.npz [--workers N] [--hier-only] [--vines-first 0/1]`` writes every column of
a few small worlds: tiled willow and vase (no first phase kept: strew.tiles._keeps_first_phase), untiled hierarchy
and willow (no tile), and a tiled hierarchy world (the rule acts). Compare two trees' files with --compare A B.
"""

from __future__ import annotations

import argparse
import sys

import numpy as np


def _cols(arr) -> dict:
    out = {"x": np.asarray(arr.x, float), "y": np.asarray(arr.y, float), "kind": np.asarray(arr.kind)}
    for c in arr.columns:
        v = np.asarray(arr[c], dtype=object)
        out[c] = np.array([repr(e) for e in v])
    return out


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("out", nargs="?")
    ap.add_argument("--workers", type=int, default=1)
    ap.add_argument("--hier-only", action="store_true")
    ap.add_argument("--vines-first", type=int, default=None, help="set strew.tiles._VINES_FIRST (absent in trees without it)")
    ap.add_argument("--compare", nargs=2)
    args = ap.parse_args()
    if args.compare:
        a, b = (np.load(p) for p in args.compare)
        worlds = sorted({k.split("/")[0] for k in a.files} | {k.split("/")[0] for k in b.files})
        for w in worlds:
            ka = sorted(k for k in a.files if k.startswith(w + "/"))
            kb = sorted(k for k in b.files if k.startswith(w + "/"))
            same = ka == kb and all(np.array_equal(a[k], b[k]) for k in ka)
            print(f"{w}: {'identical' if same else 'DIFFERENT'} ({len(a[ka[0]]) if ka else 0} vs {len(b[kb[0]]) if kb else 0} rows)")
        return
    import strew
    import strew.tiles as T
    from strew.ornament import grow_ornament

    if args.vines_first is not None:
        T._VINES_FIRST = args.vines_first
    worlds = {}
    kw = {"workers": args.workers} if args.workers > 1 else {}
    if not args.hier_only:
        worlds["willow_tiled"] = T.tiled("ornament", "willow", (120, 120), tile_size=60, seed=3, **kw)
        worlds["vase_tiled"] = T.tiled("ornament", "vase", (144, 144), tile_size=48, seed=3, **kw)
        worlds["hier_untiled"] = grow_ornament("hierarchy", strew.Region.rectangle(96, 96), rng=3)
        worlds["willow_untiled"] = grow_ornament("willow", strew.Region.rectangle(96, 96), rng=3)
    worlds["hier_tiled"] = T.tiled("ornament", "hierarchy", (96, 96), tile_size=24, seed=3, **kw)
    np.savez_compressed(args.out, **{f"{w}/{c}": v for w, arr in worlds.items() for c, v in _cols(arr).items()})
    print({w: len(a) for w, a in worlds.items()}, file=sys.stderr)


if __name__ == "__main__":
    main()
