"""``strew synth``: example-based texture synthesis by region growing (Davison et al.).

Options, checks and ``--help`` come from :data:`strew.synth.SPEC`; ``--brush FILE``,
``--plot`` and ``--save-palette`` are the CLI's own.
"""

from __future__ import annotations

import click

from .._errors import InputError
from ..synth._api import SPEC
from ._common import flag_for
from ._spec import Hooks, method_command


def _check(run) -> None:
    o = run.options
    for extra, name, want in ((o["plot_path"], "--plot", ".png"), (o["save_palette"], "--save-palette", ".json")):
        if extra is not None:
            from ..io import check_output_path

            if check_output_path(extra) != want:
                raise InputError(f"{name} {extra!r}: must be a {want} file")
    brush, radius, fill = o["brush_path"], o["brush_radius"], o["fill_point"]
    if brush is not None and fill is not None:
        raise InputError("--fill and --brush: give one of them")
    if radius is not None and brush is None:
        raise InputError("--brush-radius: needs --brush")
    if brush is not None and radius is None:
        raise InputError("--brush: needs --brush-radius")
    if o["init"] == "patch" and (brush is not None or fill is not None):
        raise InputError("--init patch: fills the whole region; drop --fill and --brush")


def _prepare(run) -> None:
    v = run.values
    sel = run.input.select(v.pop("selection", None))  # the palette's selection
    run.state["palette"], run.input = run.input, sel
    if run.region is None and sel.regions is not None:  # --select NAME=REGION: the regions together
        import shapely

        from ..region import Region

        run.region = Region(shapely.union_all([r.geometry for r in sel.regions]))
    if run.options["brush_path"] is not None:
        from ..synth._stroke import brush_points, read_stroke

        with flag_for("brush_radius", "--brush-radius"), flag_for("brush", "--brush"):
            v["brush_points"], v["brush_radius"] = brush_points(read_stroke(run.options["brush_path"], "brush"), v["brush_radius"])
    if v.get("init") == "patch":
        v.setdefault("patch_rounds", 5)
    if run.region is None and "brush_points" not in v:
        raise InputError("--region or --size: give the area to fill")


def _finish(run, arr) -> None:
    o = run.options
    if o["plot_path"] is not None:
        if run.region is None:
            raise InputError("--plot: needs --region or --size")
        from ..synth import compare_methods, plot_traces

        traces = compare_methods(run.input, run.region, rng=run.seed, k=run.values.get("k", 5), c=run.values.get("c", 2.0))
        plot_traces(traces, o["plot_path"], title=f"strew synth: {', '.join(run.input.names)}")
    if o["save_palette"] is not None:
        from ..synth import save_palette

        save_palette(run.state["palette"], o["save_palette"])


def _summary(run, arr) -> str:
    from ._common import visible_counts

    d = arr.meta.get("synth", {}).get("average_neighborhood_distance")
    n, counts = visible_counts(arr)
    return f"synth: {n} elements ({counts}); average neighbourhood distance {d:.4g}" if d is not None else f"synth: {n} elements"


command = method_command(SPEC, Hooks(
    options=[
        click.option("--brush", "brush_path", default=None, type=click.Path(dir_okay=False),
                     help="Generative brush: a stroke (.svg or .json), with --brush-radius (§5.4)."),
        click.option("--plot", "plot_path", default=None, type=click.Path(dir_okay=False),
                     help="PNG: average neighbourhood distance against time for each method (Fig. 17)."),
        click.option("--save-palette", default=None, type=click.Path(dir_okay=False), help="Also write the example palette (.json document)."),
    ],
    check=_check,
    prepare=_prepare,
    finish=_finish,
    summary=_summary,
    description="Synthesize a texture from EXEMPLAR files (.json or .svg; several make a palette).\n\n"
    "Without --fill or --brush the whole region (or size) is filled.",
))
