"""``strew ornament``: grow adaptive clip art (Wong et al. 1998) in a panel.

Options, checks and ``--help`` come from :data:`strew.ornament.SPEC`.
"""

from __future__ import annotations

from ..ornament import SPEC
from ._spec import Hooks, method_command


def _summary(run, arr) -> str:
    from ..metrics import visible_count

    info = arr.meta["ornament"]
    # the count is the drawn one, as strew info and the gallery give it (issue 23)
    return (f"{info['pattern']}: {visible_count(arr)} elements drawn from {info['elements']} grown in {run.seconds:.2f} s "
            f"({info['successes']} placed, {info['failures']} excluded circles), style {info['style']}")


command = method_command(SPEC, Hooks(
    summary=_summary,
    description="Grow ornament from PATTERN (dots, flowers, spirals, hierarchy, vase, willow) or a Python RULE_FILE.\n\n"
    "Growth repeatedly fills the largest empty circle next to the ornament with whatever the pattern's rules grow "
    "there, until no empty circle of the minimum radius remains.\n\n"
    "A RULE_FILE is a Python program: it runs with your rights (it can read, write and delete your files), so use "
    "only rule files you trust.",
))
