"""``strew demo``: write a gallery of examples."""

from __future__ import annotations

import click

from ._common import progress_bar, quiet_option, seed_option


@click.command("demo")
@click.option("--out", "out_dir", type=click.Path(file_okay=False), default="strew-demo", show_default=True, help="Gallery folder.")
@click.option("--only", multiple=True, help="Only sections whose name contains this word (repeatable).")
@seed_option
@quiet_option
def command(out_dir: str, only: tuple[str, ...], seed: int, quiet: bool) -> None:
    """Write SVG, PNG and JSON of every example, and an index.html that shows them."""
    import time
    from pathlib import Path

    from ..demo import build_gallery

    t0 = time.perf_counter()
    with progress_bar("gallery", quiet=quiet) as (progress, cancel):
        if progress is None and not quiet:
            # not a terminal (a log, CI, a pipe): one line per section instead of a bar,
            # so a long gallery never looks hung
            def progress(done: int, total: int | None, message: str) -> None:
                if done < (total or 0):
                    click.echo(f"gallery {done + 1}/{total}: {message} ({time.perf_counter() - t0:.0f} s)", err=True)

        files = build_gallery(out_dir, seed=seed, sections=only or None, progress=progress, should_cancel=cancel)
    if not quiet:
        n = sum(1 for f in files if f.suffix == ".svg")
        click.echo(f"wrote {n} examples to {Path(out_dir) / 'index.html'} in {time.perf_counter() - t0:.1f} s")
