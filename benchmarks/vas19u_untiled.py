"""The untiled vase, hashed and counted (issue 19.4, vas19u): ``grow_ornament("vase", side x side,
rng=SEED)`` for each side and seed, its digest (benchmarks/spi19p_identity.digest), its element
counts by kind, and the successes whose hook goal the parent's distance bounded (vase.hook's
``min(rho, far)``: a hook where rho > far). Run on two trees and compare.

``PYTHONPATH=TREE/src python benchmarks/vas19u_untiled.py --sides 120,200 --seeds 1 [--json F]``
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--sides", default="120,200")
    ap.add_argument("--seeds", default="1")
    ap.add_argument("--json", default=None)
    args = ap.parse_args()
    import numpy as np

    import strew
    from spi19p_identity import digest
    from strew.ornament import grow_ornament

    out = {}
    for side in [float(v) for v in args.sides.split(",")]:
        for seed in [int(v) for v in args.seeds.split(",")]:
            t0 = time.process_time()
            arr = grow_ornament("vase", strew.Region.rectangle(side, side), rng=seed)
            cpu = time.process_time() - t0
            cnt = dict(zip(arr.kinds, np.bincount(np.asarray(arr.kind), minlength=len(arr.kinds)).tolist()))
            key = f"{side:g}_s{seed}"
            out[key] = {"digest": digest(arr), "n": len(arr), "counts": cnt, "cpu_s": cpu}
            print(f"{key}: {digest(arr)} {len(arr):,} el {cnt} {cpu:.1f} CPU s", flush=True)
    if args.json:
        Path(args.json).write_text(json.dumps(out, indent=1) + "\n")


if __name__ == "__main__":
    main()
