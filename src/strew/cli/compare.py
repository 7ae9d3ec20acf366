"""``strew compare``: how faithfully a result continues its exemplar (fidelity metrics)."""

from __future__ import annotations

import click


@click.command("compare")
@click.argument("exemplar", type=click.Path(dir_okay=False))
@click.argument("result", type=click.Path(dir_okay=False))
@click.option("--region", type=click.Path(dir_okay=False), default=None, help="The result's region (default: its own, else its bounding box).")
@click.option("--json", "as_json", is_flag=True, help="Print the report as JSON.")
@click.option("--plot", type=click.Path(dir_okay=False), default=None, help="Write a figure (PNG): both side by side, g(r) curves, the local map.")
@click.option("--no-eq5", is_flag=True, help="Skip Davison's Eq. 5 (a brute-force neighbourhood match).")
def command(exemplar: str, result: str, region: str | None, as_json: bool, plot: str | None, no_eq5: bool) -> None:
    """Measure RESULT against the EXEMPLAR it continues (.json or .svg).

    Prints each metric's discrepancy, its tolerance (derived from the exemplar's own
    sampling noise) and the verdict, then the worst window of the local map. Exits 0
    whenever it measured, whatever the verdict.
    """
    import json

    from .._fidelity import fidelity, plot_fidelity
    from ..io import check_output_path, load, load_region

    if plot is not None:
        check_output_path(plot)
        if not plot.lower().endswith(".png"):
            raise click.BadParameter(f"{plot!r}: the plot is written as PNG; name it .png", param_hint="--plot")
    ex = load(exemplar)
    res = load(result)
    reg = load_region(region) if region else None
    report = fidelity(ex, res, reg, eq5=not no_eq5)
    if plot is not None:
        plot_fidelity(ex, res, report, plot, title=f"{exemplar} -> {result}")
    if as_json:
        click.echo(json.dumps(report.to_dict(), indent=2, allow_nan=False))
        return
    from rich.console import Console
    from rich.markup import escape
    from rich.table import Table

    console = Console()
    verdict = "[green]faithful[/green]" if report.faithful else f"[red]not faithful[/red] ({len(report.failures)} of {sum(m.applicable for m in report.metrics.values())} metrics fail)"
    t = Table(title=f"{escape(result)} against {escape(exemplar)}: {verdict}", show_header=True)
    for col, just in (("metric", "left"), ("value", "right"), ("tolerance", "right"), ("exemplar -> result", "right"), ("", "left")):
        t.add_column(col, justify=just)  # type: ignore[arg-type]
    for name, v, tol, side, ok in report.table():
        style = "red" if ok == "FAIL" else ("dim" if ok == "n/a" else None)
        t.add_row(escape(name), v, tol, side, ok, style=style)
    console.print(t)
    info = report.info
    lines = [
        f"length unit s     {report.s:.4g} (the exemplar's median nearest-neighbour distance)",
        f"areas             exemplar {info['exemplar_window_area']:.4g}, result interior {info['result_window_area']:.4g} (x{info['area_ratio']:.3g})",
        f"lattice           {'yes, ' + str(info['lattice_pattern']['count']) + ' neighbours' if info['lattice'] else 'no'}",
    ]
    if info["exemplar_void_share"] or info["result_void_share"]:
        lines.append(f"voids (not judged) exemplar {info['exemplar_void_share']:.3f}, result {info['result_void_share']:.3f}")
    w = report.local.get("worst")
    if w:
        b = w["bounds"]
        lines.append(f"worst window      ({b[0]:.4g}, {b[1]:.4g})-({b[2]:.4g}, {b[3]:.4g}): score {w['score']:.3g} on {w['metric'] or '-'} (> 1 fails)")
    if plot is not None:
        lines.append(f"wrote {plot}")
    for line in lines:
        console.print(escape(line), highlight=False)
