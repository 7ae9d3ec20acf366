"""g72v: digests of ``strew.grow`` outputs over seeds 1-3, several exemplars and the
three modes (fixed, rotate, flow), to check that a speed change leaves every byte alone.

Each row: element count and ``grow_hashes.digest`` (SHA-256 of positions and WKB).
Cases: stones, tiles, hex (fixed, 800 elements), stones and hex (rotate, 500), hex and
the suite's scales (flow along a field turning 90 degrees, region 16 x 11 spacings),
the suite's two_sizes and bricks (fixed, region 2.5x the exemplar's), relaxation on,
seeds 1, 2, 3.

Run: ``PYTHONPATH=src:benchmarks python benchmarks/g72v_seed_hashes.py out.json`` on two
trees and compare the JSON files.
"""

from __future__ import annotations

import json
import sys
import time

import numpy as np


def main() -> None:
    from grow import _suite_exemplar
    from grow_hashes import digest

    from strew import Region
    from strew.grow import analyze, grow
    from strew.grow._exemplars import hex_exemplar, stone_exemplar, tile_exemplar

    t0 = time.process_time()
    hexr, stones, tiles = analyze(hex_exemplar()), analyze(stone_exemplar()), analyze(tile_exemplar())
    sp = hexr.mean_edge

    def field_of(w):
        def field(p):
            a = np.radians(90.0) * np.clip(np.asarray(p)[:, 0] / w, 0, 1)
            return np.c_[np.cos(a), np.sin(a)]
        return field

    cases = [
        ("fixed stones 800", stones, dict(count=800)),
        ("fixed tiles 800", tiles, dict(count=800)),
        ("fixed hex 800", hexr, dict(count=800)),
        ("rotate stones 500", stones, dict(count=500, mode="rotate")),
        ("rotate hex 500", hexr, dict(count=500, mode="rotate")),
        ("flow hex 16", hexr, dict(region=Region.rectangle(16 * sp, 11 * sp), mode="flow", flow=field_of(16 * sp))),
    ]
    sc = _suite_exemplar("scales")
    if sc is not None:
        scr = analyze(sc)
        ssp = scr.mean_edge
        cases.append(("flow scales 16", scr, dict(region=Region.rectangle(16 * ssp, 11 * ssp), mode="flow", flow=field_of(16 * ssp))))
    for name in ("two_sizes", "bricks"):
        ex = _suite_exemplar(name)
        if ex is not None:
            x0, y0, x1, y1 = ex.region.bounds
            cases.append((f"fixed {name}", ex, dict(region=Region.rectangle(2.5 * (x1 - x0), 2.5 * (y1 - y0)))))
    rows = {}
    for label, ref, kw in cases:
        for seed in (1, 2, 3):
            out = grow(ref, rng=seed, relax=True, **kw)
            rows[f"{label} seed {seed}"] = [len(out), digest(out)]
            print(label, seed, *rows[f"{label} seed {seed}"], flush=True)
    print("cpu s", round(time.process_time() - t0, 1), file=sys.stderr)
    with open(sys.argv[1], "w") as f:
        json.dump(rows, f, indent=1)


if __name__ == "__main__":
    main()
