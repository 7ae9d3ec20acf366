"""Helper syn13a: per three sizes exemplar (suite, --harder h0-h13 s7/s8, --varied/edge), the share of the
inner frame that its largest size class covers (inner-frame density x mean bounding-disc area, as
``_grow._top_cover`` computes it) next to that class's density after growth from syn13a_stages.py output.

    python benchmarks/syn13a_cover.py [STAGES_OUTPUT]
"""
import re
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from grow_variants import HARDER, _harder_suite

from strew.synth import _grow as G
from strew.synth._api import new_state

got = {}
if len(sys.argv) > 1:
    spec = None
    with open(sys.argv[1]) as fh:
        lines = fh.read().splitlines()
    for line in lines:
        m = re.match(r"== (\S+) ", line)
        if m:
            spec = m.group(1).rsplit(":", 1)[0]
        m = re.match(r"\s+growth\s+\[(.*)\]", line)
        if m and spec:
            got[spec] = float(m.group(1).split()[-1])
mk = _harder_suite()
rows = [("three_sizes:suite:0", mk.make_exemplar("three_sizes"))]
rows += [(f"three_sizes:{i}:{s}", mk.make_exemplar("three_sizes", rng=s, **kw)) for i, kw in enumerate(HARDER["three_sizes"]) for s in (7, 8)]
rows += [(f"three_sizes:{lab}", mk.make_exemplar("three_sizes", rng=s, **kw)) for lab, tag, s, kw in _variants.cases("three_sizes", [1, 2, 3], True)]
for name, ex in rows:
    prep = new_state(ex).prep
    cov = float(G._top_cover(prep)[0])
    print(f"{name:24s} cover {cov:.3f}  large after growth {got.get(name, float('nan')):.3f}")
