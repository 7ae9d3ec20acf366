"""g46v: stones N relax on, seed 1, REPS growths in one warm process (after one of 300): min and median CPU s.
Run on each tree in turn: PYTHONPATH=src python benchmarks/g46v_inproc.py LABEL 2000 3"""
import sys
import time

from strew.grow import analyze, grow
from strew.grow._exemplars import stone_exemplar

n = int(sys.argv[2]); reps = int(sys.argv[3])
ref = analyze(stone_exemplar()); grow(ref, count=300, rng=1, relax=True)
ts = []
for _ in range(reps):
    c = time.process_time(); grow(ref, count=n, rng=1, relax=True); ts.append(time.process_time() - c)
print(sys.argv[1], n, f"min {min(ts):.4f} med {sorted(ts)[len(ts)//2]:.4f}", flush=True)
