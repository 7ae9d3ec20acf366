"""g46v: CPU s spent in _Place._nudge during stones 2000 relax on (min over REPS growths).
Run: PYTHONPATH=src python benchmarks/g46v_nudge_time.py LABEL 3"""
import sys
import time

from strew.grow import analyze, grow
from strew.grow._exemplars import stone_exemplar
from strew.grow._place import _Place

ref = analyze(stone_exemplar()); grow(ref, count=300, rng=1, relax=True)
orig = _Place._nudge
acc = [0.0, 0]
def wrapped(self, *a):
    c = time.process_time(); r = orig(self, *a); acc[0] += time.process_time() - c; acc[1] += 1; return r
_Place._nudge = wrapped
best = 1e9; tot = []
for _ in range(int(sys.argv[2])):
    acc[0] = 0.0; acc[1] = 0
    c = time.process_time(); grow(ref, count=2000, rng=1, relax=True); t = time.process_time() - c
    best = min(best, acc[0]); tot.append(t)
print(sys.argv[1], f"nudge calls {acc[1]} nudge cpu min {best:.4f} growth min {min(tot):.4f}", flush=True)
