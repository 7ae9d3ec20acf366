"""g27g: for each start (in spacings) of the hexagonal lattice over a square of 16 spacings
along the quarter circles (tests/grow/test_grow_flow14p_one_side.py), whether the order is
across-first, whether a later band run is kept over the first in any band pass, the final six share.

    PYTHONPATH=src python benchmarks/g27g_band_starts.py 2,2 3,2 2,3 3,3
"""
import sys, numpy as np
sys.path.insert(0,'tests/grow'); sys.path.insert(0,'tests')
from strew.grow import _flow_net
from strew.grow._growth import GrowParams, grow_reference
from strew.grow._objects import ELEMENT
from strew.grow._analysis import analyze
from strew_testing import fidelity_suite
from test_grow_flow_gaps import SP, _holes, _shares, _quarter_circles
from strew import Region
ref = analyze(fidelity_suite().make_exemplar("hex_lattice", nx=8, ny=8))
orig = _flow_net._band_passes
for s in sys.argv[1:]:
    sx, sy = map(float, s.split(','))
    shares = []; info = {}
    def spy(g, turn0, band):
        info['across'] = g.flow_across_first()
        begin = _flow_net.saved_moves(g, [o for o in g.order if g.state[o] == ELEMENT])
        runs = _flow_net.BAND_RUNS
        _flow_net.BAND_RUNS = runs[:1]
        try: orig(g, turn0, band)
        finally: _flow_net.BAND_RUNS = runs
        first = _flow_net._six_share(g)
        _flow_net.undo_moves(g, begin)
        moved = orig(g, turn0, band)
        shares.append((round(first,4), round(_flow_net._six_share(g),4)))
        return moved
    _flow_net._band_passes = spy
    a = 16*SP
    region = Region.rectangle(a, a)
    out = grow_reference(ref, GrowParams(region=region, mode="flow", flow=_quarter_circles(a), start=(sx*SP, sy*SP)), rng=1)
    _flow_net._band_passes = orig
    print(s, 'across', info.get('across'), 'acted', any(k>f for f,k in shares), 'final %.4f'%_shares(out.xy, region)[0], 'holes', _holes(out.xy, region), shares, flush=True)
