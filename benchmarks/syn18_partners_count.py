"""Helper syn18: how many partners fill_partners gives on two_sizes h5s11 (seeds 1, 2): PYTHONPATH=TREE/src python benchmarks/syn18_partners_count.py"""
import sys; sys.path.insert(0, __file__.rsplit("/", 1)[0])
import strew.synth._pebbles as PB, strew.synth._grow as G
from grow_variants import _harder_suite
from synth_variants import _harder, run
orig=PB.fill_partners
def fp(state, room=None):
    n0=state.n; r=orig(state, room); print("fill_partners added", r, "of n", n0, "room", room); return r
PB.fill_partners=fp
if hasattr(G,"fill_partners"): G.fill_partners=fp
ex=_harder_suite().make_exemplar("two_sizes", rng=11, **_harder()["two_sizes"][5])
for s in (1,2): run(ex,3.5,s,None)
