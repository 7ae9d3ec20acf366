"""s33h (needs benchmarks/results/s33h_rejected_move_large_to_stranded.patch applied): the three small-next-to-large figures of the suite's three sizes (the assertions of
test_synth_50x.py::test_three_sizes_50x_fewer_small_stones_far_from_large (< 0.076),
test_synth_syn13v_shell.py::test_small_stones_snug_against_large_ones (>= 0.93) and
test_synth_syn13w_farmix.py::test_far_small_stones_traded_for_medium_ones (<= 1.2)), and how
many large stones ``_shell.fill_large_beside_far_small`` moved.

``PYTHONPATH=src:tests python benchmarks/s33h_figures.py``; S33H_OFF=1 turns the move off.
"""
import os
import sys

import numpy as np
from strew_testing import fidelity_suite, synth_at_50x

from strew import Region
from strew.synth import _shell, synthesize

sys.path.insert(0, "tests/synth")
from test_synth_50x import _far_share  # noqa: E402
from test_synth_syn13v_shell import _shell_density  # noqa: E402
from test_synth_syn13w_farmix import _far_excess  # noqa: E402

orig = _shell.fill_large_beside_far_small
moved = []


def wrapped(state, room=None, since=0):
    if os.environ.get("S33H_OFF"):
        return 0
    c0 = int(getattr(state, "ceded_top", 0))
    n = orig(state, room, since)
    moved.append(c0 - int(getattr(state, "ceded_top", 0)))
    return n


_shell.fill_large_beside_far_small = wrapped
shares = []
for seed in (2, 8):
    moved.clear()
    ex, out, region, _ = synth_at_50x("three_sizes", seed)
    shares.append(_far_share(ex, out, region))
    print(f"50x seed {seed}: share {shares[-1]:.4f} moved {sum(moved)}", flush=True)
print(f"50x mean {np.mean(shares):.4f} (< 0.076)")
ex = fidelity_suite().make_exemplar("three_sizes")
x0, y0, x1, y1 = ex.region.bounds
margin = 2.0 * float(np.max(ex.radii))
moved.clear()
out = synthesize(ex, Region.rectangle(2.0 * (x1 - x0), 2.0 * (y1 - y0)), rng=1, measure=False)
got = _shell_density(out, 14.0, 16.0, margin) / _shell_density(ex, 14.0, 16.0, margin)
print(f"2x seed 1: shell snug {got:.3f} (>= 0.93), farmix {_far_excess(ex, out):.3f} (<= 1.2), moved {sum(moved)}")
