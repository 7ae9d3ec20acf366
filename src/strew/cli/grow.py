"""``strew grow``: example-based growth from one seed (Ijiri et al. 2008)."""

from __future__ import annotations

import click

from ._common import check_outputs, domain_options, echo, out_option, progress_bar, quiet_option, seed_option


@click.command("grow")
@click.argument("exemplar", type=click.Path(dir_okay=False))
@click.option("--count", type=int, default=None, help="Stop at N elements [default: fill the region].")
@domain_options()
@click.option("--start", default=None, metavar="X,Y", help="Initial seed [default: the region's centre].")
@click.option("--start-kind", default=None, metavar="KIND", help="Symbol id (kind) of the initial seed.")
@click.option("--mode", type=click.Choice(["fixed", "rotate", "flow"]), default="fixed", show_default=True,
              help="Rotation mode (§5.3): keep, best-fit rotate, or follow --flow.")
@click.option("--flow", "flow_path", type=click.Path(dir_okay=False), default=None,
              help="Flow-field strokes (SVG or JSON); implies --mode flow unless --mode is given.")
@click.option("--boundary", "boundary_path", type=click.Path(dir_okay=False), default=None,
              help="Boundary strokes (SVG or JSON) that stop growth.")
@click.option("--spray", "spray_path", type=click.Path(dir_okay=False), default=None,
              help="Spray path (SVG or JSON): only seeds within --spray-radius of it grow.")
@click.option("--spray-radius", type=float, default=None, help="Radius of the spray tool.")
@click.option("--priority", multiple=True, metavar="KIND=P", help="Seed priority of a kind (§5.1) [default: larger kinds first when kinds differ in size, else 0].")
@click.option("--jitter-scale", type=float, default=0.0, show_default=True, help="Relative scale noise S: x(1 ± S).")
@click.option("--jitter-rotation", type=float, default=0.0, show_default=True, help="Rotation noise in degrees (±).")
@click.option("--jitter-color", type=float, default=0.0, show_default=True, help="Colour noise C: fill x(1 ± C).")
@click.option("--no-relax", is_flag=True, help="Turn off the least-squares relaxation (§5.5).")
@click.option("--flip", multiple=True, metavar="I,J", help="Flip edge I,J of the exemplar's connectivity (repeatable).")
@click.option("--connectivity", is_flag=True, help="Write the grown connectivity into the JSON output.")
@click.option("--exemplar-out", type=click.Path(dir_okay=False), default=None,
              help="Also write the exemplar with its analysed connectivity (after --flip) as JSON, to edit and reuse.")
@seed_option
@out_option()
@quiet_option
def command(
    exemplar: str,
    count: int | None,
    region: str | None,
    size: str | None,
    start: str | None,
    start_kind: str | None,
    mode: str,
    flow_path: str | None,
    boundary_path: str | None,
    spray_path: str | None,
    spray_radius: float | None,
    priority: tuple[str, ...],
    jitter_scale: float,
    jitter_rotation: float,
    jitter_color: float,
    no_relax: bool,
    flip: tuple[str, ...],
    connectivity: bool,
    exemplar_out: str | None,
    seed: int,
    outs: tuple[str, ...],
    quiet: bool,
) -> None:
    """Grow a larger arrangement from EXEMPLAR (SVG or JSON), one element at a time.

    Growth starts from one seed and copies the 1-ring neighbourhoods of the exemplar
    (Ijiri et al. 2008). Without --count it fills --region or --size.
    """
    import math
    import time

    from .._errors import InputError
    from ..io import load
    from ..grow import analyze, grow
    from ..grow._tools import load_strokes
    from ._common import parse_point, resolve_domain, write_outputs

    check_outputs(outs)
    if exemplar_out is not None:
        from ..io import check_output_path

        if check_output_path(exemplar_out) != ".json":
            raise InputError(f"--exemplar-out {exemplar_out!r}: must be a .json file (it carries the edge list)")
    ex = load(exemplar)
    dom = resolve_domain(region, size)
    flips = []
    for text in flip:
        a, b = parse_point(text, "--flip")
        if a != int(a) or b != int(b):
            raise InputError(f"--flip: expected two element indices I,J, got {text!r}")
        flips.append((int(a), int(b)))
    prio: dict[str, float] = {}
    for text in priority:
        kind, sep, val = text.partition("=")
        if not sep:
            raise InputError(f"--priority: expected KIND=P, got {text!r}")
        try:
            prio[kind.strip()] = float(val)
        except ValueError:
            raise InputError(f"--priority {kind.strip()}: P must be a number, got {val!r}") from None
    flow = None
    ctx = click.get_current_context()
    mode_given = ctx.get_parameter_source("mode") != click.core.ParameterSource.DEFAULT
    if flow_path is not None:
        from ..fields import flow_field

        flow = flow_field(load_strokes(flow_path, "--flow"))
        if not mode_given:
            mode = "flow"
    boundary = load_strokes(boundary_path, "--boundary") if boundary_path else None
    spray = None
    if spray_path is not None:
        strokes = load_strokes(spray_path, "--spray")
        if len(strokes) > 1:
            raise InputError(f"--spray {spray_path}: expected one path, found {len(strokes)}")
        spray = strokes[0]
    start_pt = parse_point(start, "--start") if start is not None else None
    ref = analyze(ex, flips=flips)
    t0 = time.perf_counter()
    with progress_bar("grow", quiet=quiet) as (progress, should_cancel):
        arr = grow(
            ref,
            count=count,
            region=dom,
            start=start_pt,
            start_kind=start_kind,
            mode=mode,
            flow=flow,
            boundary=boundary,
            spray=spray,
            spray_radius=spray_radius,
            priority=prio or None,
            jitter_scale=jitter_scale,
            jitter_rotation=math.radians(jitter_rotation),
            jitter_color=jitter_color,
            relax=not no_relax,
            connectivity=connectivity,
            rng=seed,
            progress=progress,
            should_cancel=should_cancel,
        )
    dt = time.perf_counter() - t0
    params = {
        "exemplar": exemplar,
        "count": count,
        "mode": mode,
        "start": list(start_pt) if start_pt else None,
        "start_kind": start_kind,
        "flow": flow_path,
        "boundary": boundary_path,
        "spray": spray_path,
        "spray_radius": spray_radius,
        "priority": prio,
        "jitter_scale": jitter_scale,
        "jitter_rotation_deg": jitter_rotation,
        "jitter_color": jitter_color,
        "relax": not no_relax,
        "flip": [list(f) for f in flips],
    }
    write_outputs(arr, outs, method="grow", seed=seed, params=params, quiet=quiet)
    if exemplar_out is not None:
        from ..io import save

        conn = {"count": len(ex), **ref.to_dict(), "interior": ref.interior.tolist()}
        save(ex.replace(extra={**ex.extra, "connectivity": conn}), exemplar_out)
        if not quiet:
            click.echo(f"wrote {exemplar_out} (the exemplar with {len(ref.edges)} edges)", err=True)
    echo(f"grew {len(arr)} elements in {dt:.2f} s ({len(arr) / max(dt, 1e-9):,.0f} elements/s)", quiet=quiet)
