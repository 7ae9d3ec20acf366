"""g44v: stones 2000 relax on, seed 1, five growths in one warm process (after one of 300): min and median CPU s. Run on each tree in turn: PYTHONPATH=src python benchmarks/g44v_inproc.py this; PYTHONPATH=<main>/src python benchmarks/g44v_inproc.py main"""
import sys
import time

from strew.grow import analyze, grow
from strew.grow._exemplars import stone_exemplar

ref = analyze(stone_exemplar()); grow(ref, count=300, rng=1, relax=True)
ts = []
for _ in range(5):
    c = time.process_time(); grow(ref, count=2000, rng=1, relax=True); ts.append(time.process_time() - c)
print(sys.argv[1], f"min {min(ts):.3f} median {sorted(ts)[2]:.3f}")
