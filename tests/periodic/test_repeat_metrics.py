"""Repeat checks (issue 18 point 5): overlaps across the wrap, edge strips against the interior."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from strew import Shape, metrics
from strew import _periodic as P
from strew._errors import InputError
from strew.arrangement import Arrangement
from strew.region import Region


def torus_darts(seed, r, w, h):
    """Discs of radius r thrown on the torus w x h (darts per unit area fixed, so tiles of any
    size have one density), none within 2r of another across the wrap."""
    rng = np.random.default_rng(seed)
    cand = rng.uniform([0, 0], [w, h], size=(int(0.5 * w * h), 2))
    pts = np.zeros((0, 2))
    for p in cand:
        if len(pts):
            d = np.hypot(P.wrap_delta(pts[:, 0] - p[0], w), P.wrap_delta(pts[:, 1] - p[1], h))
            if d.min() < 2 * r:
                continue
        pts = np.vstack([pts, p])
    a = Arrangement({"d": Shape.circle(r), "e": Shape.rectangle(1.2 * r, 1.2 * r)}, np.where(np.arange(len(pts)) % 3 == 0, "e", "d"), pts[:, 0], pts[:, 1])
    return P.mark(a, [0, 0, w, h])


@pytest.fixture(scope="module")
def tile():
    return torus_darts(1, 1.5, 120, 100)


def _trimmed(a):
    """The same tile made without wrapping: elements crossing the frame dropped."""
    w, h = P.frame(a)[2:]
    keep = (a.x > 1.5) & (a.x < w - 1.5) & (a.y > 1.5) & (a.y < h - 1.5)
    return a.select(np.flatnonzero(keep)).replace(meta={}, region=Region.rectangle(w, h))


def test_a_torus_tile_has_no_overlaps_and_even_edges(tile):
    r = metrics.repeat_report(tile)
    assert r["count"] == len(tile)
    assert r["overlaps"] == {"inside": 0, "across": 0, "stroke_crossings_inside": 0, "stroke_crossings_across": 0}
    assert abs(r["density"]["ratio"] - 1) < 0.1
    assert abs(r["coverage"]["ratio"] - 1) < 0.1
    assert r["kind_fractions"]["max_difference"] < 0.05
    # an element crosses the edge: the tile's wrapped copies are really used
    assert len(P.images(tile)) > len(tile)


def test_a_tile_made_without_wrapping_thins_at_its_edges(tile):
    r = metrics.repeat_report(_trimmed(tile), tile=P.frame(tile))
    assert r["density"]["ratio"] < 0.85
    assert r["coverage"]["ratio"] < 0.85


def test_overlaps_across_the_wrap_are_counted_once_per_pair():
    d = Shape.circle(1.0)
    # 0 and 1 meet across the left/right seam; 2 meets 3 inside; 4 meets its own copy (tile 1.5 high)
    a = Arrangement({"d": d}, ["d"] * 2, [0.5, 9.6], [5.0, 5.0])
    r = metrics.wrap_overlaps(P.mark(a, [0, 0, 10, 10]))
    assert (r["across"], r["inside"]) == (1, 0)
    assert r["pairs"].tolist() == [[0, 1, -1, 0]]
    b = Arrangement({"d": d}, ["d"] * 3, [0.5, 9.6, 5.0], [5.0, 5.0, 5.5])
    r = metrics.wrap_overlaps(P.mark(b, [0, 0, 10, 10]))
    assert (r["across"], r["inside"]) == (1, 0)
    c = Arrangement({"d": d}, ["d"] * 2, [3.0, 4.0], [5.0, 5.0])
    r = metrics.wrap_overlaps(P.mark(c, [0, 0, 10, 10]))
    assert (r["across"], r["inside"]) == (0, 1)
    own = Arrangement({"d": d}, ["d"], [5.0], [0.5])
    r = metrics.wrap_overlaps(P.mark(own, [0, 0, 10, 1.5]))
    assert r["across"] == 1 and r["pairs"][:, :2].tolist() == [[0, 0]]


@settings(max_examples=25, deadline=None)
@given(st.lists(st.tuples(st.floats(0, 20), st.floats(0, 12)), min_size=2, max_size=12), st.floats(0.3, 2.0))
def test_wrap_overlaps_agree_with_a_5x5_block(pts, r):
    """Each overlap of the repeat is one pair: the pairs of a 5 x 5 block that touch its
    centre tile, counted with their period, give the same set."""
    xy = np.array(pts)
    a = P.mark(Arrangement({"d": Shape.circle(r)}, ["d"] * len(xy), xy[:, 0], xy[:, 1]), [0, 0, 20, 12])
    got = metrics.wrap_overlaps(a)
    n = len(a)
    big = P.tiled_copies(a, 5, 5)
    pairs, _ = metrics.overlaps(big)
    block = np.arange(len(big)) // n  # copy number; 12 is the centre of 5 x 5
    offs = P.translations(5, 5).astype(int)
    keys = set()
    for p, q in pairs:
        if block[p] != 12 and block[q] != 12:
            continue
        if block[p] != 12:
            p, q = q, p
        i, j, o = p % n, q % n, tuple(offs[block[q]])
        if i > j or (i == j and o < (0, 0)):
            i, j, o = j, i, (-o[0], -o[1])
        keys.add((i, j, *o))
    assert set(map(tuple, got["pairs"].tolist())) == keys
    assert got["inside"] + got["across"] == len(keys)


def test_seam_fidelity_against_an_exemplar(tile):
    e = torus_darts(5, 1.5, 60, 60)
    ex = e.replace(meta={}, region=Region.rectangle(60, 60))
    good = metrics.repeat_report(tile, ex)["fidelity"]
    bad = metrics.repeat_report(_trimmed(tile), ex, tile=P.frame(tile))["fidelity"]
    assert good["seam_windows"] > 0 and good["interior_windows"] > 0
    assert good["seam_failing"] == 0.0
    assert good["ratio"] < 1.5
    assert bad["seam"] > 2 * good["seam"]  # the thinned seam reads as another texture


def test_bad_input():
    a = Arrangement({"d": Shape.circle(1)}, ["d"], [1.0], [1.0])
    with pytest.raises(InputError, match="not periodic"):
        metrics.repeat_report(a)
    with pytest.raises(InputError, match="strip"):
        metrics.repeat_report(P.mark(a, [0, 0, 10, 10]), strip=6)
    empty = P.mark(a.select([]), [0, 0, 10, 10])
    r = metrics.repeat_report(empty)
    assert r["count"] == 0 and r["overlaps"]["across"] == 0
