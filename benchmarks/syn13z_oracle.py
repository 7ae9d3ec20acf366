"""syn13z (issue 13 point 1): the generator drawn at the output size (svar13i_oracle.big_params), six draws, against a --harder exemplar: python benchmarks/syn13z_oracle.py two_sizes:4:7 "stone>pebble"."""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np
from grow_variants import _harder_suite
from svar13i_oracle import big_params
from syn13z_rows import nnq
from synth_variants import _harder

from strew.metrics import fidelity

name,i,v = sys.argv[1].split(":")[:3]
kw = _harder()[name][int(i)]
mk = _harder_suite()
ex = mk.make_exemplar(name, rng=int(v), **kw)
bp = big_params(name, kw, 3.5)
pairs = [tuple(x.split(">")) for x in sys.argv[2:]]
for d in range(6):
    big = mk.make_exemplar(name, rng=int(v) + 1000 * d, **bp)
    rep = fidelity(ex, big, eq5=False, local=False)
    kn = np.asarray(big.kind_names)
    print("draw", d, {k:int((kn==k).sum()) for k in set(kn)}, rep.faithful, [f"{k}={rep.metrics[k].value:.3f}/{rep.metrics[k].tolerance:.3f}" for k in rep.failures],
          " ".join(f"nn[{a}>{b}]={rep.metrics[f'nn[{a}>{b}]'].value:.3f} out {np.round(nnq(big,a,b)/rep.s,2)}" for a,b in pairs))
