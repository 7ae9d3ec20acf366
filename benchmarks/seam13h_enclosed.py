"""Helper seam13h experiment (issue 13 point 2): ``_grow.owed_here`` (seam13g) with an
enclosure filter, run under another benchmark script without editing ``_grow``.

A copy stays owed where it stands only if the output's visible elements within the
exemplar's large spacing (``_class_spacing``) leave no angular gap wider than ``--gap``
radians around it (pi: the copy lies inside the convex hull of those neighbours, i.e.
not out beyond an open growth front). Everything after ``--`` is the target script and
its arguments, e.g.

    python benchmarks/seam13h_enclosed.py --gap 3.14159 -- benchmarks/seam13f_diag.py --seeds 1,...,8
    python benchmarks/seam13h_enclosed.py --gap 3.14159 -- benchmarks/seam13h_close.py --seeds 1-18

Measured (see the seam13h report): gap pi cuts the rule's firings about 10x on the close
sizes variant and leaves its nn[small>small] as with the rule off over 18 seeds, but
keeps only part of the 50x gain (failing windows seeds 1-16: 16, against 10 with the
rule as is and 26 without).
"""
import os
import runpy
import sys

import numpy as np
from scipy.spatial import cKDTree

import strew.synth._grow as G


def enclosed_owed_here(gap: float):
    base = G.owed_here

    def owed_here(state, pts, src):
        out = base(state, pts, src)
        if not out.any():
            return out
        prep = state.prep
        thr = G._class_spacing(prep)
        ss, cs = prep.source[src], prep.size_class[src]
        vis = np.flatnonzero(~prep.void[state.src])
        tree = cKDTree(state.pos[vis])
        for r in np.flatnonzero(out):
            nb = tree.query_ball_point(pts[r], thr[ss[r], cs[r]])
            if len(nb) < 2:
                out[r] = False
                continue
            v = state.pos[vis[nb]] - pts[r]
            a = np.sort(np.arctan2(v[:, 1], v[:, 0]))
            widest = max(float(np.diff(a).max()), float(a[0] + 2 * np.pi - a[-1]))
            out[r] = widest < gap
        return out

    return owed_here


if __name__ == "__main__":
    argv = sys.argv[1:]
    cut = argv.index("--")
    own, rest = argv[:cut], argv[cut + 1:]
    gap = float(own[own.index("--gap") + 1]) if "--gap" in own else np.pi
    G.owed_here = enclosed_owed_here(gap)
    sys.argv = rest
    sys.path.insert(0, os.path.dirname(os.path.abspath(rest[0])))
    runpy.run_path(rest[0], run_name="__main__")
