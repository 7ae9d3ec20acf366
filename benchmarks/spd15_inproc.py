"""In-process interleaved A/B of the flow network's measures made once
(:mod:`strew.grow._flow_memo`) against measuring each time (the base's way: the memo
replaced by a pass-through), on the ``hexflow`` case of ``benchmarks/grow.py
--against`` (relaxation on): CPU seconds per growth, alternating which goes first.

Run: ``PYTHONPATH=src python benchmarks/spd15_inproc.py 8`` (rounds).
"""

from __future__ import annotations

import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))

from spd15_sample import case_kwargs

from strew.grow import _flow_net, analyze, grow
from strew.grow._exemplars import hex_exemplar


def passthrough(g, name, arrays, compute):
    return compute()


def main() -> None:
    rounds = int(sys.argv[1]) if len(sys.argv) > 1 else 8
    ref = analyze(hex_exemplar())
    kw = case_kwargs("hexflow", ref)
    memo = _flow_net.memo
    grow(ref, rng=1, relax=True, **kw)
    cpu: dict[str, list[float]] = {"this": [], "base": []}
    for r in range(rounds):
        for k in ("this", "base") if r % 2 == 0 else ("base", "this"):
            _flow_net.memo = memo if k == "this" else passthrough
            c = time.process_time()
            grow(ref, rng=1, relax=True, **kw)
            cpu[k].append(time.process_time() - c)
    _flow_net.memo = memo
    ratios = [a / b for a, b in zip(cpu["this"], cpu["base"])]
    print(f"this median {statistics.median(cpu['this']):.3f} s, base {statistics.median(cpu['base']):.3f} s, "
          f"ratio of medians {statistics.median(cpu['this']) / statistics.median(cpu['base']):.3f}, "
          f"median ratio {statistics.median(ratios):.3f}, this faster in {sum(x < 1 for x in ratios)}/{rounds}")


if __name__ == "__main__":
    main()
