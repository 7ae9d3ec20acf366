# g60f: one qc16 case through the new test's _grow, pinned or not as the caller sets; argv: REGROW_UPSTREAM (None = main's path) and start "i,j". Run from the tree root with PYTHONPATH=src.
import sys
sys.path.insert(0, "tests/grow"); sys.path.insert(0, "tests")
up = None if sys.argv[1] == "None" else float(sys.argv[1])
st = tuple(int(v) for v in sys.argv[2].split(","))
from strew.grow import _flow_regrow, analyze
_flow_regrow.REGROW_UPSTREAM = up
from strew_testing import fidelity_suite
import test_grow_g60f_upstream_regrow as T
from test_grow_flow_gaps import _holes, _shares
from test_grow_g43f_flow_smooth import _across, _cores
import time
t = time.process_time()
ref = analyze(fidelity_suite().make_exemplar("hex_lattice", nx=8, ny=8))
out, region = T._grow(ref, st)
c = _cores(out.xy, region)
print(f"up={up} start={st} n={len(out.xy)} six={_shares(out.xy, region)[0]:.4f} holes={_holes(out.xy, region)} across={_across(out, region)} cores={len(c)} clustered={T._clustered(c)} cpu={time.process_time()-t:.1f}", flush=True)
