"""A program world's PNG overview paints each face in its own fill, as strew render does (issue 19.3)."""

from __future__ import annotations

import io
from pathlib import Path

import numpy as np
import pytest
import shapely

from strew.tiles import tiled

LABELLED = """
from strew.program import *
p = set_weighted_face_labels(irregular_properties(0.002), "a", 0.4, "b", 0.3)
arrangement = uniform_partition(p, CROP_ADD_BOUNDARY)
"""


@pytest.mark.slow
def test_faces_keep_their_fill_and_tiles_leave_no_grid(tmp_path: Path):
    pytest.importorskip("PIL")
    from PIL import Image

    from strew.io._overview import Overview, _paint

    script = tmp_path / "labelled.py"
    script.write_text(LABELLED)
    size = (240.0, 200.0)
    arr = tiled("program", str(script), size, tile_size=80.0, halo=40.0, seed=2)
    ov = Overview(size, 480)  # 2 px a unit
    ov.add(arr)
    img = np.asarray(Image.open(io.BytesIO(ov.png())).convert("RGB"))
    cells, labels = np.asarray(arr["cell"]), np.asarray(arr["labels"])
    faces = np.flatnonzero(cells == "face")
    seen = {"": 0, "labelled": 0}
    for i in faces.tolist():
        poly = arr.geometry[i]
        inner = poly.buffer(-3.0)  # away from the edges' strokes
        if inner.is_empty:
            continue
        x, y = shapely.get_coordinates(inner.representative_point())[0]
        got = tuple(img[int((size[1] - y) * 2), int(x * 2)].tolist())
        want = _paint(arr.element_parts[i][0].style, "fill", (0, 0, 0))
        if labels[i] == "":
            assert got == (255, 255, 255)  # no fill: the background, not the kind's colour
            seen[""] += 1
        else:
            assert want is not None and got == want != (255, 255, 255)
            seen["labelled"] += 1
        # no grid: along the tile borders a face keeps its colour
        for bx in (80.0, 160.0):
            seg = shapely.intersection(inner, shapely.LineString([(bx, 0), (bx, size[1])]))
            if not seg.is_empty and seg.length > 4:
                yy = np.linspace(seg.bounds[1] + 1, seg.bounds[3] - 1, 5)
                col = {tuple(img[int((size[1] - v) * 2), int(bx * 2)].tolist()) for v in yy}
                assert col == {got}
    assert seen[""] >= 3 and seen["labelled"] >= 3
