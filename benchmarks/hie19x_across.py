"""Per world: the vines on the later side of the borders (+-1 s, +-2 s) split by the tile
that grew them: the finished tile across the nearest border line (kept at their parent,
or grown and dropped) and the other finished tiles whose halo reaches there (near the
corners); against the interior's vine density (issue 19.4, helper hie19x). The dropped
count of hie19x_band.py pools every finished tile; this one keeps the tile across the
line apart. ``python benchmarks/hie19x_across.py TAG [TAG ...]``"""

import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import orn19m_willow as W  # noqa: E402


def _across(x, y, placer, tile):
    """Whether ``placer`` is the tile across the nearest inner border line (4 x 4 tiles)."""
    lines = np.arange(1, 4) * tile
    ddx, ddy = np.abs(x[:, None] - lines), np.abs(y[:, None] - lines)
    col, row = np.clip(np.floor(x / tile), 0, 3).astype(int), np.clip(np.floor(y / tile), 0, 3).astype(int)
    vert = ddx.min(1) <= ddy.min(1)
    lx, ly = lines[ddx.argmin(1)], lines[ddy.argmin(1)]
    ncol = np.where(vert, np.where(x < lx, col + 1, col - 1), col)
    nrow = np.where(vert, row, np.where(y < ly, row + 1, row - 1))
    return placer == nrow * 4 + ncol


def main(tags):
    for tag in tags:
        for p in sorted((HERE / "results").glob(f"orn19m_{tag}_T*.npz")):
            z, w = np.load(p), W._world(p)
            s, tile = w["s"], w["tile"]
            ga = w["garea"] / s**2
            kv = w["kinds"].index("vine")
            v = w["inside"] & (w["kind"] == kv)
            iv = (v & (w["d"] >= 3)).sum() / ((w["gd"] >= 3).sum() * ga)
            acr, dacr = _across(z["x"], z["y"], z["tile"], tile), _across(z["dx"], z["dy"], z["dtile"], tile)
            dv = w["dinside"] & (w["dkind"] == kv)
            for width in (1.0, 2.0):
                a_l = ((w["gd"] < width) & (w["gsd"] > 0)).sum() * ga
                k = v & (w["d"] < width) & (w["sd"] > 0) & w["other"]
                d = dv & (w["dd"] < width) & (w["dsd"] > 0)
                own = (v & (w["d"] < width) & (w["sd"] > 0) & ~w["other"]).sum() / a_l / iv
                ka, da = (k & acr).sum() / a_l / iv, (d & dacr).sum() / a_l / iv
                print(f"{p.name} +-{width:g}s later side: the finished tile across the line grew {ka + da:.3f} (kept {ka:.3f}, "
                      f"dropped {da:.3f}); other finished tiles kept {(k & ~acr).sum() / a_l / iv:.3f} dropped {(d & ~dacr).sum() / a_l / iv:.3f}; "
                      f"the later tile's own {own:.3f}")


if __name__ == "__main__":
    main(sys.argv[1:])
