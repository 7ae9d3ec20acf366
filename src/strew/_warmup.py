"""Compile strew's numba kernels ahead of the first command (issue 16).

    python -m strew._warmup [--list] [--case NAME ...]

Runs every method once on tiny inputs, through the same entry points a user's first
command goes through (``strew.cli.main``, a studio session's stroke), so that numba
compiles each kernel with the signatures those commands use and writes it to its
on-disk cache (``cache=True``). The wheel build (``hatch_build.py``) runs this in a
subprocess with ``NUMBA_CACHE_DIR`` pointing at a scratch folder and ships the cache
files next to the kernel modules (``strew/<package>/__pycache__``), where numba's
in-tree cache locator finds them after ``pip install .``: the source stamp numba
checks is a hash of the source file's content (numba >= 0.64), and the index key holds
numba's version, the CPU (name and features) and the function's bytecode, so a
mismatch on any of these only means a compile, as without the shipped files.

It can also be run by hand after an install whose caches did not match (another CPU,
another numba): ``python -m strew._warmup`` then fills numba's usual cache.

Each case is small (well under a second warm); a failing case is reported and the
others still run (exit status 1 if any failed).
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
import traceback
from pathlib import Path

__all__ = ["CASES", "STUDIO_CASES", "warm_up"]

# name -> CLI arguments; "{ex}" is the examples folder, "{out}" a scratch folder.
# Chosen to reach every kernel a command calls with the argument types it uses: the
# plain and periodic variants compile separate copies (periodic branches are pruned
# at compile time), and options that switch kernels (kind choice, scale choice,
# rotation modes, flow, boundary, spray, patch init, global optimisation) get a case.
CASES: dict[str, list[str]] = {
    "pack fill-gap": ["pack", "{ex}/shapes/concave.svg", "--size", "60x50", "--scale", "0.2:0.3", "--seed", "1"],
    "pack fill-gap fit": ["pack", "{ex}/shapes/concave.svg", "{ex}/shapes/tree.svg", "--size", "60x50", "--kind-choice", "fit", "--scale-choice", "fit", "--scale", "0.1:0.3", "--seed", "1"],
    "pack fill-gap region": ["pack", "{ex}/shapes/elongated.svg", "--region", "{ex}/regions/blob_with_hole.svg", "--seed", "1", "--max-failures", "20"],
    "pack fill-gap periodic": ["pack", "{ex}/shapes/concave.svg", "--size", "60x50", "--scale", "0.15:0.25", "--periodic", "--seed", "1"],
    "synth fill": ["synth", "{ex}/exemplars/stones.svg", "--size", "90x70", "--seed", "1"],
    "synth patch": ["synth", "{ex}/exemplars/stones.svg", "--size", "90x70", "--init", "patch", "--optimize", "global", "--seed", "1"],
    "synth brush": ["synth", "{ex}/synth/stones.json", "--brush", "{ex}/synth/stroke.json", "--brush-radius", "30", "--seed", "1"],
    "synth periodic": ["synth", "{ex}/exemplars/stones.svg", "--size", "90x70", "--periodic", "--seed", "1"],
    "grow": ["grow", "{ex}/exemplars/scales.svg", "--count", "40", "--seed", "1"],
    "grow rotate": ["grow", "{ex}/exemplars/stones.svg", "--count", "30", "--mode", "rotate", "--seed", "1"],
    "grow flow": ["grow", "{ex}/grow/scales_hex.json", "--flow", "{ex}/grow/flow_strokes.json", "--count", "30", "--seed", "1"],
    # flow mode filling a region: the passes after the growth (the relaxation's sparse
    # system, the distances to the region's edge: strew.grow._relax_kernels, _flow_kernels)
    "grow flow region": ["grow", "{ex}/grow/scales_hex.json", "--flow", "{ex}/grow/flow_strokes.json", "--size", "160x120", "--seed", "1"],
    "grow boundary": ["grow", "{ex}/grow/stones_irregular.json", "--boundary", "{ex}/grow/boundary_stroke.json", "--count", "30", "--seed", "1"],
    "grow spray": ["grow", "{ex}/exemplars/scales.svg", "--spray", "{ex}/grow/spray_path.json", "--spray-radius", "40", "--count", "30", "--seed", "1"],
    "grow periodic": ["grow", "{ex}/exemplars/scales.svg", "--size", "80x80", "--periodic", "--count", "40", "--seed", "1"],
    "ornament dots": ["ornament", "dots", "--size", "50x50", "--seed", "1"],
    "ornament flowers": ["ornament", "flowers", "--size", "50x50", "--seed", "1"],
    "ornament spirals": ["ornament", "spirals", "--size", "50x50", "--seed", "1"],
    "ornament hierarchy": ["ornament", "hierarchy", "--size", "50x50", "--seed", "1"],
    "ornament vase": ["ornament", "vase", "--size", "50x50", "--seed", "1"],
    "ornament willow": ["ornament", "willow", "--size", "50x50", "--seed", "1"],
    "ornament periodic": ["ornament", "dots", "--size", "50x50", "--periodic", "--seed", "1"],
    # the default square (2000): a smaller one leaves fig03's blobs empty, uncompiled
    "run": ["run", "{ex}/program/fig03_two_scales.py", "--seed", "1"],
    "run partitions": ["run", "{ex}/program/fig05_partitions.py", "--size", "300", "--seed", "1"],
}

# the studio's first stroke of each tool: the messages a browser sends, to a session
STUDIO_CASES: dict[str, str] = {"studio brush": "brush", "studio spray": "spray"}


def _studio(project: Path, tool: str) -> None:
    from .studio._session import Session

    s = Session(project, size=(200, 160))
    s.handle({"type": "load_exemplar", "example": "scales.svg"})
    pts = [[30.0 + 5.0 * i, 80.0 + 20.0 * ((i % 10) / 10.0)] for i in range(25)]
    s.handle({"type": "stroke_start", "tool": tool, "radius": 30, "points": pts[:1]})
    for p in pts[1:]:
        s.handle({"type": "stroke_move", "points": [p]})
    s.handle({"type": "stroke_end"})


def warm_up(names: list[str] | None = None, log=print) -> list[str]:
    """Run the warm-up cases (all, or those named); returns the names that failed.

    Parameters
    ----------
    names : list of str, optional
        Case names from :data:`CASES` and :data:`STUDIO_CASES`.
    log : callable
        Called with one line per case (name, seconds, ok or the error).
    """
    from ._resources import examples_dir
    from .cli import main

    ex = str(examples_dir())
    todo = [n for n in [*CASES, *STUDIO_CASES] if names is None or n in names]
    failed = []
    with tempfile.TemporaryDirectory(prefix="strew-warmup-") as tmp:
        for i, name in enumerate(todo):
            out = Path(tmp) / f"case{i}"
            out.mkdir()
            t0 = time.perf_counter()
            try:
                if name in CASES:
                    argv = [a.format(ex=ex) for a in CASES[name]]
                    rc = main([*argv, "-q", "-o", str(out / "out.json")])
                    if rc != 0:
                        raise RuntimeError(f"exit status {rc}")
                else:
                    _studio(out, STUDIO_CASES[name])
            except Exception as e:  # one case failing leaves the others' kernels compiled
                failed.append(name)
                log(f"{name}: FAILED after {time.perf_counter() - t0:.1f} s: {e!r}")
                traceback.print_exc(file=sys.stderr)
            else:
                log(f"{name}: {time.perf_counter() - t0:.1f} s")
    return failed


def _main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m strew._warmup", description=__doc__.splitlines()[0])
    p.add_argument("--list", action="store_true", help="print the case names and exit")
    p.add_argument("--case", action="append", default=None, help="run only this case (repeatable)")
    args = p.parse_args(argv)
    names = [*CASES, *STUDIO_CASES]
    if args.list:
        print("\n".join(names))
        return 0
    unknown = [c for c in args.case or [] if c not in names]
    if unknown:
        p.error(f"unknown case {unknown}; cases: {names}")
    t0 = time.perf_counter()
    failed = warm_up(args.case, log=lambda s: print(s, flush=True))
    print(f"warm-up: {time.perf_counter() - t0:.1f} s, {len(failed)} failed" + (f": {', '.join(failed)}" if failed else ""), flush=True)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(_main())
