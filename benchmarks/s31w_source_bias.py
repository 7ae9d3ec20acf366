"""Helper s31w (issue 13 point 2): where in the exemplar synth's output copies come from, by
where they stand in the output. For a state pickled by ``s31w_state50.py``, prints the
mean exemplar y (x) of the sources of the output's lower and upper (left and right)
halves, the share of each half copied from the exemplar's lower (left) half, and per
kind the output's median nearest-same-kind distance by the source's exemplar y band
and by the output half, against the exemplar's own by exemplar half.

    PYTHONPATH=src python benchmarks/s31w_source_bias.py STATE.pkl [STATE.pkl ...]
"""

from __future__ import annotations

import pickle
import sys

import numpy as np
from scipy.spatial import cKDTree


def main() -> None:
    for path in sys.argv[1:]:
        with open(path, "rb") as f:
            d = pickle.load(f)
        st, ex = d["state"], d["ex"]
        pos, src, epos = st["pos"], st["src"], st["epos"]
        vis = ~st["void"][src]
        pos, src = pos[vis], src[vis]
        x0, y0, x1, y1 = ex.region.bounds
        cx, cy = 0.5 * (x0 + x1), 0.5 * (y0 + y1)
        oc = 0.5 * (pos.min(0) + pos.max(0))
        sy, sx = epos[src, 1], epos[src, 0]
        lo, le = pos[:, 1] < oc[1], pos[:, 0] < oc[0]
        print(f"{path}: n {len(pos)}")
        print(f"  source y: output lower half mean {sy[lo].mean():.1f} (share from exemplar's lower half {np.mean(sy[lo] < cy):.2f}), "
              f"upper half {sy[~lo].mean():.1f} ({np.mean(sy[~lo] < cy):.2f}); exemplar centre y {cy:.1f}")
        print(f"  source x: output left half mean {sx[le].mean():.1f} (share from exemplar's left half {np.mean(sx[le] < cx):.2f}), "
              f"right half {sx[~le].mean():.1f} ({np.mean(sx[~le] < cx):.2f})")
        names = np.asarray(ex.kind_names)
        for k in np.unique(names):
            mine = names[src] == k
            p = pos[mine]
            if len(p) < 3:
                continue
            dd = cKDTree(p).query(p, k=2)[0][:, 1]
            e = ex.xy[names == k]
            de = cKDTree(e).query(e, k=2)[0][:, 1]
            el = e[:, 1] < cy
            print(f"  {k}: output nn median lower/upper half {np.median(dd[lo[mine]]):.2f}/{np.median(dd[~lo[mine]]):.2f}; "
                  f"by source in exemplar lower/upper half {np.median(dd[sy[mine] < cy]):.2f}/{np.median(dd[sy[mine] >= cy]):.2f}; "
                  f"exemplar's own lower/upper half {np.median(de[el]):.2f}/{np.median(de[~el]):.2f}")


if __name__ == "__main__":
    main()
