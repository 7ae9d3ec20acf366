"""Stripes snapped to a periodic tile stay within stated bounds (issue 18 follow-up).

`_snap_stripes` turns a stripes set onto the tile's lattice of repeats. Rounding the
lattice vector alone turned the lines by 65 degrees for angle 2, widths 21 and 40 (three
face labels) on a 100 x 220 tile. The snap now turns by at most 15 degrees and keeps the
widths within a factor 2. It picks the in-bounds vector of least cost, or it refuses and
names the nearest reachable angle.
"""

import math
import re
import subprocess
import sys
import textwrap

import numpy as np
import pytest
import shapely
from hypothesis import example, given
from hypothesis import strategies as st

from strew import _periodic as P
from strew import metrics
from strew._errors import InputError
from strew.program import run
from strew.program._operators import _snap_stripes, set_face_labels, stripes_properties
from strew.region import Region

MAX_TURN = math.radians(15.0)  # the bounds _snap_stripes documents
MAX_RATIO = 2.0


def _lattice(p, period, w, h):
    """Every lattice vector (k, l) whose period is at least half the asked one, with its
    turn (radians), widths' ratio and cost |period (k / w, l / h) - n0|^2."""
    n0 = np.array([-math.sin(p.angle), math.cos(p.angle)])
    kmax, lmax = math.ceil(MAX_RATIO * w / period) + 1, math.ceil(MAX_RATIO * h / period) + 1
    k, l = (a.ravel().astype(float) for a in np.meshgrid(np.arange(-kmax, kmax + 1), np.arange(-lmax, lmax + 1)))
    keep = (k != 0) | (l != 0)
    k, l = k[keep], l[keep]
    v = np.stack([k / w, l / h])
    length = np.hypot(v[0], v[1])
    turn = np.arccos(np.clip(n0 @ v / length, -1.0, 1.0))
    ratio = 1.0 / (period * length)
    cost = (period * v[0] - n0[0]) ** 2 + (period * v[1] - n0[1]) ** 2
    inside = (turn <= MAX_TURN + 1e-12) & (ratio >= 1 / MAX_RATIO - 1e-12) & (ratio <= MAX_RATIO + 1e-12)
    return k, l, turn, ratio, cost, inside


def test_the_case_hypothesis_found_is_refused_with_the_nearest_reachable_angle():
    p = set_face_labels(stripes_properties(2.0, 21, 40), "a", "b", "c")
    with pytest.raises(InputError) as err:
        _snap_stripes(p, (0, 0, 100, 220))
    msg = str(err.value)
    assert "angle 2 rad" in msg and "100 x 220 tile" in msg and "15 deg" in msg
    near = float(re.search(r"nearest reachable angle is (-?[0-9.]+) rad", msg).group(1))
    assert near == pytest.approx(math.pi / 2, abs=1e-3)  # (k, l) = (-1, 0): a turn of 24.6 degrees
    # taking the advice works: that angle snaps within the bounds on this tile
    q = _snap_stripes(set_face_labels(stripes_properties(near, 21, 40), "a", "b", "c"), (0, 0, 100, 220))
    assert math.cos(q.angle - near) >= math.cos(MAX_TURN)
    assert 1 / MAX_RATIO <= q.widths[0] / 21 <= MAX_RATIO


