"""Helper seam13m (issue 13 point 2): the local fidelity map of a PERFECT continuation at
50x the exemplar's area. Can any method reach "no failing window at 50x" under the
current metric?

The oracle is the exemplar's own generator (``examples/fidelity/make.py``) drawn at about
``--k`` times the exemplar's area, with the exemplar's own stone outlines (seed 0; the
generator's ``_stone`` replays them, so only the throw differs) and positions from
``--seeds`` (independent draws). Two framings, both with every element wholly inside
the output rectangle (as ``SynthState.to_arrangement(clip=True)`` leaves synth's output):

``framed``
    The generator thrown in the output rectangle itself (centres keep a radius off its
    walls, as the exemplar's frame does; counts by the inner box's area, as
    ``fidelity_calibration.larger``). The exemplar is drawn this way.
``cropped``
    The generator thrown in a rectangle ``--pad`` largest diameters wider on every side,
    then cut to the output rectangle, keeping the elements wholly inside (synth's clip):
    an endless texture clipped, with the gaps clipping leaves along the edge.

Each draw is judged as ``seam13f_diag.py`` judges synth: ``fidelity(ex, draw, region,
eq5=False)`` with ``region`` the output rectangle (7.07 x the exemplar's side). Printed
per draw: elements, failing windows, worst window, each failing window's metric and
score, and whether it lies on the map's edge (first/last row or column).

    python benchmarks/seam13m_oracle50.py [--names three_sizes,two_sizes,stones]
        [--seeds 1-16] [--modes framed,cropped] [--k 50] [--pad 2]
        [--json benchmarks/results/seam13m_oracle50.json]

Figures (02:3x-02:5x UTC, ``benchmarks/results/seam13m_oracle50_*.json``). three_sizes,
framed, seeds 1-8: 1 failing window in 8 x 169 (seed 1, nn[medium>medium] 1.054, inside
the canvas), worst window per draw 0.76-1.05 (mean 0.87); every draw faithful globally.
Synth on 61d61c7 (``seam13f_diag.py --seeds 1,...,16``): 10 failing windows in 16 x 169,
worst per seed 0.79-1.18 (mean 0.98). A perfect continuation is not at zero either: the
local map's tolerance leaves about 1 failing window per 8 draws of the generator itself.
Controls, framed, seeds 1-2: stones 0 failing (worst 0.66, 0.56); two_sizes 6 and 2
failing (worst 1.16, 1.13: nn[stone>pebble], fraction[stone], one empty_circle), though
synth passes two_sizes at 50x: drawn larger, the generator is not the exemplar's process
where its count stops a throw in the exemplar but its darts run out first at 50x
(three_sizes at 50x: 12,900 elements against 14,206 asked), so an oracle that fails says
as much about the draw's scaling as about the metric. The cropped framing was not run
against the suite's exemplar (stopped for time).
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
from pathlib import Path
from typing import Any

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _runner import SKIPPED, fidelity_suite  # noqa: E402

from strew import Region  # noqa: E402
from strew.metrics import fidelity  # noqa: E402

mk = fidelity_suite()


def _fast_dart(rng: np.random.Generator, box: tuple[float, float, float, float], radii: Any, count: int, *, gap: float = 0.0,
               placed: tuple[np.ndarray, np.ndarray] | None = None, tries: int = 20000, periodic: bool = False) -> tuple[np.ndarray, np.ndarray]:
    """``make._dart``'s process (the same darts per area, sequential acceptance, the k-th
    accepted dart takes ``radii[k]``) with the clearance to earlier darts from a k-d tree
    instead of all pairs: ``make._dart`` at 50x the exemplar's area takes tens of minutes."""
    from scipy.spatial import cKDTree

    assert not periodic
    x0, y0, x1, y1 = box
    tries = int(tries * (x1 - x0) * (y1 - y0) / 170.0**2)
    radii_arr = np.broadcast_to(np.asarray(radii, float), (count,)) if np.ndim(radii) == 0 else np.asarray(radii, float)
    P = np.zeros((0, 2)) if placed is None else np.asarray(placed[0], float).reshape(-1, 2)
    R = np.zeros(0) if placed is None else np.asarray(placed[1], float)
    n0 = len(P)
    m = float(radii_arr[:count].max()) if count else 0.0
    k, done = 0, 0
    batch = 512  # as make._dart: the same random stream, so the same draws bit for bit
    while done < tries and k < count:
        b = min(batch, tries - done)
        cand = rng.uniform((x0 + m, y0 + m), (x1 - m, y1 - m), (b, 2))
        done += b
        rmax = float(radii_arr[k:count].max())
        reach = rmax + gap + (float(R.max()) if len(R) else 0.0)
        clear = np.full(b, np.inf)
        if len(P):
            tree = cKDTree(P)
            kk = min(48, len(P))
            d, j = tree.query(cand, k=kk, distance_upper_bound=reach)
            d, j = d.reshape(b, kk), j.reshape(b, kk)
            ok = np.isfinite(d)
            c = np.where(ok, d - R[np.minimum(j, len(R) - 1)], np.inf).min(axis=1)
            full = ok[:, -1]  # as many neighbours as asked within reach: measure exactly
            for i in np.flatnonzero(full):
                jj = tree.query_ball_point(cand[i], reach)
                c[i] = (np.hypot(*(P[jj] - cand[i]).T) - R[jj]).min()
            clear = c
        new: list[int] = []
        newr: list[float] = []
        rmin = float(radii_arr[k:count].min()) if k < count else 0.0
        for i in np.flatnonzero(clear >= rmin + gap):
            if k >= count:
                break
            r = float(radii_arr[k])
            if clear[i] < r + gap:
                continue
            if new:
                dd = cand[new] - cand[i]
                if np.any(np.hypot(dd[:, 0], dd[:, 1]) < np.asarray(newr) + r + gap):
                    continue
            new.append(i)
            newr.append(r)
            k += 1
        if new:
            P = np.r_[P, cand[new]]
            R = np.r_[R, newr]
    return P[n0:], R[n0:]


