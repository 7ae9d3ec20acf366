"""Helper c50: a digest of synth's 50x output for one suite class and seed (as seam17_all50.py
makes it), to tell whether two trees give byte-identical output on this machine.

    PYTHONPATH=TREE/src python benchmarks/c50_hash.py [clusters] [3]
"""
import hashlib
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _runner import fidelity_suite

from strew import Region
from strew.synth import synthesize

name = sys.argv[1] if len(sys.argv) > 1 else "clusters"
seed = int(sys.argv[2]) if len(sys.argv) > 2 else 3
ex = fidelity_suite().make_exemplar(name)
x0, y0, x1, y1 = ex.region.bounds
out = synthesize(ex, Region.rectangle(7.07 * (x1 - x0), 7.07 * (y1 - y0)), rng=seed, measure=False)
h = hashlib.sha256(np.ascontiguousarray(out.xy).tobytes() + np.ascontiguousarray(out.kind).tobytes() + np.ascontiguousarray(out.rotation).tobytes()).hexdigest()[:16]
print(name, seed, "n", len(out), "sha256", h)
