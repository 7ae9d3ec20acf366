"""Run a benchmark with a variant of synth's balance rule (``_grow._prefer_balanced``)
wrapped in (helper bal19g, issue 19 point 4; the variants measured, none in the source):

- ``context``: where the output holds context elements (a tile grown beside finished
  ones), the rule's older constants, a disc of 1 exemplar side and z 1.5 (elsewhere
  0.5 and 0.75);
- ``cut``: seeds whose disc (``BALANCE_RADIUS`` exemplar sides) the region's boundary
  cuts are left as they are; the others as before;
- ``cutctx``: ``cut`` only where the output holds context elements (untiled synthesis
  unchanged);
- ``base``: the rule as it is.

``python benchmarks/bal19g_variant.py VARIANT SCRIPT -- <the script's arguments>``, SCRIPT a
file of benchmarks/ (worlds_strips.py, synth.py, fidelity.py), e.g. ``python
benchmarks/bal19g_variant.py cut worlds_strips.py -- --methods synth --synth-exemplar
three_sizes --widths 3,2,1 --seeds 1,2,3,4,5,6,7,8 --no-control --no-fidelity --out F``.
"""

import runpy
import sys
from pathlib import Path

import numpy as np

import strew.synth._grow as G

variant, script = sys.argv[1:3]
orig = G._prefer_balanced


def _side(state, seeds):
    prep = state.prep
    side = np.sqrt(np.bincount(prep.source, minlength=len(prep.names)) / np.maximum(prep.density, 1e-12))
    return side[prep.source[state.src[seeds]]]


def context(state, seeds, cands, costs, slack, c):
    if not state.fixed.any():
        return orig(state, seeds, cands, costs, slack, c)
    saved = G.BALANCE_RADIUS, G.BALANCE_Z
    G.BALANCE_RADIUS, G.BALANCE_Z = 1.0, 1.5
    try:
        orig(state, seeds, cands, costs, slack, c)
    finally:
        G.BALANCE_RADIUS, G.BALANCE_Z = saved


def cut(state, seeds, cands, costs, slack, c):
    if len(seeds) == 0 or state.region is None or state.tile is not None:
        return orig(state, seeds, cands, costs, slack, c)
    import shapely

    near = shapely.distance(state.region.geometry.boundary, shapely.points(state.pos[seeds])) < G.BALANCE_RADIUS * _side(state, seeds)
    keep = np.flatnonzero(~near)
    if len(keep) == len(seeds):
        return orig(state, seeds, cands, costs, slack, c)
    if len(keep) == 0:
        return None
    sub = costs[keep]
    orig(state, seeds[keep], cands[keep], sub, np.broadcast_to(np.asarray(slack, float), costs.shape[:1])[keep], c)
    costs[keep] = sub
    return None


def cutctx(state, seeds, cands, costs, slack, c):
    if not state.fixed.any():
        return orig(state, seeds, cands, costs, slack, c)
    return cut(state, seeds, cands, costs, slack, c)


if variant != "base":
    G._prefer_balanced = {"context": context, "cut": cut, "cutctx": cutctx}[variant]
print(f"balance rule variant: {variant}", flush=True)
sys.argv = [script] + sys.argv[4:]
runpy.run_path(str(Path(__file__).resolve().parent / script), run_name="__main__")
