"""Ornament inputs of issue 21: Appendix A rules at small minimum radii finish, dots in a
rectangle cost about what they cost in a disc (runtime-independent checks)."""

from __future__ import annotations

import numpy as np
import pytest
import shapely

from strew import Region
from strew.ornament import grow_elements
from strew.ornament import _engine


class _Repeat(AssertionError):
    pass


@pytest.fixture
def no_repeated_failure(monkeypatch):
    """Fail at once when a circle centre joins the exclude list twice with no success in
    between: the main loop would then find the same circle again, forever (§4.1's
    exclude list exists to prevent exactly this)."""
    seen: dict[tuple, int] = {}
    add = _engine._Grower.add_exclude

    def checked(self, p):
        key = (round(float(p[0]), 9), round(float(p[1]), 9))
        if seen.get(key) == self.stats["successes"]:
            raise _Repeat(f"circle at {key} failed twice with no success in between")
        seen[key] = self.stats["successes"]
        return add(self, p)

    monkeypatch.setattr(_engine._Grower, "add_exclude", checked)
    return seen


@pytest.mark.parametrize("size, min_radius", [(60.0, 0.5), (100.0, 1.0)])
def test_flowers_at_small_minimum_radii_never_retry_a_failed_circle(no_repeated_failure, size, min_radius):
    orn = grow_elements("flowers", Region.rectangle(size, size), rng=1, min_radius=min_radius)
    st = orn.stats
    assert st["successes"] > 20
    # every iteration either places elements or excludes a new circle; the raster has
    # resolution**2 cells, so a finite run stays far below that many iterations
    assert st["iterations"] < orn.params["resolution"] ** 2 / 4
    assert len(no_repeated_failure) >= st["failures"]


def test_dots_in_a_rectangle_work_like_dots_in_a_disc(no_repeated_failure):
    rect = grow_elements("dots", Region.rectangle(120, 80), rng=1)
    disc = grow_elements("dots", Region(shapely.Point(60, 40).buffer(55.3, 64)), rng=1)
    nr = sum(e.type == "dot" for e in rect.elements)
    nd = sum(e.type == "dot" for e in disc.elements)
    assert nr > 300 and nd > 300
    # the work per dot (loop iterations, failures and rejected circles) is alike
    work_r = (rect.stats["iterations"] + rect.stats["rejected"]) / nr
    work_d = (disc.stats["iterations"] + disc.stats["rejected"]) / nd
    assert work_r < 2 * work_d
    assert np.isfinite(work_r)
