"""Compose docs/gallery.png (the README picture) from a `strew demo` gallery.

    strew demo --out /tmp/gallery && python scripts/readme_picture.py /tmp/gallery

Takes up to six pictures, preferring one per method, and tiles them 3 x 2.
"""

from __future__ import annotations

import sys
from pathlib import Path

from PIL import Image

PREFERRED = ["pack-stones", "grow-flow", "synth-two-scales", "ornament-hierarchy-rect", "program-fig11d-mosaic", "pack-trees", "grow-", "synth-", "ornament-", "program-", "exemplar-stones"]


def main() -> None:
    gallery = Path(sys.argv[1] if len(sys.argv) > 1 else "strew-demo")
    pngs = sorted(gallery.glob("*.png"))
    chosen: list[Path] = []
    for prefix in PREFERRED:
        for p in pngs:
            if p.stem.startswith(prefix) and p not in chosen:
                chosen.append(p)
                break
        if len(chosen) == 6:
            break
    tile = 400
    cols = 3
    rows = (len(chosen) + cols - 1) // cols
    sheet = Image.new("RGB", (cols * tile + (cols - 1) * 8, rows * tile + (rows - 1) * 8), "white")
    for i, p in enumerate(chosen):
        im = Image.open(p).convert("RGB")
        im.thumbnail((tile, tile))
        x = (i % cols) * (tile + 8) + (tile - im.width) // 2
        y = (i // cols) * (tile + 8) + (tile - im.height) // 2
        sheet.paste(im, (x, y))
    out = Path(__file__).resolve().parents[1] / "docs" / "gallery.png"
    sheet.save(out, optimize=True)
    print(f"wrote {out} from {', '.join(p.stem for p in chosen)}")


if __name__ == "__main__":
    main()
