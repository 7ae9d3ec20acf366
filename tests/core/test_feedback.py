"""A result far from what was asked says why (issue 22 point 3)."""

from __future__ import annotations

import subprocess
import sys
import warnings

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import strew
import strew.grow
import strew.pack
from strew import Arrangement, Region, Shape, metrics
from strew._feedback import ResultWarning, suggested_scale


def _star(r=230.0):
    a = np.linspace(0, 2 * np.pi, 10, endpoint=False)
    k = np.where(np.arange(10) % 2 == 0, 1.0, 0.45)
    return Shape.polygon(np.c_[r * k * np.cos(a), r * k * np.sin(a)])


def _overlapping_tessellation(r=10.0, grow_by=1.01):
    """Hexagons drawn 1% too large: every tile covers its neighbours' edges."""
    a = np.arange(6) * np.pi / 3
    hexagon = Shape.polygon(np.c_[grow_by * r * np.cos(a), grow_by * r * np.sin(a)])
    i, j = np.meshgrid(np.arange(6), np.arange(6), indexing="ij")
    xs = (i * 1.5 * r).ravel()
    ys = (j * np.sqrt(3) * r + (i % 2) * np.sqrt(3) * r / 2).ravel()
    return Arrangement({"hex": hexagon}, [0] * len(xs), xs, ys)


def test_pack_with_shapes_large_against_the_region_says_so_and_its_advice_works():
    region = Region.rectangle(470, 470)
    with pytest.warns(ResultWarning, match=r"large against the region .*'star'.*scale (\S+) fits about 200") as rec:
        few = strew.pack.pack({"star": _star()}, region, rng=1)
    assert len(few) < 10
    import re

    s = float(re.search(r"\(scale (\S+) fits", str(rec[0].message)).group(1))
    with warnings.catch_warnings():
        warnings.simplefilter("error", ResultWarning)
        many = strew.pack.pack({"star": _star()}, region, scale=(s, s), rng=1)
    assert len(many) >= 100  # the suggested scale gives a texture, and no warning


def test_pack_says_nothing_when_many_elements_fit():
    with warnings.catch_warnings():
        warnings.simplefilter("error", ResultWarning)
        arr = strew.pack.pack({"sq": Shape.rectangle(4, 4)}, Region.rectangle(60, 60), rng=1)
    assert len(arr) > 50


def test_grow_of_an_overlapping_exemplar_grows_all_it_was_asked_and_says_why():
    ex = _overlapping_tessellation()
    assert metrics.summary(ex)["filled_overlap_pairs"] > 50
    with pytest.warns(ResultWarning, match="exemplar's own elements overlap"):
        out = strew.grow.grow(ex, count=100, rng=1)
    assert len(out) == 100  # was 1, silently
    assert out.meta["params"]["avoid_overlaps"] is False


def test_grow_that_stops_short_says_why():
    ex = _overlapping_tessellation(grow_by=0.98)  # tiles that do not touch: nothing to warn about up front
    with pytest.warns(ResultWarning, match=r"grow: made (\d+) of the 2000 elements asked for: the growth front"):
        out = strew.grow.grow(ex, count=2000, region=Region.rectangle(120, 120), rng=1)
    assert len(out) < 0.9 * 2000


def test_grow_of_a_touching_tessellation_is_quiet():
    with warnings.catch_warnings():
        warnings.simplefilter("error", ResultWarning)
        out = strew.grow.grow(_overlapping_tessellation(grow_by=1.0), count=60, rng=1)
    assert len(out) == 60


def test_cli_prints_the_reason_on_stderr_and_still_writes(tmp_path):
    ex = tmp_path / "tess.svg"
    strew.save(_overlapping_tessellation(), ex)
    out = tmp_path / "out.json"
    r = subprocess.run([sys.executable, "-m", "strew", "grow", str(ex), "--count", "40", "--seed", "1", "--out", str(out), "-q"],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    assert "strew: warning: grow: the exemplar's own elements overlap" in r.stderr
    assert len(strew.load(out)) == 40


@given(st.floats(1e-3, 1e6), st.floats(1e2, 1e9), st.integers(10, 1000))
def test_suggested_scale_is_just_below_the_exact_one(area, region_area, target):
    s = suggested_scale(area, region_area, target)
    exact = np.sqrt(0.5 * region_area / (target * area))
    assert 0.89 * exact <= s <= exact
