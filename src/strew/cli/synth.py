"""``strew synth``: example-based texture synthesis by region growing (Davison et al.)."""

from __future__ import annotations

import click

from ._common import check_outputs, domain_options, echo, out_option, parse_point, progress_bar, quiet_option, resolve_domain, seed_option, write_outputs


def _parse_select(items: tuple[str, ...]) -> dict | None:
    """``NAME``, ``NAME:WEIGHT`` or ``NAME=REGION`` (a region file: that texture fills it)."""
    from .._errors import InputError

    if not items:
        return None
    out: dict = {}
    for item in items:
        if not item.strip():
            raise InputError("--select: empty selection (name an exemplar)")
        if "=" in item:
            name, _, path = item.partition("=")
            if not name or not path:
                raise InputError(f"--select: expected NAME=REGION.svg, got {item!r}")
            from ..io import load_region

            out[name] = load_region(path)
            continue
        name, _, w = item.partition(":")
        if not name:
            raise InputError(f"--select: expected NAME or NAME:WEIGHT, got {item!r}")
        try:
            out[name] = float(w) if w else 1.0
        except ValueError:
            raise InputError(f"--select: weight of {name!r} must be a number, got {w!r}") from None
    return out


@click.command("synth")
@click.argument("exemplars", nargs=-1, required=True, type=click.Path(dir_okay=False))
@domain_options()
@click.option("--fill", "fill_at", default=None, metavar="X,Y", help="Filler: grow from this point until no room is left.")
@click.option("--brush", "brush_path", default=None, type=click.Path(dir_okay=False), help="Generative brush: a stroke (.svg or .json).")
@click.option("--brush-radius", type=float, default=None, help="Brush radius (document units).")
@click.option("--select", "select", multiple=True, metavar="NAME[:W]|NAME=REGION", help="Exemplars of the palette to use, with weights (shares of the region), or each with the region file it fills (repeatable; default all).")
@click.option("--k", type=int, default=5, show_default=True, help="k-coherence set size.")
@click.option("--c", "c_ratio", type=float, default=2.0, show_default=True, help="Ratio constant rejecting poor candidates (> 1).")
@click.option("--optimize", type=click.Choice(["horizon", "global", "none"]), default="horizon", show_default=True)
@click.option("--init", type=click.Choice(["grow", "patch"]), default="grow", show_default=True, help="Region growing, or Ma et al.'s patch initialisation.")
@click.option("--patch-rounds", type=click.IntRange(0), default=5, show_default=True, help="With --init patch: rounds of global optimisation.")
@click.option("--keep-voids", is_flag=True, help="Keep void elements (column 'void') instead of hiding them.")
@click.option("--plot", "plot_path", default=None, type=click.Path(dir_okay=False), help="PNG: average neighbourhood distance against time for each method (Fig. 17).")
@click.option("--save-palette", default=None, type=click.Path(dir_okay=False), help="Also write the example palette (.json document).")
@seed_option
@quiet_option
@out_option()
def command(exemplars, region, size, fill_at, brush_path, brush_radius, select, k, c_ratio, optimize, init, patch_rounds, keep_voids, plot_path, save_palette, seed, quiet, outs):
    """Synthesize a texture from EXEMPLAR files (.json or .svg; several make a palette).

    Without --fill or --brush the whole region (or size) is filled.
    """
    from .._errors import InputError

    check_outputs(outs)
    for extra, name in ((plot_path, "--plot"), (save_palette, "--save-palette")):
        if extra is not None:
            from ..io import check_output_path

            suffix = check_output_path(extra)
            want = ".png" if name == "--plot" else ".json"
            if suffix != want:
                raise InputError(f"{name} {extra!r}: must be a {want} file")
    if brush_path is not None and fill_at is not None:
        raise InputError("--fill and --brush: give one of them")
    if (brush_radius is not None) and brush_path is None:
        raise InputError("--brush-radius: needs --brush")
    if brush_path is not None and brush_radius is None:
        raise InputError("--brush: needs --brush-radius")
    if init == "patch" and (brush_path is not None or fill_at is not None):
        raise InputError("--init patch: fills the whole region; drop --fill and --brush")

    from ..synth import load_palette, save_palette as _save_palette, synthesize
    from ..synth._stroke import brush_points, read_stroke

    dom = resolve_domain(region, size)
    palette = load_palette(list(exemplars))
    sel = palette.select(_parse_select(select))
    if dom is None and sel.regions is not None:  # --select NAME=REGION: the regions together
        import shapely

        from ..region import Region

        dom = Region(shapely.union_all([r.geometry for r in sel.regions]))
    point = parse_point(fill_at, "--fill") if fill_at is not None else None
    bp = br = None
    if brush_path is not None:
        bp, br = brush_points(read_stroke(brush_path), brush_radius)
    if dom is None and bp is None:
        raise InputError("--region or --size: give the area to fill")
    params = {"k": k, "c": c_ratio, "optimize": optimize, "init": init, "keep_voids": keep_voids, "select": dict(zip(sel.names, sel.weights))}
    if sel.regions is not None:
        params["select_regions"] = {s.partition("=")[0]: s.partition("=")[2] for s in select}
    if init == "patch":
        params["patch_rounds"] = patch_rounds
    if point is not None:
        params["fill"] = list(point)
    if brush_path is not None:
        params.update(brush=str(brush_path), brush_radius=brush_radius)
    with progress_bar("synth", quiet=quiet) as (progress, should_cancel):
        arr = synthesize(
            sel, dom, fill_point=point, brush_points=bp, brush_radius=br, init=init, k=k, c=c_ratio, optimize=optimize,
            patch_rounds=patch_rounds if init == "patch" else None, keep_voids=keep_voids, rng=seed, progress=progress, should_cancel=should_cancel,
        )
    if plot_path is not None:
        if dom is None:
            raise InputError("--plot: needs --region or --size")
        from ..synth import compare_methods, plot_traces

        traces = compare_methods(sel, dom, rng=seed, k=k, c=c_ratio)
        plot_traces(traces, plot_path, title=f"strew synth: {', '.join(sel.names)}")
    write_outputs(arr, outs, method="synth", seed=seed, params=params, quiet=quiet)
    if save_palette is not None:
        _save_palette(palette, save_palette)
    d = arr.meta.get("synth", {}).get("average_neighborhood_distance")
    counts = ", ".join(f"{kk} {v}" for kk, v in arr.counts().items() if v)
    echo(f"synth: {len(arr)} elements ({counts}); average neighbourhood distance {d:.4g}" if d is not None else f"synth: {len(arr)} elements", quiet=quiet)
