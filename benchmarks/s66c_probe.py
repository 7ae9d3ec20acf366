"""Helper s66c (from g64c_probe.py): diagnosis of SYNTH on ``--varied`` clusters p4s39: the signed g[disc,dot]
curve (output minus exemplar, per bin of r/s), the ring shape of exemplar and output (dots per disc,
dot-to-disc distances, disc spacing) and optional PNG renders. src untouched.

    PYTHONPATH=src:benchmarks python benchmarks/s66c_probe.py clusters:p4s39 1 [--png PREFIX]
"""
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from _runner import fidelity_suite
from fresh17_rows import exemplar
from s64c_deciles import render, ring_shape
from synth_variants import run

import strew._fidelity as F
from strew.metrics import fidelity

CAP = []
_orig = F._discrepancies


def _wrap(a, b, kinds, s, **kw):
    CAP.append((a, b))
    return _orig(a, b, kinds, s, **kw)


F._discrepancies = _wrap


def main():
    np.set_printoptions(precision=2, suppress=True, linewidth=220)
    png = sys.argv[sys.argv.index("--png") + 1] if "--png" in sys.argv else None
    mk = fidelity_suite()
    cls, label = sys.argv[1].split(":")
    ex = exemplar(mk, cls, label)
    print(f"== {sys.argv[1]} exemplar counts", {k: int(np.sum(ex.kind == j)) for j, k in enumerate(ex.kinds)}, "frame", ex.region.bounds,
          "radii", {k: round(ex.shapes[k].radius, 2) for k in ex.kinds}, flush=True)
    ring_shape(ex, "exemplar")
    if png:
        render(ex, f"{png}_exemplar.png")
    for seed in _variants.ints(sys.argv[2]):
        out, _ = run(ex, 3.5, seed, None)
        CAP.clear()
        rep = fidelity(ex, out, eq5=False, local=False)
        a, b = CAP[0]
        for tag, st in (("exemplar", b), ("output", a)):
            print(f"   {tag} window area {st.area:.0f} counts {st.counts[:2]} lambda=n/area {np.array2string(st.counts[:2] / st.area, formatter={'float_kind': '{:.3e}'.format})} cell density {np.array2string(st.density, formatter={'float_kind': '{:.3e}'.format})}")
        print(f" seed {seed}: {'pass' if rep.faithful else 'FAIL'} n={len(out)} frame {out.region.bounds} s={rep.s:.2f} counts",
              {k: int(np.sum(out.kind == j)) for j, k in enumerate(out.kinds)})
        for k, m in rep.metrics.items():
            if m.applicable and (k.startswith(("g[", "density")) or not m.passed):
                print(f"   {k} {m.value:.3g}/{m.tolerance:.3g}")
        ge, go = rep.g_exemplar["disc,dot"], rep.g_result["disc,dot"]
        print("   r/s       ", rep.r / rep.s)
        print("   r         ", rep.r)
        print("   g_ex      ", ge)
        print("   g_out     ", go)
        print("   out-ex    ", go - ge)
        print(f"   share of squared error per bin (%) {(100 * (go - ge) ** 2 / np.sum((go - ge) ** 2))}")
        ring_shape(out, f"output s{seed}")
        if png:
            render(out, f"{png}_out_s{seed}.png")


if __name__ == "__main__":
    main()