mk._dart = _fast_dart
SIDE = {"stones": 200.0, "two_sizes": 220.0, "three_sizes": 210.0}


def _outlines(name: str) -> list[np.ndarray]:
    """The stone outlines the seed-0 exemplar draws, in order."""
    got: list[np.ndarray] = []
    orig = mk._stone

    def rec(*a: Any, **kw: Any) -> np.ndarray:
        v = orig(*a, **kw)
        got.append(v)
        return v

    mk._stone = rec
    try:
        mk.make_exemplar(name)
    finally:
        mk._stone = orig
    return got


def _draw(name: str, seed: int, size: float, outlines: list[np.ndarray]) -> Any:
    """The class drawn in a ``size`` square with the exemplar's outlines and counts for
    the same saturation as the exemplar (the inner box rule of ``fidelity_calibration``)."""
    ex = mk.make_exemplar(name)
    rad = {n: sh.radius for n, sh in ex.shapes.items()}
    side = SIDE[name]

    def fair(count: int, m: float) -> int:
        return int(round(count * ((size - 2 * m) / (side - 2 * m)) ** 2))

    var = {
        "stones": lambda: dict(size=size, count=fair(160, 1.2 * rad["stone"])),
        "two_sizes": lambda: dict(size=size, n_large=fair(80, 1.1 * rad["stone"]), n_small=fair(220, 1.15 * rad["pebble"])),
        "three_sizes": lambda: dict(size=size, counts=tuple(fair(c, 1.1 * rad[n]) for c, n in zip((170, 65, 26), ("small", "medium", "large")))),
    }[name]()
    it = iter(outlines)
    orig = mk._stone
    mk._stone = lambda *a, **kw: (orig(*a, **kw), next(it))[1]  # the rng stream as drawn, the exemplar's outline
    try:
        return mk.make_exemplar(name, rng=seed, **var)
    finally:
        mk._stone = orig


