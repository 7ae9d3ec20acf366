"""Helper s67h: exemplars by label (hIsV --harder, pIsV / vV --varied)."""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from _runner import fidelity_suite
from grow_variants import _harder_suite
from synth_variants import _harder


def exemplar(cls, label):
    i, _, v = label[1:].partition("s")
    if label.startswith("h"):
        return _harder_suite().make_exemplar(cls, rng=int(v), **_harder()[cls][int(i)])
    mk = fidelity_suite()
    if label.startswith("v"):
        return mk.make_exemplar(cls, rng=int(label[1:]))
    sets = _variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, [])
    return mk.make_exemplar(cls, rng=int(v), **sets[int(i)])
