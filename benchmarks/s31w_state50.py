"""Helper s31w (issue 13 point 2): synthesize one suite exemplar at 50x (as seam17_all50.py
does) and pickle the synth state's last picture (positions, exemplar sources, birth
iterations, the exemplar's element positions) with the output and its local fidelity map.

    PYTHONPATH=src python benchmarks/s31w_state50.py NAME SEED OUT.pkl
"""

from __future__ import annotations

import pickle
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _runner import fidelity_suite

from strew import Region
from strew.metrics import fidelity
from strew.synth import synthesize
from strew.synth._state import SynthState


def main() -> None:
    name, seed, path = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    ex = fidelity_suite().make_exemplar(name)
    x0, y0, x1, y1 = ex.region.bounds
    region = Region.rectangle(7.07 * (x1 - x0), 7.07 * (y1 - y0))
    keep: dict = {}
    orig = SynthState.to_arrangement

    def spy(self, **kw):
        p = self.prep
        keep.update(pos=self.pos[: self.n].copy(), src=self.src[: self.n].copy(), born=np.asarray(self.born[: self.n]).copy(),
                    epos=p.pos.copy(), ekind=p.kind.copy(), void=p.void.copy(), r=p.r.copy(), rc=p.rc.copy())
        return orig(self, **kw)

    SynthState.to_arrangement = spy
    t = time.process_time()
    out = synthesize(ex, region, rng=seed, measure=False)
    rep = fidelity(ex, out, region, eq5=False)
    S = np.asarray(rep.local["score"], float)
    bad = [(i, j, round(float(s), 3), rep.local["worst_metric"][i][j]) for (i, j), s in np.ndenumerate(S) if np.isfinite(s) and s > 1.0]
    print(f"{name} s{seed} n={len(out)} worst {np.nanmax(S):.3f} failing {len(bad)} {bad} cpu {time.process_time() - t:.0f}s", flush=True)
    with open(path, "wb") as f:
        pickle.dump({"ex": ex, "out": out, "region": region, "local": rep.local, "state": keep}, f)


if __name__ == "__main__":
    main()
