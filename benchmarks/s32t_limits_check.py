"""Helper s32t: ``_grow.shape_limits`` (compiled exemplar count, zone share by shapely
only at the domain's edge) against s31t's all-shapely computation, on many exemplars.

    PYTHONPATH=src python benchmarks/s32t_limits_check.py [--seeds 1-24]

For sticks, scales and rows_noisy (default parameters at every variant seed, and every
``VARIED`` / ``EDGE`` set of ``benchmarks/_variants.py`` at every seed) the limits and
reaches must be equal element by element; prints the mismatch count and the time of both
(one call each, ms; numba compiled before).
"""
import argparse
import importlib.util
import sys
import time
from pathlib import Path

import numpy as np
import shapely

sys.path.insert(0, str(Path(__file__).resolve().parent))
import _variants  # noqa: E402

from strew import Region  # noqa: E402
from strew.synth import _grow, new_state  # noqa: E402
from strew.synth._shapes import SHRUNK, element_geometries  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
spec = importlib.util.spec_from_file_location("mk", ROOT / "examples/fidelity/make.py")
mk = importlib.util.module_from_spec(spec)
spec.loader.exec_module(mk)


def shapely_limits(prep):
    """s31t's shape_limits body (STRtree dwithin count, buffer zone share for all)."""
    out = np.full(len(prep.kind), -1, np.int64)
    reach = np.asarray(prep.r, float).copy()
    if prep.overlap_free:
        for s, dom in enumerate(prep.domains):
            ids = np.flatnonzero(prep.source == s)
            if len(ids) < 3 or prep.void[ids].any() or len(np.unique(prep.kind[ids])) != 1:
                continue
            if not np.all(prep.rc[ids] < SHRUNK * prep.r[ids]):
                continue
            g = element_geometries(prep, ids, prep.pos[ids])
            d = reach[ids]
            tree = shapely.STRtree(g)
            a, b = tree.query(g, predicate="dwithin", distance=float(d.max()))
            keep = a != b
            a, b = a[keep], b[keep]
            close = shapely.dwithin(g[a], g[b], d[a])
            cnt = np.bincount(a[close], minlength=len(ids))
            zone = shapely.buffer(g, d, quad_segs=8)
            share = shapely.area(shapely.intersection(zone, dom)) / shapely.area(zone)
            ok = share >= 0.5
            out[ids[ok]] = np.round(cnt[ok] / share[ok]).astype(np.int64)
    return out, reach


p = argparse.ArgumentParser()
p.add_argument("--seeds", default="1-24")
a = p.parse_args()
seeds = _variants.ints(a.seeds)
_variants.VARIED_SEEDS = tuple(seeds)
bad = tested = limited = 0
t_old = t_new = 0.0
first = True
for name in ("sticks", "scales", "rows_noisy"):
    for label, _tag, v, kw in [("default", "default", 0, {})] + _variants.cases(name, seeds, True):
        ex = mk.make_exemplar(name, rng=v, **kw) if label != "default" else mk.make_exemplar(name)
        prep = new_state(ex, Region.rectangle(50, 50), rng=1).prep
        if first:
            _grow.shape_limits(prep)  # compile
            prep._shape_limits = None
            first = False
        t = time.perf_counter()
        old = shapely_limits(prep)
        t_old += time.perf_counter() - t
        t = time.perf_counter()
        new = _grow.shape_limits(prep)
        t_new += time.perf_counter() - t
        tested += 1
        limited += int((new[0] >= 0).sum())
        if not (np.array_equal(old[0], new[0]) and np.array_equal(old[1], new[1])):
            bad += 1
            print(f"MISMATCH {name} {label}: {np.flatnonzero(old[0] != new[0])[:10]}", flush=True)
print(f"exemplars {tested}, limited elements {limited}, mismatching exemplars {bad}; "
      f"time shapely {1e3 * t_old:.0f} ms, compiled {1e3 * t_new:.0f} ms ({1e3 * t_old / tested:.1f} -> {1e3 * t_new / tested:.1f} ms each)")
