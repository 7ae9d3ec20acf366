"""``benchmarks/orn19m_willow.py make`` with vas19x's grid-point choice counted (issue 19.4):
prints how many vine calls chose another grid point than d67a7c3's rule would (0: the world
is d67a7c3's; vas19x_skips.old_free). Arguments as orn19m_willow.py's.

``PYTHONPATH=src python benchmarks/vas19x_make.py make --pattern vase --tag TAG --tiles T --overlaps [--seed S] [--untiled]``
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))


def main() -> None:
    import orn19m_willow
    from vas19x_skips import old_free

    from strew.ornament.patterns import vase

    new_free = vase._free_grid_point
    st = {"calls": 0, "differ": 0}

    def counted(ctx, near, start=None):
        a, b = new_free(ctx, near, start), old_free(ctx, near, start)
        st["calls"] += 1
        st["differ"] += (a is None) != (b is None) or (a is not None and a[1] != b[1])
        return a

    vase._free_grid_point = counted
    orn19m_willow.main()
    print(f"vas19x: grid-point calls {st['calls']}, choice differs from d67a7c3's {st['differ']}", flush=True)


if __name__ == "__main__":
    main()
