"""Trace room fill on the studio's brush (helper s28o, issue 13 point 1).

Paints the stroke of ``tests/studio/test_studio_session.py::
test_brush_finishes_the_stroke_when_it_ends`` (tiles.svg, radius 100, 16 points) twice,
with ``BRUSH_ITERATIONS`` 1 (bounded: finished at the stroke's end) and 10000 (grown
fully at every segment), and prints per segment the state's count and what each
``_grow.fill_room`` call added (with whether the horizon was still open, i.e. growth
unfinished).

    PYTHONPATH=src python benchmarks/s28o_brush_trace.py [--set _grow.ROOM_ONE_CLASS=False] [--seeds 3,4] [--quiet] [--example stones.svg]

``--seeds``: the session seeds (the test's is 3); ``--quiet``: one line per seed.
"""

from __future__ import annotations

import sys
import tempfile

import numpy as np

import strew.studio._session as session_module
from strew.studio._session import Session
from strew.synth import _grow

EXAMPLE = "tiles.svg"  # --example NAME.svg
LINE = [(100.0 + 20 * i, 200.0) for i in range(16)]


def main() -> None:
    args = sys.argv[1:]
    while args and args[0] == "--set":
        name, val = args[1].split("=")
        _mod, attr = name.split(".")
        setattr(_grow, attr, eval(val))
        args = args[2:]
    seeds, quiet = [3], False
    while args:
        if args[0] == "--seeds":
            seeds = [int(x) for x in args[1].split(",")]
            args = args[2:]
        elif args[0] == "--example":
            global EXAMPLE
            EXAMPLE = args[1]
            args = args[2:]
        elif args[0] == "--quiet":
            quiet = True
            args = args[1:]
        else:
            raise SystemExit(f"unknown argument {args[0]}")
    log: list = []
    quiet_log = quiet
    orig = _grow.fill_room

    def traced(state, room=None, since=0):
        n = state.n
        open_ = bool(state.horizon.any())
        got = orig(state, room, since)
        if got and not quiet_log:
            # where the room-filled elements stand: distance to the nearest element whose
            # free space is still open (the growth front), in units of r-bar
            from scipy.spatial import cKDTree

            hz = np.flatnonzero(state.horizon[:n])
            d = cKDTree(state.pos[hz]).query(state.pos[n:])[0] / float(state.prep.rbar.max()) if len(hz) else np.full(got, np.inf)
            print(f"    fill_room at n={n}: {got} added, distance to the open front / r-bar {np.round(d, 2).tolist()}, open front {len(hz)} of {n}")
        log.append((n, got, open_))
        return got

    _grow.fill_room = traced
    for seed in seeds:
        counts = {}
        for iters in (1, 10_000):
            counts[iters] = paint(seed, iters, log, quiet)
        print(f"seed {seed}: bounded {counts[1][0]} full {counts[10_000][0]} ratio {counts[1][0] / counts[10_000][0]:.3f}"
              f" fill_room added bounded {counts[1][1]} (while open {counts[1][2]}) full {counts[10_000][1]}", flush=True)


def paint(seed, iters, log, quiet):
    """Paint the test's stroke; returns (scene count, fill_room added, added while the horizon was open)."""
    session_module.BRUSH_ITERATIONS = iters
    with tempfile.TemporaryDirectory() as d:
        s = Session(d, seed=seed, size=(600.0, 400.0))
        s.handle({"type": "load_exemplar", "example": EXAMPLE})
        log.clear()
        s.handle({"type": "stroke_start", "tool": "brush", "radius": 100.0, "points": [list(LINE[0])]})
        seg = [(0, s.state.n, list(log))]
        for i, p in enumerate(LINE[1:]):
            log.clear()
            s.handle({"type": "stroke_move", "points": [list(p)]})
            seg.append((i + 1, s.state.n, list(log)))
        log.clear()
        s.handle({"type": "stroke_end"})
        seg.append(("end", s.state.n, list(log)))
        if not quiet:
            print(f"seed {seed} BRUSH_ITERATIONS={iters}: scene {len(s.scene())}")
            for i, n, lg in seg:
                print(f"  seg {i}: n={n} fill_room {[(a, b, 'open' if c else 'done') for a, b, c in lg]}")
        return (len(s.scene()), sum(g for _, n, lg in seg for _, g, _ in lg), sum(g for _, n, lg in seg for _, g, o in lg if o))


if __name__ == "__main__":
    main()
