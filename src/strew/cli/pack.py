"""``strew pack``: dense non-periodic aggregates of arbitrary shapes (Sakurai & Miyata)."""

from __future__ import annotations

import click

from ._common import check_outputs, domain_options, echo, out_option, progress_bar, quiet_option, seed_option


def _per_kind(values: tuple[str, ...], name: str, parse, default):
    """``[KIND=]VALUE`` options: a value for all kinds, overridden per kind."""
    out = {"*": default}
    for text in values:
        kind, sep, rest = text.partition("=")
        if sep and ":" not in kind:
            out[kind.strip()] = parse(rest, f"{name} {kind.strip()}")
        else:
            out["*"] = parse(text, name)
    return out


@click.command("pack")
@click.argument("shapes", nargs=-1, required=True, type=click.Path(dir_okay=False))
@domain_options()
@click.option("--method", type=click.Choice(["fill-gap", "naive"]), default="fill-gap", show_default=True,
              help="Fill-gap (§4) or naive dart throwing (§3.2).")
@click.option("--max-failures", type=int, default=None,
              help="Stop after N consecutive cancellations [default: 200 fill-gap, 10000 naive].")
@click.option("--rotate", multiple=True, metavar="[KIND=]A:B",
              help="Rotation range in degrees [default: 0:360]; repeat with KIND= for one kind.")
@click.option("--scale", multiple=True, metavar="[KIND=]A:B", help="Scale range [default: 1:1]; KIND= for one kind.")
@click.option("--margin", multiple=True, metavar="[KIND=]M",
              help="Grow each exclusive region by M (a buffer) [default: 0]; KIND= for one kind.")
@click.option("--exclusive", type=click.Path(dir_okay=False), default=None,
              help="SVG or JSON file of exclusive shapes, matched to kinds by name.")
@click.option("--weight", multiple=True, metavar="KIND=W",
              help="Requested proportions of kinds (others 1) [default: equal].")
@click.option("--kind-choice", type=click.Choice(["fit", "cycle"]), default="fit", show_default=True,
              help="Fill-gap: try the kinds most behind their proportions until one fits the gap, or cycle (§3.2).")
@click.option("--scale-choice", type=click.Choice(["random", "fit"]), default="random", show_default=True,
              help="Fill-gap: uniform scales in the range, or the largest that fits each gap first.")
@click.option("--candidates", type=int, default=100, show_default=True, help="Fill-gap: candidates P per round.")
@click.option("--power", type=float, default=16.0, show_default=True, help="Fill-gap: exponent n of d**n.")
@click.option("--resolution", type=float, default=None, help="Fill-gap: pixel side of the distance field.")
@seed_option
@out_option()
@quiet_option
def command(
    shapes: tuple[str, ...],
    region: str | None,
    size: str | None,
    method: str,
    max_failures: int | None,
    rotate: tuple[str, ...],
    scale: tuple[str, ...],
    margin: tuple[str, ...],
    exclusive: str | None,
    weight: tuple[str, ...],
    kind_choice: str,
    scale_choice: str,
    candidates: int,
    power: float,
    resolution: float | None,
    seed: int,
    outs: tuple[str, ...],
    quiet: bool,
) -> None:
    """Pack copies of SHAPE... (SVG or JSON files) densely into a region.

    A file holding several shapes gives several kinds, in equal proportions unless
    --weight is given (fill-gap keeps them within 0.05; naive cycles or draws by
    weight). Elements lie wholly inside the region and never overlap.
    """
    import time
    import warnings
    from pathlib import Path

    import numpy as np

    from .. import metrics
    from .._errors import InputError
    from ..io import load_shapes
    from ..pack import pack
    from ._common import parse_range, resolve_domain, write_outputs

    check_outputs(outs)
    dom = resolve_domain(region, size)
    if dom is None:
        raise InputError("give --region FILE or --size WxH")
    lib: dict = {}
    for path in shapes:
        for name, sh in load_shapes(path).items():
            key = name if name not in lib else f"{Path(path).stem}-{name}"
            lib[key] = sh
    excl = load_shapes(exclusive) if exclusive else None

    def deg_range(text: str, name: str) -> tuple[float, float]:
        lo, hi = parse_range(text, name)
        return float(np.radians(lo)), float(np.radians(hi))

    def number(text: str, name: str) -> float:
        try:
            return float(text)
        except ValueError:
            raise InputError(f"{name}: expected a number, got {text!r}") from None

    rot = _per_kind(rotate, "--rotate", deg_range, (0.0, 2 * np.pi))
    sca = _per_kind(scale, "--scale", lambda t, n: parse_range(t, n), (1.0, 1.0))
    mar = _per_kind(margin, "--margin", number, 0.0)
    weights = None
    if weight:
        w = _per_kind(weight, "--weight", number, 1.0)
        weights = {**{k: w["*"] for k in lib}, **{k: v for k, v in w.items() if k != "*"}}
    params = {
        "method": method,
        "max_failures": max_failures,
        "rotate": list(rotate),
        "scale": list(scale),
        "margin": list(margin),
        "exclusive": exclusive,
        "weight": list(weight),
        "kind_choice": kind_choice,
        "scale_choice": scale_choice,
        "candidates": candidates,
        "power": power,
        "resolution": resolution,
        "shapes": list(shapes),
    }
    t0 = time.perf_counter()
    with warnings.catch_warnings(record=True) as caught, progress_bar(f"pack ({method})", quiet=quiet) as (prog, cancel):
        warnings.simplefilter("always")
        arr = pack(
            lib,
            dom,
            method=method,
            rotation=rot,
            scale=sca,
            margin=mar,
            exclusive=excl,
            weights=weights,
            max_failures=max_failures,
            kind_choice=kind_choice,
            scale_choice=scale_choice,
            candidates=candidates,
            power=power,
            resolution=resolution,
            rng=seed,
            progress=prog,
            should_cancel=cancel,
        )
    dt = time.perf_counter() - t0
    for w_ in caught:
        click.echo(f"strew: warning: {w_.message}", err=True)
    if len(arr) == 0:
        raise InputError(arr.meta["pack"]["stopped"])
    write_outputs(arr, outs, method="pack", seed=seed, params=params, quiet=quiet)
    counts = ", ".join(f"{k} {c}" for k, c in arr.counts().items())
    cov = metrics.coverage(arr)
    echo(
        f"packed {len(arr)} elements ({counts}), coverage {100 * cov:.1f}%, {dt:.2f} s, "
        f"{method}, stopped after {arr.meta['pack']['stopped']}",
        quiet=quiet,
    )
