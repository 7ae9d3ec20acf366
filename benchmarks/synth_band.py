"""Issue 13: the kind shares of the fidelity suite's several-size exemplars in their
whole frame, in their interior, and in synth's output.

The suite's generator (``examples/fidelity/make.py``) throws each class inside the frame
inset by its own largest radius, as an artist keeps every stone wholly inside the frame:
a band along the frame, about 1.1 times the largest radius wide, holds no large element.
Region growing copies interior neighbourhoods only (k-coherence candidates are elements
whose neighbourhood lies inside the exemplar's domain, §5.1), so a stationary output
takes the interior's shares, while ``strew.metrics.fidelity`` takes the kind fractions
(and the density factor share x elements per area) over the whole frame. Printed per
case: the largest kind's share in the whole frame, in the interior (centres at least the
band's width from the frame) and in the inner part of synth's output (region ``--scale``
times the frame's side; 10 % margin), and each as a ratio to the whole frame's; then the
exemplar's and the output's share as ``strew.metrics.fidelity`` counts them (``judge_ex``,
``judge_out``: minus sampling beyond the frame's wall reach, ``info["exemplar_wall_reach"]``
printed as ``reach``).

    python benchmarks/synth_band.py [--only three_sizes,two_sizes] [--variants 0-3] [--seeds 1] [--scale 3.5]
"""

from __future__ import annotations

from typing import Any

import numpy as np
from _runner import Bench, fidelity_suite, parse_args

from strew import Region
from strew.metrics import fidelity
from strew.synth import synthesize


def _ints(text: str) -> list[int]:
    out: list[int] = []
    for part in text.split(","):
        a, _, b = part.partition("-")
        out.extend(range(int(a), int(b or a) + 1))
    return out


def shares(arr: Any, box: tuple[float, float, float, float], kinds: int) -> np.ndarray:
    """Kind shares of the elements whose centres lie in ``box``."""
    x0, y0, x1, y1 = box
    xy = arr.xy
    inside = (xy[:, 0] >= x0) & (xy[:, 0] <= x1) & (xy[:, 1] >= y0) & (xy[:, 1] <= y1)
    counts = np.bincount(np.asarray(arr.kind)[inside], minlength=kinds).astype(float)
    return counts / max(counts.sum(), 1.0)


def main() -> None:
    def extra(p: Any) -> None:
        p.add_argument("--only", default="three_sizes,two_sizes", help="suite class names, comma-separated")
        p.add_argument("--variants", default="0-3", help="exemplar seeds (0: the default exemplar)")
        p.add_argument("--seeds", default="1", help="synth seeds")
        p.add_argument("--scale", type=float, default=3.5, help="region side / exemplar frame side")

    args = parse_args(__doc__.splitlines()[0], extra)
    mk = fidelity_suite()
    bench = Bench("synth_band", "largest kind's share: exemplar frame, exemplar interior, synth output", baseline="the exemplar's whole frame", json_path=args.json)
    for name in args.only.split(","):
        for v in _ints(args.variants):
            ex = mk.make_exemplar(name, rng=v or None)
            K = len(ex.kinds)
            radius = np.array([ex.shapes[k].radius for k in ex.kinds])
            big = int(np.argmax(radius))
            band = 1.1 * float(radius.max())
            x0, y0, x1, y1 = ex.region.bounds
            whole = shares(ex, (x0, y0, x1, y1), K)[big]
            inner = shares(ex, (x0 + band, y0 + band, x1 - band, y1 - band), K)[big]
            w, h = args.scale * (x1 - x0), args.scale * (y1 - y0)
            for seed in _ints(args.seeds):
                out = synthesize(ex, Region.rectangle(w, h), rng=seed, measure=False)
                got = shares(out, (0.1 * w, 0.1 * h, 0.9 * w, 0.9 * h), K)[big]
                rep = fidelity(ex, out, eq5=False, local=False)
                m = rep.metrics[f"fraction[{ex.kinds[big]}]"]
                bench.row(f"{name} v{v}", seed=seed, kind=ex.kinds[big], band=round(band, 1), frame=round(float(whole), 3),
                          interior=round(float(inner), 3), output=round(float(got), 3),
                          interior_ratio=round(float(inner / whole), 2), output_ratio=round(float(got / whole), 2),
                          reach=round(float(rep.info["exemplar_wall_reach"]), 1), judge_ex=round(float(m.exemplar), 3), judge_out=round(float(m.result), 3))
    bench.finish()


if __name__ == "__main__":
    main()
