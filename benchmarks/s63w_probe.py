"""Helper s63w: which exemplars fill_swapped's new target touches: synth's frame test
(``Prepared.frame_window``), the metric's wall reach (for comparison only), and whether
``_swap._swap_density`` differs from ``_displace._inner_density`` for a kind fill_swapped acts on.

    PYTHONPATH=src:benchmarks python benchmarks/s63w_probe.py harder two_sizes 25-34
    PYTHONPATH=src:benchmarks python benchmarks/s63w_probe.py varied two_sizes,stones,three_sizes 25-34
"""
import sys
import numpy as np
sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from strew._fidelity import _wall_reach
from strew.synth._palette import Palette
from strew.synth._prepare import prepare
from strew.synth._displace import _inner_density
from strew.synth._swap import _swap_density
from strew.synth._shapes import shape_test_needed

which, classes, seeds = sys.argv[1], sys.argv[2].split(","), _variants.ints(sys.argv[3])
if which == "harder":
    from grow_variants import _harder_suite
    from synth_variants import _harder
    mk, H = _harder_suite(), _harder()
    rows = [(c, f"h{i}s{v}", mk.make_exemplar(c, rng=v, **p)) for c in classes for v in seeds for i, p in enumerate(H[c])]
else:
    from _runner import fidelity_suite
    _variants.VARIED_SEEDS = tuple(seeds)  # (--varied-variants; --variants the same seeds)
    mk = fidelity_suite()
    rows = [(c, lab, mk.make_exemplar(c, rng=v, **kw)) for c in classes for lab, _, v, kw in _variants.cases(c, seeds, True)]
for c, lab, ex in rows:
    pal = Palette({"ex": ex})
    prep = prepare(pal.select("ex"))
    names = list(ex.kinds)
    rad = np.array([ex.shapes[names[k]].radius for k in ex.kind]) * np.asarray(ex.scale, float)
    wr = _wall_reach(ex.xy, ex.kind, rad, ex.region.geometry) if ex.region is not None else None
    m = 2.0 * float(prep.rc.max())
    a, b = _inner_density(prep, m), _swap_density(prep, m, 0)
    ids = np.flatnonzero(~prep.void)
    kinds, cnt = np.unique(prep.skind[ids], return_counts=True)
    one = len(np.unique(prep.size_class[ids])) == 1
    acts = one and (cnt >= 10).sum() >= 2 and not shape_test_needed(prep)
    diff = not np.allclose(a[kinds], b[kinds], equal_nan=True)
    print(f"{c}:{lab} window={bool(prep.frame_window[0])} wall_reach={wr if wr is None else round(wr, 2)} "
          f"swap_can_act={acts} target_differs={diff} {'TOUCHED' if acts and diff else ''} "
          f"inner={np.round(a[kinds] * 1e4, 2).tolist()} swap={np.round(b[kinds] * 1e4, 2).tolist()} counts={cnt.tolist()}", flush=True)
