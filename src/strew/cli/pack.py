"""``strew pack``: dense non-periodic aggregates of arbitrary shapes (Sakurai & Miyata).

Options, checks and ``--help`` come from :data:`strew.pack.SPEC`.
"""

from __future__ import annotations

from ..pack._pack import SPEC
from ._spec import Hooks, method_command


def _summary(run, arr) -> str:
    from .. import metrics
    from ._common import visible_counts

    n, counts = visible_counts(arr)
    info = arr.meta["pack"]
    return (f"packed {n} elements ({counts}), coverage {100 * metrics.coverage(arr):.1f}%, {run.seconds:.2f} s, "
            f"{info['algorithm']}, stopped after {info['stopped']}")


command = method_command(SPEC, Hooks(
    summary=_summary,
    description="Pack copies of SHAPE... (SVG or JSON files) densely into a region.\n\n"
    "A file holding several shapes gives several kinds, in equal proportions unless --weight is given "
    "(fill-gap keeps them within 0.05; naive cycles or draws by weight). Elements lie wholly inside the "
    "region and never overlap, nor overlap the elements of --around. With --periodic the region is a "
    "repeat tile: elements may cross its edges and wrap in at the opposite side, and the tile's copies "
    "laid side by side never overlap.",
))
