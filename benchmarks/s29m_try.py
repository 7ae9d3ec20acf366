"""Helper s29m (issue 13 point 1, three_sizes h6): syn13z_rows.py with synth's density target
(``_displace._inner_density``) taken over the exemplar's whole frame (MODE=whole), or per kind the larger
of inner and whole (MODE=max; MODE=mid: middle size classes only), to test whether the inner frame's low medium count holds the medium back.

    MODE=whole PYTHONPATH=src:benchmarks python benchmarks/s29m_try.py three_sizes:6:22:1,2:large:medium
"""
import os
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np

import strew.synth._displace as D

_orig = D._inner_density
MODE = os.environ.get("MODE", "whole")


def patched(prep, margin):
    a = _orig(prep, margin)
    b = _orig(prep, 0.0)
    if MODE == "whole":
        return b
    if MODE == "mid":
        sel = prep.selected_elements & ~prep.void
        out = a.copy()
        for s_ in np.unique(prep.source[sel]):
            m = sel & (prep.source == s_)
            lo, hi = prep.size_class[m].min(), prep.size_class[m].max()
            mid = np.unique(prep.skind[m & (prep.size_class > lo) & (prep.size_class < hi)])
            out[mid] = np.fmax(a[mid], b[mid])
        return out
    return np.fmax(a, b)


D._inner_density = patched
sys.argv = sys.argv[:1] + sys.argv[1:]
import runpy

runpy.run_path(os.path.join(os.path.dirname(__file__), "syn13z_rows.py"), run_name="__main__")
