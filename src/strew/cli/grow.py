"""``strew grow``: example-based growth from one seed (Ijiri et al. 2008).

Options, checks and ``--help`` come from :data:`strew.grow.SPEC`; ``--exemplar-out``
is the CLI's own.
"""

from __future__ import annotations

import click

from ..grow import SPEC
from ._spec import Hooks, method_command


def _check(run) -> None:
    path = run.options.get("exemplar_out")
    if path is not None:
        from .._errors import InputError
        from ..io import check_output_path

        if check_output_path(path) != ".json":
            raise InputError(f"--exemplar-out {path!r}: must be a .json file (it carries the edge list)")


def _prepare(run) -> None:
    if "flow" in run.values and "mode" not in run.values:  # --flow implies --mode flow
        run.values["mode"] = "flow"


def _finish(run, arr) -> None:
    path = run.options.get("exemplar_out")
    if path is None:
        return
    from ..grow import analyze
    from ..io import save

    ex = run.input
    ref = analyze(ex, flips=run.values.get("flips", ()))
    conn = {"count": len(ex), **ref.to_dict(), "interior": ref.interior.tolist()}
    save(ex.replace(extra={**ex.extra, "connectivity": conn}), path)
    if not run.quiet:
        click.echo(f"wrote {path} (the exemplar with {len(ref.edges)} edges)", err=True)


def _summary(run, arr) -> str:
    from ._common import visible_counts

    n, _ = visible_counts(arr)
    return f"grew {n} elements in {run.seconds:.2f} s ({n / max(run.seconds, 1e-9):,.0f} elements/s)"


command = method_command(SPEC, Hooks(
    options=[click.option("--exemplar-out", type=click.Path(dir_okay=False), default=None,
                          help="Also write the exemplar with its analysed connectivity (after --flip) as JSON, to edit and reuse.")],
    check=_check,
    prepare=_prepare,
    finish=_finish,
    summary=_summary,
    description="Grow a larger arrangement from EXEMPLAR (SVG or JSON), one element at a time.\n\n"
    "Growth starts from one seed and copies the 1-ring neighbourhoods of the exemplar (Ijiri et al. 2008). "
    "Without --count it fills --region or --size.",
))
