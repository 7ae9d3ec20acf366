"""Helper s34v: cProfile (CPU time) of synth on a ``strew.synth._exemplars`` exemplar at
``benchmarks/synth_speed.py``'s quick size, over seeds 1-5 (numba compiled first), of
``new_state`` (``new``) or ``fill`` (``fill``), sorted by ``tottime`` or ``cumulative``.

    PYTHONPATH=src python benchmarks/s34v_profile.py grid fill tottime 30
"""
import cProfile, pstats, sys, time
from strew import Region
from strew.synth import fill, new_state
from strew.synth._exemplars import EXEMPLARS
QUICK = {"grid": (400, 400), "stripes": (320, 320)}
case = sys.argv[1]; what = sys.argv[2]
ex = EXEMPLARS[case]()
w, h = QUICK[case]
fill(new_state(ex, Region.rectangle(60, 60) if case == "grid" else Region.rectangle(w, h), rng=0))
pr = cProfile.Profile(time.process_time)
t = time.process_time(); ns = 0
for s in range(1, 6):
    if what == "new": pr.enable()
    st = new_state(ex, Region.rectangle(w, h), rng=s)
    if what == "new": pr.disable()
    if what == "fill": pr.enable()
    fill(st)
    if what == "fill": pr.disable()
    ns += st.n
print(f"{case} n={ns} cpu_s={time.process_time() - t:.2f} el/s={ns/(time.process_time() - t):.0f}")
pstats.Stats(pr).sort_stats(sys.argv[3]).print_stats(int(sys.argv[4]))
