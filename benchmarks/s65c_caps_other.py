"""s65c: does the ring cap act on two_sizes / three_sizes (and other classes)? capped
children of each exemplar (ring_caps(prep)[0]); with none, grow skips the rule (rcap None)."""
import sys
import numpy as np
sys.path.insert(0, "benchmarks")
import _variants
from _runner import fidelity_suite
from fresh17_rows import exemplar
from strew import Region
from strew.synth import new_state
from strew.synth._prepare import ring_caps
mk = fidelity_suite()
seeds = _variants.ints(sys.argv[2])
for cls in sys.argv[1].split(","):
    nsets = len(_variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, []))
    labels = [f"v{s}" for s in seeds] + [f"p{i}s{s}" for i in range(nsets) for s in seeds]
    acting = []
    for lab in labels:
        ex = exemplar(mk, cls, lab)
        prep = new_state(ex, Region.rectangle(50, 50), rng=1).prep
        c = ring_caps(prep)[0]
        if c.any():
            acting.append(f"{lab}:{int(c.sum())}")
    print(f"{cls}: {len(labels)} exemplars, capped children in {len(acting)}: {' '.join(acting)}", flush=True)
