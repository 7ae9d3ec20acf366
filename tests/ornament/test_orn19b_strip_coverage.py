"""benchmarks/worlds_strips.py --coverage: drawn geometry counted where it lies (issue 19.4).

Border-strip statistics count an element at its centre; a willow stem that a later tile
starts at the cut and runs inward then counts far from the border it touches. The
coverage measure counts a line's length, a polygon's area, in the strip or interior and
the tile where each part of it lies.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest
import shapely

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def coverage_units():
    sys.path.insert(0, str(ROOT / "benchmarks"))
    try:
        import worlds_strips
    finally:
        sys.path.remove(str(ROOT / "benchmarks"))
    return worlds_strips.coverage_units


class _Arr:
    """The three things coverage_units reads of an Arrangement."""

    def __init__(self, geoms, kind, kinds):
        self._g = np.array(geoms, dtype=object)
        self.kind = np.asarray(kind)
        self.kinds = kinds

    def geometry_of(self, what):
        assert what == "geometry"
        return self._g


def test_lines_count_their_length_and_polygons_their_area_where_they_lie(coverage_units):
    # 40 x 40 world, tiles of 20 (tile 0 bottom left, 1 right of it), strips |x - 20| < 2
    # or |y - 20| < 2, no edge band
    arr = _Arr([shapely.LineString([(5, 10), (15, 10)]),    # kind 0, tile 0's interior
                shapely.LineString([(16, 5), (24, 5)]),     # kind 1, crosses the border x = 20
                shapely.box(30, 30, 31, 31)],               # kind 0, a polygon in tile 3
               [0, 1, 0], ["stem", "leaf"])
    u = coverage_units(arr, (40.0, 40.0), 20.0, 2.0, 0.0)
    # tile 0: 10 of the first line inside; the second: 2 inside (16-18), 2 in the strip (18-20)
    assert u["inner_kind"][0].tolist() == pytest.approx([10.0, 2.0])
    assert u["strip_kind"][0].tolist() == pytest.approx([0.0, 2.0])
    # tile 1: 2 in the strip (20-22), 2 inside (22-24)
    assert u["strip_kind"][1].tolist() == pytest.approx([0.0, 2.0])
    assert u["inner_kind"][1].tolist() == pytest.approx([0.0, 2.0])
    # tile 3: the square's area
    assert u["inner_kind"][3].tolist() == pytest.approx([1.0, 0.0])
    # the sets' areas: a tile's strip is its two 2-wide bands along the inner borders
    assert u["strip"].tolist() == pytest.approx([76.0] * 4)
    assert u["inner"].tolist() == pytest.approx([324.0] * 4)