@given(st.floats(-3.2, 3.2), st.floats(20, 300), st.floats(100, 900), st.floats(100, 900))
@example(2.0, 61.0, 100.0, 220.0)  # the repeat, 183, as one width
@example(-0.77, 70.0 / 3 * 2, 100.0, 100.0)  # rounding turned this one 44 degrees
def test_the_snap_is_the_least_cost_lattice_vector_within_the_bounds(angle, width, w, h):
    p = set_face_labels(stripes_properties(angle, width), "a", "b", "c")
    period = 3 * width  # one width, three labels
    n0 = np.array([-math.sin(angle), math.cos(angle)])
    k0, l0 = round(w * n0[0] / period), round(h * n0[1] / period)
    k, l, turn, ratio, cost, inside = _lattice(p, period, w, h)
    if k0 == 0 and l0 == 0:
        with pytest.raises(InputError, match="smaller than two stripes"):
            _snap_stripes(p, (0, 0, w, h))
        return
    if not inside.any():
        with pytest.raises(InputError, match="nearest reachable angle"):
            _snap_stripes(p, (0, 0, w, h))
        return
    q = _snap_stripes(p, (0, 0, w, h))
    pn = q.widths[0] * 3
    v = np.array([-math.sin(q.angle), math.cos(q.angle)]) / pn  # the snapped frequency (k / w, l / h)
    kq, lq = v[0] * w, v[1] * h
    assert abs(kq - round(kq)) < 1e-7 and abs(lq - round(lq)) < 1e-7  # a lattice vector
    got = (period * v[0] - n0[0]) ** 2 + (period * v[1] - n0[1]) ** 2
    assert got <= cost[inside].min() + 1e-9  # the least cost within the bounds
    assert math.acos(min(1.0, float(n0 @ v) * pn)) <= MAX_TURN + 1e-9
    assert 1 / MAX_RATIO - 1e-9 <= pn / period <= MAX_RATIO + 1e-9
    at = (k == k0) & (l == l0)
    if inside[at].all():  # where rounding was within the bounds, the snap is unchanged
        assert (round(kq), round(lq)) == (k0, l0)


SCRIPT = textwrap.dedent(
    """
    from strew.program import *

    steep = stripes_partition(set_face_labels(stripes_properties(-0.77, 70), "a", "b"))
    issue = stripes_partition(set_face_labels(stripes_properties(2.0, 21, 40), "a", "b", "c"))
    grid = grid_partition(set_face_labels(stripes_properties(2.0, 21, 40), "a", "b", "c"),
                          stripes_properties(0.3, 30), CROP_ADD_BOUNDARY)
    """
)


@pytest.fixture(scope="module")
def script(tmp_path_factory):
    path = tmp_path_factory.mktemp("snap18i") / "snap18i_script.py"
    path.write_text(SCRIPT)
    return path


def test_a_small_tile_keeps_the_direction_and_still_repeats(script):
    """Rounding turned these stripes 44 degrees on a 100 x 100 tile; the snap keeps them
    within the bound, and the 3 x 3 copies still tile the plane without gaps or overlaps."""
    arr = run(script, Region.rectangle(100, 100), rng=1, name="steep", periodic=True)
    edges = arr.select(np.flatnonzero(np.asarray(arr["cell"]) == "edge"))
    slanted = 0
    for g in edges.geometry:
        xy = np.asarray(g.coords)
        d = xy[-1] - xy[0]
        if abs(d[0]) < 1e-9 or abs(d[1]) < 1e-9:
            continue  # the tile's outline
        slanted += 1
        assert abs(math.sin(math.atan2(d[1], d[0]) - -0.77)) <= math.sin(MAX_TURN)
    assert slanted >= 1
    faces = arr.select(np.flatnonzero(np.asarray(arr["cell"]) == "face"))
    tiled = P.tiled_copies(faces, 3, 3)
    assert shapely.union_all(tiled.geometry).area == pytest.approx(9 * 100 * 100, rel=1e-9)
    assert len(metrics.overlaps(tiled)[0]) == 0


@pytest.mark.parametrize("name", ["issue", "grid"])
def test_cli_refuses_with_exit_2_and_names_the_nearest_angle(script, tmp_path, name):
    out = tmp_path / "t.json"
    res = subprocess.run([sys.executable, "-m", "strew", "run", str(script), "--name", name, "--size", "100x220",
                          "--periodic", "--out", str(out)], capture_output=True, text=True)
    assert res.returncode == 2, res.stderr
    assert "100 x 220 tile" in res.stderr and "nearest reachable angle is 1.5708 rad" in res.stderr
    assert not out.exists()
