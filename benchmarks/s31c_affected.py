"""Helper s31c: which exemplars ``_prepare.SURROUND_K`` changes (their interior, hence co(e)).

    PYTHONPATH=src python benchmarks/s31c_affected.py [VARIANT_SEEDS] [CLASSES]

For the fidelity suite's exemplars and the ``--varied`` / ``--harder`` sets at the given
variant seeds (default 17-24), prints each exemplar whose interior differs with the flag
on and off (the others synthesize byte-identically): per size class the interior count
off -> on.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import numpy as np

import _variants
from _runner import fidelity_suite
from strew.synth import _prepare
from strew.synth._api import as_selection
from strew.synth._prepare import prepare


class _Stop(Exception):
    pass


def _grab(*args, **kw):
    """Stands in for ``_prepare.k_coherence``: stops ``prepare`` with the interior mask and size classes."""
    raise _Stop(np.array(args[10], bool), np.asarray(args[13]))


_prepare.k_coherence = _grab


def interior(ex, on):
    _prepare.SURROUND_K = on
    try:
        prepare(as_selection(ex), k=5)
    except _Stop as e:
        return e.args
    raise RuntimeError("k_coherence not reached")


def main():
    vs = _variants.ints(sys.argv[1]) if len(sys.argv) > 1 else list(range(17, 25))
    only = sys.argv[2].split(",") if len(sys.argv) > 2 else None
    mk = fidelity_suite()
    from grow_variants import _harder_suite
    from synth_variants import _harder

    hk = _harder_suite()
    cases = []
    for cls in ["clusters", "rings", "two_sizes", "three_sizes", "stones", "sparse_voids", "sticks", "stripes", "hex", "bricks", "scales", "grid"]:
        if only and cls not in only:
            continue
        try:
            cases.append((f"{cls} suite", lambda cls=cls: mk.make_exemplar(cls)))
        except Exception:
            continue
        for v in vs:
            cases.append((f"{cls} v{v}", lambda cls=cls, v=v: mk.make_exemplar(cls, rng=v)))
            for i, kw in enumerate(_variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, [])):
                cases.append((f"{cls} p{i}s{v}", lambda cls=cls, v=v, kw=kw: mk.make_exemplar(cls, rng=v, **kw)))
            for i, kw in enumerate(_harder().get(cls, [])):
                cases.append((f"{cls} h{i}s{v}", lambda cls=cls, v=v, kw=kw: hk.make_exemplar(cls, rng=v, **kw)))
    changed = 0
    for name, make in cases:
        try:
            ex = make()
        except Exception:  # a class without that variant
            continue
        if not len(ex):
            continue
        a, cl = interior(ex, False)
        b, _ = interior(ex, True)
        if (a != b).any():
            changed += 1
            per = {int(c): f"{int(a[cl == c].sum())}->{int(b[cl == c].sum())}" for c in np.unique(cl) if (a[cl == c] != b[cl == c]).any()}
            print(name, per, flush=True)
    print(f"{changed} of {len(cases)} exemplars changed")


if __name__ == "__main__":
    main()
