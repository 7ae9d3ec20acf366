"""Run a benchmark script with ``strew.synth._thin._match_nn`` logged (helper s72m).

Before each row's line the script prints, per call of the choice: ``match_nn n_k chosen cand
acted rounds old_bound`` (``rounds``: scoring rounds, one per removal where a round took one;
``old_bound``: whether main's ``MATCH_NN_WORK = 2e7`` would have made it take nearest first).

    PYTHONPATH=src:benchmarks:tests python benchmarks/s72m_logged.py benchmarks/synth_variants.py ARGS...
"""
import runpy
import sys

import strew.synth._thin as T

orig = T._match_nn


def logged(state, vis, of_k, ins, cand, chosen, k):
    r0 = T.MATCH_NN_COUNT[0]
    r = orig(state, vis, of_k, ins, cand, chosen, k)
    nk = int(of_k.sum())
    print(f"    match_nn n_k {nk} chosen {len(chosen)} cand {len(cand)} acted {r is not chosen} "
          f"rounds {T.MATCH_NN_COUNT[0] - r0} old_bound {len(chosen) * len(cand) * nk > 2e7}", flush=True)
    return r


T._match_nn = logged
sys.argv = sys.argv[1:]
runpy.run_path(sys.argv[0], run_name="__main__")
