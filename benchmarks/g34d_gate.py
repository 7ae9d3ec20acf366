"""Helper g34d: which ``--varied`` exemplars turn on the keep-nearest-distance rule (strew.grow._spacing).

    PYTHONPATH=src python benchmarks/g34d_gate.py VARIANT_SEEDS [CLASS,...]

Prints, per class and label, the exemplars (variant seed) where
``reference_nn(ex, "fixed", None)`` is not None, with :func:`free_share` of every one-kind
exemplar. Only those rows can change: elsewhere growth is unchanged (no draw is added).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _variants  # noqa: E402
from _runner import fidelity_suite  # noqa: E402
from fresh17_rows import exemplar  # noqa: E402

from strew.grow._spacing import free_share, reference_nn  # noqa: E402


def main():
    seeds = _variants.ints(sys.argv[1])
    mk = fidelity_suite()
    classes = sys.argv[2].split(",") if len(sys.argv) > 2 else list(_variants.VARIED)
    on = []
    for cls in classes:
        sets = _variants.VARIED.get(cls, []) + _variants.EDGE.get(cls, [])
        for lab in ["v"] + [f"p{i}s" for i in range(len(sets))]:
            row = []
            for s in seeds:
                ex = exemplar(mk, cls, f"{lab}{s}")
                if len(ex.kinds) != 1:
                    continue
                row.append(f"{free_share(ex):.2f}")
                if reference_nn(ex, "fixed", None) is not None:
                    on.append(f"{cls}:{lab}{s}")
            if row:
                print(f"  {cls:12s} {lab:4s} free_share {' '.join(row)}", flush=True)
    print("rule on:", " ".join(on))


if __name__ == "__main__":
    main()
