"""Helper syn15: per kind, the exemplar's and synth's (3.5x, seeds 1, 2) density over the mean of the exemplar's generator drawn at 3.5x (rngs 101-104), for a --harder set at given variant seeds.

    PYTHONPATH=TREE/src python benchmarks/syn15_oracle_ratio.py stripes 3 7,8,9,10
"""
import sys, numpy as np
sys.path.insert(0, "benchmarks")
from grow_variants import _harder_suite
from synth_variants import _harder, run
from strew.metrics import fidelity
name, i = sys.argv[1], int(sys.argv[2])
vs = [int(x) for x in sys.argv[3].split(",")]
mk = _harder_suite()
kw = dict(_harder()[name][i])
for v in vs:
    ex = mk.make_exemplar(name, rng=v, **kw)
    size = ex.meta["params"]["size"]
    def dens(o):
        rep = fidelity(ex, o, eq5=False, local=False)
        return rep, {k: rep.metrics[f"density[{k}]"].result for k in ex.kinds}
    orc = []
    for r in range(101, 105):
        kw2 = dict(kw); kw2["size"] = size * 3.5
        if "count" in ex.meta["params"]:
            kw2["count"] = int(round(ex.meta["params"]["count"] * 12.25))
        orc.append(dens(mk.EXEMPLARS[name](r, **kw2))[1])
    rep, _ = dens(ex)
    exd = {k: rep.metrics[f"density[{k}]"].exemplar for k in ex.kinds}
    tol = {k: round(rep.metrics[f"density[{k}]"].tolerance, 3) for k in ex.kinds}
    om = {k: np.mean([o[k] for o in orc]) for k in ex.kinds}
    line = f"{name} h{i}s{v} tol {tol} ex/oracle " + " ".join(f"{k} {exd[k]/om[k]:.3f}" for k in ex.kinds)
    for s in (1, 2):
        out, _ = run(ex, 3.5, s, None)
        r2, d = dens(out)
        line += f" | synth s{s} n={len(out)} /oracle " + " ".join(f"{k} {d[k]/om[k]:.3f}" for k in ex.kinds)
    print(line, flush=True)
