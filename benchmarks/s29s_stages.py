"""Helper s29s: element count after each stage of synth's fill on chosen --varied rows.

    PYTHONPATH=src python benchmarks/s29s_stages.py CLASS:LABEL[,CLASS:LABEL...] 1-3

Prints, per row and seed, the count after the growth loop (Algorithm 1, §5.1) and after
each later stage of ``_grow.grow`` (the stage's name and its change), the output's count,
the signed density ratio per kind (output / exemplar, as ``strew.metrics.fidelity``
measures it: ``density[kind]`` is ``|ratio - 1|``) and a rough one (elements per unit
area in the box shrunk by 0.15 of its side).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _variants
from fresh17_rows import exemplar
from _runner import fidelity_suite

from strew.synth import _grow, _displace, _shell, _farmix, _pebbles, _swap, _thin
from strew import _fidelity
from strew.metrics import fidelity

SIGNED: list = []
_disc = _fidelity._discrepancies


def _signed(a, b, *args, **kw):
    """Record the first (result against exemplar) density ratio, signed."""
    SIGNED.append(a.density / b.density)
    return _disc(a, b, *args, **kw)


_fidelity._discrepancies = _signed

LOG: list = []


def _wrap(mod, name):
    f = getattr(mod, name)

    def g(state, *a, **k):
        if not LOG or LOG[-1][0] == "start":
            LOG.append(("loop", state.n))
        n0 = state.n
        r = f(state, *a, **k)
        LOG.append((name, state.n - n0))
        return r

    setattr(mod, name, g)


for mod, names in ((_grow, ["_complete_anchor_rings", "fill_room", "fill_holes"]), (_displace, ["fill_displaced"]),
                   (_shell, ["fill_beside_largest", "fill_beside_far_small"]), (_farmix, ["trade_far_small"]),
                   (_pebbles, ["fill_partners"]), (_swap, ["fill_swapped"]),
                   (_thin, ["thin_small", "thin_orphans", "thin_crowded", "thin_edge_strays"])):
    for n in names:
        _wrap(mod, n)


def _inner(arr, m=0.15):
    """Elements per unit area in the region's box shrunk by ``m`` of its side (a rough,
    signed stand-in for fidelity's Voronoi density)."""
    x0, y0, x1, y1 = arr.region.bounds
    dx, dy = m * (x1 - x0), m * (y1 - y0)
    xy = arr.xy
    ins = (xy[:, 0] > x0 + dx) & (xy[:, 0] < x1 - dx) & (xy[:, 1] > y0 + dy) & (xy[:, 1] < y1 - dy)
    return ins.sum() / ((x1 - x0 - 2 * dx) * (y1 - y0 - 2 * dy))


def main():
    specs, seeds = sys.argv[1], _variants.ints(sys.argv[2])
    mk = fidelity_suite()
    from synth_variants import run

    for spec in specs.split(","):
        cls, label = spec.split(":")
        ex = exemplar(mk, cls, label)
        for seed in seeds:
            LOG.clear()
            SIGNED.clear()
            LOG.append(("start", 0))
            out, _ = run(ex, 3.5, seed, None)
            rep = fidelity(ex, out, eq5=False, local=False)
            stages = " ".join(f"{k}={v:+d}" if k != "loop" else f"loop={v}" for k, v in LOG[1:] if v or k == "loop")
            dens = " ".join(f"{k}={m.value:.3f}{'' if m.passed else '!'}" for k, m in rep.metrics.items() if k.startswith("density"))
            fails = [f"{k}={m.value:.3g}/{m.tolerance:.3g}" for k, m in rep.metrics.items() if m.applicable and not m.passed]
            sgn = _inner(out) / _inner(ex)
            print(f"{spec} seed {seed}: n_ex={len(ex)} n={len(out)} inner ratio {sgn:.3f} density ratio {' '.join(f'{x:.3f}' for x in SIGNED[0])} {stages} | {dens} | {'pass' if rep.faithful else 'FAIL ' + ' '.join(fails)}", flush=True)


if __name__ == "__main__":
    main()
