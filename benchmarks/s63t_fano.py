"""Helper s63t: ``_grow._top_spread`` (the dispersion of an exemplar's largest class in windows
of its inner frame, against independent points) for three sizes rows, and whether
``_grow._own_setup`` keeps each (only kept exemplars are evaluated by ``_top_ahead``).

    PYTHONPATH=src:benchmarks python benchmarks/s63t_fano.py v25,p4s27,p4s29,p0s32,h6s29
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import numpy as np

from s60t_ahead_probe import exemplar

import strew.synth._grow as G
from strew.synth._api import new_state

for label in sys.argv[1].split(","):
    prep = new_state(exemplar(label)).prep
    top, _a, cover, rate = G._own_setup(prep)
    f = G._top_spread(prep)
    print(label, "kept" if top.any() else "not kept", np.round(f[cover > 0], 3), flush=True)
