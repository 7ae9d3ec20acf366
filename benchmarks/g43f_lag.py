"""g43f: the lattice's lag from the field (``grow.py``'s ``field_misalignment``) of saved
outputs of ``benchmarks/g43f_smooth.py --save DIR`` (hex, the qc field).

    PYTHONPATH=src python benchmarks/g43f_lag.py /tmp/g43f/qc32_*_hex_r1.npy
"""
import re
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import grow as gb  # noqa: E402
from g43f_smooth import make_field  # noqa: E402

from strew import Region  # noqa: E402

ex = gb._suite_exemplar("hex_lattice", nx=8, ny=8)
sp = 12.0
for f in sys.argv[1:]:
    m = re.match(r"(qc|arc|sine)(\d+)_", Path(f).name)
    kind, n = m.group(1), int(m.group(2))
    xy = np.load(f)
    region = Region.rectangle(n * sp, n * sp)
    inner = region.distance_to_boundary(xy) > 2 * sp
    r = gb.field_misalignment(ex, xy, sp, inner, make_field(kind, n, sp))
    print(f"{Path(f).stem:22s} lag med/p90={r['misalign_deg_median']:.1f}/{r['misalign_deg_p90']:.1f}", flush=True)
