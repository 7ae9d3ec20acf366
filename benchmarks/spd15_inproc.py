"""In-process interleaved A/B of spd15's shortcuts against the base's way, CPU seconds
per growth, alternating which goes first:

- ``memo``: the flow network's measures made once (:mod:`strew.grow._flow_memo`)
  against measuring each time (the memo replaced by a pass-through), on the ``hexflow``
  case of ``benchmarks/grow.py --against`` (relaxation on);
- ``near``: ``GrowIndex.near`` through :func:`strew.grow._index_kernels.near_one`
  against 00c3e6f's ``near`` (the batched ``hash_near`` with one-element query arrays),
  on ``hexflow`` or ``stones`` (2,000 elements, relaxation on).

Run: ``PYTHONPATH=src python benchmarks/spd15_inproc.py memo hexflow 8`` (what, case,
rounds).
"""

from __future__ import annotations

import statistics
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))

from spd15_sample import case_kwargs

from strew._kernels.grid import hash_near
from strew.grow import _flow_net, _index, analyze, grow
from strew.grow._exemplars import hex_exemplar, stone_exemplar


def passthrough(g, name, arrays, compute):
    return compute()


def base_near(self, x, y, r, states, limit=-1):
    """00c3e6f's GrowIndex.near: hash_near with one-element query arrays."""
    if getattr(self, "qx", None) is None or len(self.out_q) != len(self.out):
        self.qx, self.qy, self.qr = np.zeros(1), np.zeros(1), np.zeros(1)
        self.out_q = np.zeros(len(self.out), dtype=np.int64)
    pts = self.points
    self.qx[0] = x
    self.qy[0] = y
    self.qr[0] = r
    k = hash_near(self.qx, self.qy, self.qr, states, limit if limit > 0 else len(self.out), self.cell,
                  pts.head, pts.ent, pts.cur, pts.ext, self.pos, self.state, self.out_q, self.out)
    return self.out[:k].tolist()


def main() -> None:
    what = sys.argv[1] if len(sys.argv) > 1 else "memo"
    case = sys.argv[2] if len(sys.argv) > 2 else "hexflow"
    rounds = int(sys.argv[3]) if len(sys.argv) > 3 else 8
    ref = analyze({"hexflow": hex_exemplar, "stones": stone_exemplar}[case]())
    kw = case_kwargs(case, ref)
    memo = _flow_net.memo
    near = _index.GrowIndex.near

    def use(k):
        if what == "memo":
            _flow_net.memo = memo if k == "this" else passthrough
        else:
            _index.GrowIndex.near = near if k == "this" else base_near

    for k in ("this", "base"):
        use(k)
        grow(ref, rng=1, relax=True, **kw)
    cpu: dict[str, list[float]] = {"this": [], "base": []}
    for r in range(rounds):
        for k in ("this", "base") if r % 2 == 0 else ("base", "this"):
            use(k)
            c = time.process_time()
            grow(ref, rng=1, relax=True, **kw)
            cpu[k].append(time.process_time() - c)
    use("this")
    ratios = [a / b for a, b in zip(cpu["this"], cpu["base"])]
    print(f"{what} {case}: this median {statistics.median(cpu['this']):.3f} s, base {statistics.median(cpu['base']):.3f} s, "
          f"ratio of medians {statistics.median(cpu['this']) / statistics.median(cpu['base']):.3f}, "
          f"median ratio {statistics.median(ratios):.3f}, this faster in {sum(x < 1 for x in ratios)}/{rounds}")


if __name__ == "__main__":
    main()
