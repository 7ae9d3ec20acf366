"""The shared periodic contract (issue 18): frame, canonical positions, wrapped images."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from strew import Shape, metrics
from strew import _periodic as P
from strew._errors import InputError
from strew.arrangement import Arrangement


def _dots(xs, ys, r=1.0):
    return Arrangement({"d": Shape.circle(r)}, ["d"] * len(xs), xs, ys)


def test_overlap_across_the_wrap_is_seen_only_with_images():
    a = P.mark(_dots([0.5, 9.5, 5.0], [5.0, 5.0, 5.0]), [0, 0, 10, 10])
    assert len(metrics.overlaps(a)[0]) == 0  # 9 apart in the plane
    pairs, _ = metrics.overlaps(P.images(a))
    assert len(pairs) > 0  # 1 apart across the wrap


@given(
    st.lists(st.floats(-1e4, 1e4, allow_nan=False), min_size=1, max_size=30),
    st.floats(0.5, 100),
    st.floats(0.5, 100),
)
def test_canonical_positions_lie_in_the_half_open_tile(xs, w, h):
    x, y = P.canonical(np.array(xs), np.array(xs[::-1]), [-3.0, 2.0, w, h])
    assert np.all((x >= -3.0) & (x < -3.0 + w))
    assert np.all((y >= 2.0) & (y < 2.0 + h))
    # wrapping moves by whole periods
    k = (np.array(xs) - x) / w
    np.testing.assert_allclose(k, np.round(k), atol=1e-6 * max(1.0, np.abs(k).max()))


def test_tiled_copies_counts_and_period():
    a = P.mark(_dots([1.0, 4.0], [2.0, 7.0]), [0, 0, 10, 10])
    t = P.tiled_copies(a, 3, 2)
    assert len(t) == 12
    assert P.frame(t) is None
    row = np.sort(t.x[np.isclose(t.y, 2.0)])
    np.testing.assert_allclose(row, [-9.0, 1.0, 11.0])
    assert sorted(set(np.round(t.y, 6))) == [2.0, 7.0, 12.0, 17.0]  # an even count puts the original low


def test_rejects_bad_frames():
    with pytest.raises(InputError, match="width and height must be positive"):
        P.mark(_dots([0.0], [0.0]), [0, 0, 0, 5])
    with pytest.raises(InputError, match="not periodic"):
        P.images(_dots([0.0], [0.0]))
    from strew.region import Region

    with pytest.raises(InputError, match="rectangular region"):
        P.frame_of_region(Region.circle(0, 0, 5))
    assert P.frame_of_region(Region.rectangle(8, 6, 1, 2)) == (1.0, 2.0, 8.0, 6.0)
