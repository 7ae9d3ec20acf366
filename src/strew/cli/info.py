"""``strew info``: counts per kind, bounds and metrics of an arrangement."""

from __future__ import annotations

import click


MAX_PAIR_KINDS = 64  # kind-pair statistics (nearest neighbour by kind, g_ab(r)) up to this many kinds


@click.command("info")
@click.argument("input", type=click.Path())
@click.option("--region", type=click.Path(dir_okay=False), default=None, help="Measure against this region instead.")
@click.option("--json", "as_json", is_flag=True, help="Print the figures as JSON.")
def command(input: str, region: str | None, as_json: bool) -> None:
    """Print counts per kind, bounds and the metrics of INPUT (.json or .svg)."""
    import json

    from .. import metrics
    from ..io import load, load_region

    from ..io._parquet import is_dataset

    if is_dataset(input):  # a world (issue 19): summarised from its columns, never loaded whole
        from ..io._parquet import parquet_summary

        s = parquet_summary(input)
        if as_json:
            click.echo(json.dumps(s, indent=2, default=str))
        else:
            w = s["meta"].get("world", {})
            click.echo(f"{input}: {s['elements']:,} elements in {s['tiles']} tiles ({w.get('size')}, tile {w.get('tile_size')}), "
                       + ", ".join(f"{k} {c:,} ({s['kind_fractions'][k]:.3f})" for k, c in s["counts"].items()))
        return
    arr = load(input)
    reg = load_region(region) if region else None
    s = metrics.summary(arr, reg)
    # the single-arrangement parts of the fidelity measures (strew compare)
    # both cost one term per pair of kinds: a drawing of 9,174 distinct shapes (each
    # its own kind, 1 MB) ran over 10 min and 4 GB here; past MAX_PAIR_KINDS they are
    # left out (null in JSON) and the summary says so
    pairs = len(arr.kinds) <= MAX_PAIR_KINDS
    s["nearest_neighbor_by_kind"] = metrics.nearest_neighbor_distances(arr) if pairs else None
    s["pair_correlation"] = _pair_correlation(arr, reg) if pairs else None
    if as_json:
        # what cannot be computed (a density CV without a region) is null, never NaN,
        # which JSON.parse and other strict readers reject
        click.echo(json.dumps(_finite_or_none(s), indent=2, allow_nan=False))
        return
    from rich.console import Console
    from rich.table import Table

    console = Console()
    hidden = s["elements"] - s["count"]
    t = Table(title=f"{input}: {s['count']} elements" + (f" ({hidden} invisible not counted)" if hidden else ""), show_header=True)
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
        f"filled overlaps   {s['filled_overlap_pairs']} pairs, area {s['filled_overlap_area']:.4g}",
        f"stroke crossings  {s['stroke_crossings']} pairs (open strokes that cross or touch)",
        f"coverage          {s['coverage']:.4f}",
        *([f"density CV        {s['density_cv']:.4f}"] if _finite(s["density_cv"]) else []),
        f"nearest neighbour mean {nn['mean']:.4g}, std {nn['std']:.4g}, min {nn['min']:.4g}, cv {nn['cv']:.3f}",
    ]
    if "outside" in s:
        lines.append(f"outside region    {s['outside']} elements (region area {s['region_area']:.4g})")
    if not pairs:
        lines.append(f"kind pairs        not measured: {len(arr.kinds):,} kinds (more than {MAX_PAIR_KINDS})")
    for key, v in (s["nearest_neighbor_by_kind"] or {}).items():
        lines.append(f"nearest {key:<10s} median {v['median']:.4g}, mean {v['mean']:.4g} ({v['count']} elements)")
    pc = s["pair_correlation"]
    if pc is not None:
        for key, g in pc["g"].items():
            finite = [(r, v) for r, v in zip(pc["r"], g) if v is not None]
            if finite:
                rp, gp = max(finite, key=lambda t: t[1])
                lines.append(f"g({key}) peak {gp:.3g} at r {rp:.4g}; r up to {pc['r_max']:.4g}")
    for line in lines:
        console.print(line, highlight=False)


def _pair_correlation(arr, reg):  # type: ignore[no-untyped-def]
    """g_ab(r) as JSON-ready lists (NaN -> null), or None when it is undefined."""
    import math

    from .. import metrics
    from .._errors import InputError

    try:
        pc = metrics.pair_correlation(arr, reg)
    except InputError:
        return None

    def clean(v: float) -> float | None:
        v = float(v)
        return v if math.isfinite(v) else None

    return {"r": [float(r) for r in pc["r"]], "r_max": float(pc["r_max"]), "g": {k: [clean(v) for v in g] for k, g in pc["g"].items()}}


def _finite(v) -> bool:  # type: ignore[no-untyped-def]
    import math

    return isinstance(v, (int, float)) and math.isfinite(v)


def _finite_or_none(obj):  # type: ignore[no-untyped-def]
    """``obj`` with every non-finite float replaced by None (JSON null)."""
    if isinstance(obj, dict):
        return {k: _finite_or_none(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_finite_or_none(v) for v in obj]
    if isinstance(obj, float) and not _finite(obj):
        return None
    return obj
