"""Helper s62d: counterfactuals (diagnosis only, not a change) on --harder synth rows: MODE=noswap
(``_swap.SWAP = False``) or MODE=whole (``_displace._inner_density`` takes the whole frame's count for a kind of
one size class whose inner frame holds fewer than its share by more than one binomial standard error), MODE=window
(where the metric's test finds the exemplar's frame a window, wall reach 0, every kind's target is the whole frame's
count), MODE=swapwindow (the same, for fill_swapped only).

    MODE=noswap PYTHONPATH=src:benchmarks python benchmarks/s62d_counter.py two_sizes:h8s36,two_sizes:h9s36 1-6
"""
import os
import sys
import numpy as np
import shapely
sys.path.insert(0, __file__.rsplit("/", 1)[0])
import strew.synth._swap as SW
import strew.synth._displace as DP
mode = os.environ.get("MODE", "noswap")
if mode == "noswap":
    SW.SWAP = False
elif mode == "whole":
    _orig = DP._inner_density

    def whole(prep, margin):
        out = _orig(prep, margin)
        for s, dom in enumerate(prep.domains):
            if not prep.selected[s]:
                continue
            inner = dom.buffer(-margin)
            mine = prep.selected_elements & ~prep.void & (prep.source == s)
            ids = np.flatnonzero(mine)
            ids = ids[shapely.contains_xy(inner, prep.pos[ids, 0], prep.pos[ids, 1])]
            S = len(out)
            n_all = np.bincount(prep.skind[mine], minlength=S).astype(float)
            n_in = np.bincount(prep.skind[ids], minlength=S).astype(float)
            p = inner.area / dom.area
            short = (n_all > 0) & (n_in < p * n_all - 1.0 * np.sqrt(n_all * p * (1 - p)))
            out[short] = np.maximum(out[short], n_all[short] / dom.area)
        return out

    DP._inner_density = whole
elif mode in ("window", "swapwindow"):
    # where the metric's own test finds the exemplar's frame a window, not a wall (_fidelity._wall_reach = 0),
    # every kind's target is its whole frame's count (the reach is set per exemplar by the rows script: REACH)
    _orig = DP._inner_density
    REACH = {"v": None}

    def window(prep, margin):
        out = _orig(prep, margin)
        if REACH["v"] != 0.0 or (mode == "swapwindow" and not ACTIVE[0]):
            return out
        for s, dom in enumerate(prep.domains):
            if not prep.selected[s]:
                continue
            mine = prep.selected_elements & ~prep.void & (prep.source == s)
            S = len(out)
            n_all = np.bincount(prep.skind[mine], minlength=S).astype(float)
            kinds = np.unique(prep.skind[mine])
            out[kinds] = n_all[kinds] / dom.area
        return out

    DP._inner_density = window
    ACTIVE = [False]
    if mode == "swapwindow":  # only fill_swapped's target (it reads _displace._inner_density at call time)
        _fs = SW.fill_swapped

        def fs(state):
            ACTIVE[0] = True
            try:
                return _fs(state)
            finally:
                ACTIVE[0] = False

        SW.fill_swapped = fs
    import strew._fidelity as F
    _wr = F._wall_reach
print("MODE", mode, flush=True)
sys.argv = [sys.argv[0]] + sys.argv[1:]
exec(open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "s62d_rows.py")).read())
