"""digest of synth outputs for synth_variants rows (case:label), 3.5x, seed 1, as synth_variants.run does."""
import sys, hashlib
import numpy as np
sys.path.insert(0, 'benchmarks')
import _variants
from _runner import fidelity_suite
from synth_variants import run
import strew
mk = fidelity_suite()
for spec in sys.argv[1].split(','):
    cls, label = spec.split(':')
    i, _, v = label[1:].partition('s')
    sets = _variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, [])
    ex = mk.make_exemplar(cls, rng=int(v), **sets[int(i)])
    out, _ = run(ex, 3.5, 1, None)
    print(spec, len(out), hashlib.sha1(np.ascontiguousarray(out.xy).tobytes()).hexdigest()[:12], flush=True)
