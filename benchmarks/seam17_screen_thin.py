"""Helper seam17 screening (issue 13 point 2), NOT a change of strew: runs
``benchmarks/seam17_all50.py`` with ``_thin.thin_orphans`` kept off ring children
(``_grow._ring_kids``; its removals of them are filtered out of the mask it removes), to
measure the change proposed for ``_thin.py`` (``results/seam17_proposed_thin_ring_kids.diff``).

    PYTHONPATH=TREE/src:benchmarks python benchmarks/seam17_screen_thin.py --names rings --seeds 1,9 --oracle-names '' --json F
"""
import runpy
import sys

import numpy as np

import strew.synth._grow as G
import strew.synth._thin as T

f=T.thin_orphans
def w(state,since=0):
    orig=state.remove
    ch=G._ring_kids(state.prep)[0]
    def rm(mask):
        m=np.asarray(mask,bool).copy(); m[:state.n]&=~ch[state.src[:state.n]]; return orig(m)
    state.remove=rm
    try: return f(state,since)
    finally: del state.remove
T.thin_orphans=w
sys.argv=['seam17_all50.py']+sys.argv[1:]
runpy.run_path('benchmarks/seam17_all50.py', run_name='__main__')
