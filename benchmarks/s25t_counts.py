"""Helper s25t: synth's kind counts against the class's own generator drawn at the output size.

For each CLASS:H:V, the exemplar (HARDER set H at variant seed V), synth's output at 3.5x side
(seed 1 unless :SEEDS given) and one generator draw at the output size (syn18_oracle's
big_params), counted per kind in the whole region and 20 units from its edge.

    PYTHONPATH=TREE/src python benchmarks/s25t_counts.py three_sizes:5:15[:1,2] ...
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
from grow_variants import _harder_suite
from svar13i_oracle import big_params
from syn13z_rows import counts
from synth_variants import _harder, run

for spec in sys.argv[1:]:
    p = spec.split(":")
    name, i, v = p[0], int(p[1]), int(p[2])
    seeds = [int(s) for s in p[3].split(",")] if len(p) > 3 else [1]
    kw = _harder()[name][i]
    mk = _harder_suite()
    ex = mk.make_exemplar(name, rng=v, **kw)
    big = mk.make_exemplar(name, rng=v + 1000, **big_params(name, kw, 3.5))
    def tally(a):
        kn = np.asarray(a.kind_names)
        return {k: int((kn == k).sum()) for k in sorted(set(kn))}
    print(f"{name} h{i}s{v}: exemplar {tally(ex)} generator@out {tally(big)} inner/1e4 {counts(big, 20)}", flush=True)
    for s in seeds:
        out, _ = run(ex, 3.5, s, None)
        print(f"   synth seed {s}: {tally(out)} inner/1e4 {counts(out, 20)}", flush=True)
