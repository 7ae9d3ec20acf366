"""Helper syn17: per --harder row, each kind's density in synth's output (3.5x, as synth_variants runs it) over the exemplar's, signed (the fidelity metric density[k] is |ratio - 1|).

    PYTHONPATH=TREE/src python benchmarks/syn17_density_dir.py CLASS:H:V:SEEDS ...
"""
import sys; sys.path.insert(0,"benchmarks")
from grow_variants import _harder_suite
from synth_variants import _harder, run
from strew.metrics import fidelity
mk=_harder_suite(); H=_harder()
for spec in sys.argv[1:]:
    cls,i,v,seeds=spec.split(":")
    ex=mk.make_exemplar(cls, rng=int(v), **H[cls][int(i)])
    for s in map(int, seeds.split(",")):
        out,_=run(ex,3.5,s,None)
        rep=fidelity(ex,out,eq5=False,local=False)
        print(spec, s, {k: (round(rep.metrics[f"density[{k}]"].result,6), round(rep.metrics[f"density[{k}]"].exemplar,6), round(rep.metrics[f"density[{k}]"].result/rep.metrics[f"density[{k}]"].exemplar,3)) for k in ex.kinds}, "faithful", rep.faithful, flush=True)
