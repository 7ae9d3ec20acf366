"""``strew demo``: a gallery of examples written as SVG, PNG and an index.html.

Each method contributes a section: a module with a function ``items(rng)`` returning
:class:`DemoItem` objects. To add a section, add one line to :data:`SECTIONS`.
"""

from __future__ import annotations

import html
import time
from collections.abc import Callable, Sequence
from pathlib import Path

import numpy as np

from ._errors import InputError
from ._demo_item import DemoItem
from ._progress import Reporter

__all__ = ["DemoItem", "SECTIONS", "build_gallery"]

# (section title, module). Each module defines ``items(rng) -> list[DemoItem]``.
SECTIONS: list[tuple[str, str]] = [
    ("Basics: exemplars drawn for strew", "strew._demos.basics"),
    ("Packing: fill-gap (Sakurai & Miyata)", "strew.pack._demo"),
    ("Growth from one seed (Ijiri et al.)", "strew.grow._demo"),
    ("Programmable arrangements: planar maps, partitions, mappers (Loi et al.)", "strew.program._demo"),
    ("Adaptive clip art: rule-driven floral ornament (Wong et al.)", "strew.ornament._demo"),
    ("Example palettes and region-growing synthesis (Davison et al.)", "strew.synth._demo"),
    ("Seamless repeat tiles: wallpaper, textile and game textures", "strew._demos.repeat"),
]


def _section_items(module: str, seed: int) -> list[DemoItem]:
    import importlib

    mod = importlib.import_module(module)
    return list(mod.items(np.random.default_rng(seed)))


def build_gallery(
    out_dir: str | Path,
    *,
    seed: int = 0,
    sections: Sequence[str] | None = None,
    png_width: int = 800,
    progress: Callable[[int, int | None, str], None] | None = None,
    should_cancel: Callable[[], bool] | None = None,
) -> list[Path]:
    """Build every gallery section into ``out_dir``; returns the files written.

    Parameters
    ----------
    out_dir : path
        Created if missing.
    seed : int
        Seed for every section (each gets its own Generator from it).
    sections : sequence of str, optional
        Only sections whose module name contains one of these words.
    """
    from .io import atomic_write, save
    from .io.document import dumps
    from .metrics import visible_count

    out = Path(out_dir)
    chosen = [(t, m) for t, m in SECTIONS if not sections or any(s in m for s in sections)]
    if not chosen:  # checked before creating the folder: a refused run writes nothing
        names = ", ".join(m.replace("._demo", "").rsplit(".", 1)[-1] for _, m in SECTIONS)
        raise InputError(f"--only: no gallery section matches {', '.join(sections or [])} (have: {names})")
    out.mkdir(parents=True, exist_ok=True)
    rep = Reporter(progress, should_cancel, total=len(chosen), message="gallery")
    written: list[Path] = []
    blocks: list[str] = []
    for i, (title, module) in enumerate(chosen):
        rep.tick(i, message=title, force=True)
        t0 = time.perf_counter()
        items = _section_items(module, seed)
        figs = []
        for item in items:
            svg_path = out / f"{item.name}.svg"
            png_path = out / f"{item.name}.png"
            json_path = out / f"{item.name}.json"
            arr = item.arrangement.with_meta(demo=item.name)
            save(arr, svg_path, **item.svg_options)
            save(arr, png_path, width=png_width, **{k: v for k, v in item.svg_options.items() if k == "repeat"})
            atomic_write(json_path, dumps(arr))
            written += [svg_path, png_path, json_path]
            figs.append(
                f'<figure><a href="{html.escape(svg_path.name)}"><img src="{html.escape(png_path.name)}" '
                f'alt="{html.escape(item.title)}" loading="lazy"></a><figcaption><b>{html.escape(item.title)}</b>'
                f" ({visible_count(item.arrangement)} elements)<br>{html.escape(item.description)}</figcaption></figure>"
            )
        dt = time.perf_counter() - t0
        blocks.append(f"<section><h2>{html.escape(title)}</h2><p class=t>built in {dt:.2f} s</p>{''.join(figs)}</section>")
    rep.done(len(chosen))
    page = (
        "<!doctype html><html><head><meta charset=utf-8><title>strew gallery</title><style>"
        "body{font-family:system-ui,sans-serif;margin:2em;color:#222}figure{display:inline-block;margin:1em;"
        "vertical-align:top;width:360px}img{width:360px;border:1px solid #ddd}.t{color:#888}</style></head><body>"
        "<h1>strew gallery</h1><p>Each picture links to its SVG; a .json strew document sits beside it.</p>"
        + "".join(blocks)
        + "</body></html>\n"
    )
    index = out / "index.html"
    atomic_write(index, page)
    written.append(index)
    return written
