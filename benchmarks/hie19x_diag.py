"""Tiled hierarchy: does a later tile's vines phase see its finished neighbour's kept
vines, and where does the later side's vine excess grow from (issue 19.4, helper hie19x).

``PYTHONPATH=TREE/src python benchmarks/hie19x_diag.py make --tag TAG --tiles 94
--pattern hierarchy --overlaps`` runs ``benchmarks/hie19u_vines.py make`` (the world's
npz in benchmarks/results/orn19m_TAG_T94.npz) with ``_Grower._try`` wrapped, and writes
``benchmarks/results/hie19x_diag_TAG_T94.npz``: per successful vine of a run with context
(a later tile), its empty circle (x, y, r), the exact distance from the circle's centre to
the nearest context element (``ctx_clear``: below r - 1 cell means the circle reached
into a kept element, i.e. the tile did not see it), whether its parent is a context
element, the parent's and the vine's bounding-circle centres. Nothing in the library
changes. ``... analyze TAG`` prints the figures by side of the border.
"""

from __future__ import annotations

import runpy
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
RES = HERE / "results"


def make() -> None:
    import shapely

    import strew.ornament._engine as E

    rows: list = []
    trees: dict = {}
    orig = E._Grower._try

    def _try(self, goal, candidates, shift=None, circle=None):
        n0 = len(self.elements)
        ok = orig(self, goal, candidates, shift, circle)
        if not ok or not self.n_context:
            return ok
        ch = self.elements[n0]
        if ch.type != "vine":
            return ok
        key = id(self)
        if key not in trees:
            geoms = [pr.geometry for el in self.elements[: self.n_context] for pr in el.proxies]
            trees.clear()
            trees[key] = (shapely.STRtree(geoms), geoms)
        tree, geoms = trees[key]
        c = goal if circle is None else circle
        p = shapely.Point(float(c.center[0]), float(c.center[1]))
        i = tree.nearest(p)
        clear = float(shapely.distance(p, geoms[int(i)])) if i is not None else np.inf
        par = ch.parent
        pctx = bool(par is not None and par.index < self.n_context)
        px, py = par.proxies[0].bounding_circle()[:2] if par is not None else (np.nan, np.nan)
        qx, qy = ch.proxies[0].bounding_circle()[:2]
        rows.append((len(trees), float(c.center[0]), float(c.center[1]), float(c.radius), float(goal.radius), clear, pctx,
                     float(px), float(py), float(qx), float(qy), str(par.type if par is not None else ""), self.h))
        return ok

    E._Grower._try = _try
    tag = sys.argv[sys.argv.index("--tag") + 1]
    tiles = sys.argv[sys.argv.index("--tiles") + 1]
    sys.argv = [str(HERE / "hie19u_vines.py")] + sys.argv[1:]
    try:
        runpy.run_path(str(HERE / "hie19u_vines.py"), run_name="__main__")
    finally:
        a = list(zip(*rows)) if rows else [[]] * 13
        np.savez_compressed(RES / f"hie19x_diag_{tag}_T{float(tiles):g}.npz", cx=np.array(a[1]), cy=np.array(a[2]), r=np.array(a[3]),
                            raised=np.array(a[4]), clear=np.array(a[5]), pctx=np.array(a[6], bool), px=np.array(a[7]), py=np.array(a[8]),
                            qx=np.array(a[9]), qy=np.array(a[10]), ptype=np.array(a[11], str), h=np.array(a[12]))


if __name__ == "__main__":
    if sys.argv[1:2] == ["make"]:
        make()
