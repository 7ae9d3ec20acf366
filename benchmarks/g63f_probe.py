"""g63f: per regrowth attempt of ``regrow_sheared`` (upstream / all sides, patch size,
widened), the six share before/after, the far point, the lattice's turn p90 against the
band pass's limit and the elements turned past 12 degrees; for qc cases (hex, rng 1).

    PYTHONPATH=src:benchmarks python benchmarks/g63f_probe.py 16:2:14 16:14:2
"""
import sys

import numpy as np

import g43f_smooth as gs
import grow as gb
from strew import Region
from strew.grow import grow as grow_fn
from strew.grow import _flow_regrow as fr
from strew.grow._flow_net import _misalignment
from strew.grow._flow_net import _six_share as six_share
from strew.grow._flow_retry import interior_score

orig = fr._grow_back
log = []


def wrapped(g, patch, target, rep, up):
    s0, f0, t0, m0 = six_share(g), interior_score(g)[1], fr._turned(g), _misalignment(g)
    orig(g, patch, target, rep, up)
    lim = getattr(g, "flow_net_turn0", None)
    lim = None if lim is None or g.p.flow_net_turn is None else lim + g.p.flow_net_turn
    log.append(f"  up={up:d} patch={len(patch)} six {s0:.4f}->{six_share(g):.4f} far {f0:.3f}->{interior_score(g)[1]:.3f} "
               f"turn {m0:.2f}->{_misalignment(g):.2f} lim {lim} turned {t0}->{fr._turned(g)}")


fr._grow_back = wrapped
ex = gb._suite_exemplar("hex_lattice", nx=8, ny=8)
sp = 12.0
for arg in sys.argv[1:]:
    n, i, j = (int(v) for v in arg.split(":"))
    region = Region.rectangle(n * sp, n * sp)
    log.clear()
    out = grow_fn(ex, region=region, mode="flow", flow=gs.make_field("qc", n, sp), rng=1, start=(i * sp, j * sp))
    inner = region.distance_to_boundary(out.xy) > 2 * sp
    c = gs.cores(out.xy, sp, inner)
    print(f"qc{n} ({i},{j}) n={len(out)} cores {c['cores']} clustered {c['clustered_cores']}")
    print("\n".join(log), flush=True)
