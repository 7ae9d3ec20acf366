"""``strew info``: counts per kind, bounds and metrics of an arrangement."""

from __future__ import annotations

import click


@click.command("info")
@click.argument("input", type=click.Path(dir_okay=False))
@click.option("--region", type=click.Path(dir_okay=False), default=None, help="Measure against this region instead.")
@click.option("--json", "as_json", is_flag=True, help="Print the figures as JSON.")
def command(input: str, region: str | None, as_json: bool) -> None:
    """Print counts per kind, bounds and the metrics of INPUT (.json or .svg)."""
    import json

    from .. import metrics
    from ..io import load, load_region

    arr = load(input)
    reg = load_region(region) if region else None
    s = metrics.summary(arr, reg)
    if as_json:
        click.echo(json.dumps(s, indent=2))
        return
    from rich.console import Console
    from rich.table import Table

    console = Console()
    t = Table(title=f"{input}: {s['count']} elements", show_header=True)
    t.add_column("kind")
    t.add_column("count", justify="right")
    t.add_column("fraction", justify="right")
    for k, c in s["counts"].items():
        t.add_row(k, str(c), f"{s['kind_fractions'][k]:.3f}")
    console.print(t)
    b = s["bounds"]
    nn = s["nearest_neighbor"]
    lines = [
        f"bounds            {b[0]:.4g}, {b[1]:.4g} .. {b[2]:.4g}, {b[3]:.4g}",
        f"overlaps          {s['overlap_pairs']} pairs, area {s['overlap_area']:.4g}",
        f"coverage          {s['coverage']:.4f}",
        f"density CV        {s['density_cv']:.4f}",
        f"nearest neighbour mean {nn['mean']:.4g}, std {nn['std']:.4g}, min {nn['min']:.4g}, cv {nn['cv']:.3f}",
    ]
    if "outside" in s:
        lines.append(f"outside region    {s['outside']} elements (region area {s['region_area']:.4g})")
    for line in lines:
        console.print(line, highlight=False)
