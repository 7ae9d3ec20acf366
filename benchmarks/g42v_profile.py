"""Where ``strew.grow`` spends its CPU time with the relaxation on (issue 14 point 5).

Two views, stdlib only (no profiler package): a sampling profile (``SIGPROF`` every
0.5 ms of CPU; each sample counts its innermost Python line as self time and every
function on the stack once as inclusive time) and CPU seconds per ``_Grower`` method
(``--methods``: ``time.process_time`` around each call, inclusive; the wrapper costs
about a microsecond a call). A sample taken while compiled code (numba, GEOS, numpy)
runs is seen at the next Python line checked, often the next call's first line: read
the self times of lines that only call compiled code as belonging to the call before.

Run: ``PYTHONPATH=src python benchmarks/g42v_profile.py stones 4`` (``stones``: 2,000
stones; ``hexflow``: the hexagonal lattice in flow mode, 30 x 20 spacings, as
``benchmarks/grow.py --against``), or ``... stones 3 --methods relax_window,place,choose``.
"""

from __future__ import annotations

import argparse
import collections
import functools
import signal
import time

import numpy as np


def _case(name: str):
    from strew import Region
    from strew.grow import analyze
    from strew.grow._exemplars import hex_exemplar, stone_exemplar

    if name == "stones":
        return analyze(stone_exemplar()), dict(count=2000)
    ref = analyze(hex_exemplar())
    w = 30 * ref.mean_edge

    def field(p):
        a = np.radians(90.0) * np.clip(np.asarray(p)[:, 0] / w, 0, 1)
        return np.c_[np.cos(a), np.sin(a)]

    return ref, dict(region=Region.rectangle(w, 20 * ref.mean_edge), mode="flow", flow=field)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("case", choices=("stones", "hexflow"))
    ap.add_argument("runs", type=int, nargs="?", default=3, help="growths sampled (seeds 1..runs)")
    ap.add_argument("--methods", default=None, help="comma-separated _Grower methods to time instead of sampling")
    ap.add_argument("--top", type=int, default=40)
    a = ap.parse_args()
    import strew.grow._growth as G
    from strew.grow import grow

    ref, kw = _case(a.case)
    grow(ref, rng=1, relax=True, **kw)  # kernels compiled or loaded outside the figures
    acc: dict[str, float] = collections.defaultdict(float)
    calls: dict[str, int] = collections.Counter()
    if a.methods:
        for name in a.methods.split(","):
            f = getattr(G._Grower, name)

            def timed(*args, _f=f, _n=name, **kws):
                t = time.process_time()
                try:
                    return _f(*args, **kws)
                finally:
                    acc[_n] += time.process_time() - t
                    calls[_n] += 1

            setattr(G._Grower, name, functools.wraps(f)(timed))
    selfc: collections.Counter = collections.Counter()
    incl: collections.Counter = collections.Counter()
    lines: collections.Counter = collections.Counter()
    n = [0]

    def sample(_sig, fr):
        n[0] += 1
        seen = set()
        top = True
        while fr is not None:
            key = f"{fr.f_code.co_filename.rsplit('/', 1)[-1]}:{fr.f_code.co_name}"
            if top:
                selfc[key] += 1
                lines[f"{key}:{fr.f_lineno}"] += 1
                top = False
            if key not in seen:
                incl[key] += 1
                seen.add(key)
            fr = fr.f_back

    if not a.methods:
        signal.signal(signal.SIGPROF, sample)
        signal.setitimer(signal.ITIMER_PROF, 0.0005, 0.0005)
    cpu = 0.0
    els = 0
    for r in range(a.runs):
        t = time.process_time()
        out = grow(ref, rng=r + 1, relax=True, **kw)
        cpu += time.process_time() - t
        els += len(out)
    signal.setitimer(signal.ITIMER_PROF, 0, 0)
    print(f"{a.case}: {els} elements in {cpu:.3f} CPU s ({els / cpu:,.0f} el/CPU-s; sampled runs are slower)")
    if a.methods:
        for k, v in sorted(acc.items(), key=lambda kv: -kv[1]):
            print(f"{k:28s} {v:7.3f} s {100 * v / cpu:5.1f} %  {calls[k]} calls")
        return
    m = max(n[0], 1)
    print(f"{n[0]} samples")
    for title, c in (("inclusive", incl), ("self", selfc), ("lines (self)", lines)):
        print(f"== {title}")
        for k, v in c.most_common(a.top):
            print(f"{100 * v / m:5.1f} %  {k}")


if __name__ == "__main__":
    main()