def oracle(name: str, seed: int, k: float, mode: str, pad: float, outlines: list[np.ndarray]) -> tuple[Any, Region, int]:
    """(draw, output region, elements clipped by the cut)."""
    size = SIDE[name] * math.sqrt(k)
    region = Region.rectangle(size, size)
    if mode == "framed":
        arr = _draw(name, seed, size, outlines)
        return arr, region, 0
    ex = mk.make_exemplar(name)
    big = max(sh.radius for sh in ex.shapes.values()) * 2.0 * pad
    arr = _draw(name, seed, size + 2 * big, outlines)
    arr = arr.replace(x=arr.x - big, y=arr.y - big)
    centre_in = (arr.x >= 0) & (arr.x < size) & (arr.y >= 0) & (arr.y < size)
    arr = arr.select(centre_in)
    inside = region.contains_geometry(arr.geometry, tolerance=1e-9)
    return arr.select(inside).replace(region=region), region, int((~inside).sum())


def windows(ex: Any, out: Any, region: Region) -> tuple[Any, list[dict[str, Any]]]:
    rep = fidelity(ex, out, region, eq5=False)
    L = rep.local
    S = np.asarray(L["score"], float)
    W = np.asarray(L["worst_metric"], dtype=object)
    rows = []
    nr, nc = S.shape
    for (i, j), s in np.ndenumerate(S):
        if not np.isfinite(s):
            continue
        rows.append(dict(i=int(i), j=int(j), score=float(s), metric=str(W[i, j]), edge=bool(i in (0, nr - 1) or j in (0, nc - 1))))
    return rep, rows


def main() -> None:
    if "--quick" in sys.argv[1:]:
        print("seam13m_oracle50: skipped: 50x draws (minutes)")
        sys.exit(SKIPPED)
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--names", default="three_sizes,two_sizes,stones")
    ap.add_argument("--seeds", default="1-16", help="a range a-b or a list")
    ap.add_argument("--modes", default="framed,cropped")
    ap.add_argument("--k", type=float, default=50.0)
    ap.add_argument("--pad", type=float, default=2.0, help="cropped: the throw's margin, in largest diameters")
    ap.add_argument("--json", default="benchmarks/results/seam13m_oracle50.json")
    a = ap.parse_args()
    seeds = list(range(int(a.seeds.split("-")[0]), int(a.seeds.split("-")[1]) + 1)) if "-" in a.seeds else [int(s) for s in a.seeds.split(",")]
    out: dict[str, Any] = {"benchmark": "seam13m_oracle50", "k": a.k, "pad": a.pad, "rows": []}
    for name in a.names.split(","):
        ex = mk.make_exemplar(name)
        outlines = _outlines(name)
        for mode in a.modes.split(","):
            tot = 0
            for seed in seeds:
                t0 = time.process_time()
                arr, region, clipped = oracle(name, seed, a.k, mode, a.pad, outlines)
                rep, rows = windows(ex, arr, region)
                fail = [r for r in rows if r["score"] > 1]
                tot += len(fail)
                worst = max(r["score"] for r in rows)
                row = dict(name=name, mode=mode, seed=seed, n=len(arr), clipped=clipped, windows=len(rows), failing=len(fail), worst=worst,
                           faithful=bool(rep.faithful), global_failures=list(rep.failures), fails=fail, cpu_s=round(time.process_time() - t0, 1))
                out["rows"].append(row)
                desc = " ".join(f"{r['metric']}={r['score']:.2f}{'@edge' if r['edge'] else ''}" for r in fail)
                print(f"{name:12s} {mode:8s} s{seed:<3d} n={len(arr):6d} clipped={clipped:4d} failing {len(fail):2d}/{len(rows)} worst {worst:.3f} "
                      f"global {'pass' if rep.faithful else 'FAIL ' + ','.join(rep.failures)}  {desc}", flush=True)
                out.setdefault("totals", {})[f"{name}/{mode}"] = tot
                with open(a.json, "w") as f:  # after every draw: a stopped run keeps its figures
                    json.dump(out, f, indent=1)
            print(f"{name:12s} {mode:8s} total failing windows over {len(seeds)} draws: {tot} (mean {tot / len(seeds):.2f}/draw)", flush=True)
    print(f"figures written to {a.json}")


if __name__ == "__main__":
    main()
