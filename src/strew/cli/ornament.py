"""``strew ornament``: grow adaptive clip art (Wong et al. 1998) in a panel."""

from __future__ import annotations

import click

from ._common import (
    check_outputs,
    domain_options,
    echo,
    out_option,
    parse_point,
    progress_bar,
    quiet_option,
    resolve_domain,
    seed_option,
    write_outputs,
)


@click.command("ornament")
@click.argument("pattern", metavar="PATTERN_OR_RULE_FILE")
@domain_options(default_size=None)
@click.option("--seed-point", "seed_points", multiple=True, metavar="X,Y", help="Seed position (repeatable); default: the centre of the largest inscribed circle.")
@click.option("--resolution", type=int, default=None, help="Raster cells along the panel's longer side (default: cells of half the minimum radius).")
@click.option("--min-radius", type=float, default=None, help="Stop when no empty circle is this large (default: the pattern's).")
@click.option("--style", default="outline", show_default=True, help="Rendering style: outline, tapered, filigree, skeletal (-leafy, -beads, -ribbon), or one the pattern defines.")
@click.option("--max-elements", type=int, default=None, help="Stop after this many elements.")
@seed_option
@out_option()
@quiet_option
def command(pattern, region, size, seed_points, resolution, min_radius, style, max_elements, seed, outs, quiet):
    """Grow ornament from PATTERN (dots, flowers, spirals, hierarchy, vase, willow) or a Python RULE_FILE.

    Growth repeatedly fills the largest empty circle next to the ornament with whatever
    the pattern's rules grow there, until no empty circle of the minimum radius remains.

    A RULE_FILE is a Python program: it runs with your rights (it can read, write and
    delete your files), so use only rule files you trust.
    """
    from .._errors import InputError
    from ..ornament import available_styles, grow_elements, load_pattern

    check_outputs(outs)
    pat = load_pattern(pattern)
    styles = available_styles(pat)
    if style not in styles:
        raise InputError(f"--style: unknown style {style!r} for pattern {pat.name!r} (have: {', '.join(styles)})")
    dom = resolve_domain(region, size)
    if dom is None:
        raise InputError("give the panel with --region FILE or --size WxH")
    seeds = [parse_point(p, "--seed-point") for p in seed_points] or None
    with progress_bar(f"ornament {pat.name}", quiet=quiet) as (progress, should_cancel):
        orn = grow_elements(
            pat,
            dom,
            seeds=seeds,
            rng=seed,
            resolution=resolution,
            min_radius=min_radius,
            max_elements=max_elements,
            progress=progress,
            should_cancel=should_cancel,
        )
    arr = orn.render(style)
    params = {**arr.meta.get("params", {}), "pattern": str(pattern)}
    write_outputs(arr, outs, method="ornament", seed=seed, params=params, quiet=quiet)
    st = orn.stats
    from ..metrics import visible_count

    n = sum(1 for e in orn.elements if e.type != "seed")
    echo(  # the count is the drawn one, as strew info and the gallery give it (issue 23)
        f"{pat.name}: {visible_count(arr)} elements drawn from {n} grown in {st['seconds']:.2f} s ({st['successes']} placed, "
        f"{st['failures']} excluded circles), style {style}",
        quiet=quiet,
    )
