"""Per world: each kind's density on each side of the borders (+-1 s, +-2 s) against the
interior's, and what placed it (issue 19.4, helper hie19x). ``python benchmarks/hie19x_kinds.py TAG ...``"""

import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import orn19m_willow as W  # noqa: E402


def main(tags):
    for tag in tags:
        for p in sorted((HERE / "results").glob(f"orn19m_{tag}_T*.npz")):
            w = W._world(p)
            s = w["s"]
            ga = w["garea"] / s**2
            a_i = (w["gd"] >= 3).sum() * ga
            for width in (1.0, 2.0):
                gn = w["gd"] < width
                a_f, a_l = (gn & (w["gsd"] < 0)).sum() * ga, (gn & (w["gsd"] > 0)).sum() * ga
                near = w["inside"] & (w["d"] < width)
                out = []
                for k, kn in enumerate(w["kinds"]):
                    m = w["kind"] == k
                    iv = (w["inside"] & m & (w["d"] >= 3)).sum() / a_i
                    f = (near & m & (w["sd"] < 0)).sum() / a_f / iv
                    l = (near & m & (w["sd"] > 0)).sum() / a_l / iv
                    out.append(f"{kn} {f:.2f}/{l:.2f}")
                print(f"{p.name} +-{width:g}s finished/later side: " + "  ".join(out))


if __name__ == "__main__":
    main(sys.argv[1:])
