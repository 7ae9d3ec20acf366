"""Bounded fuzz of every method's Python entry point (issue 17, point 8).

Degenerate, collinear, duplicate-point, tiny and huge polygons go in as regions, shapes
and exemplars. Each call must either raise a clean :class:`InputError` or return a valid
arrangement (finite columns, positive scales) within a time bound: ``should_cancel``
turns True at the deadline, so a hang shows up as ``Cancelled`` instead of stalling the
suite. A handful of examples per method keeps the whole module within seconds.
"""

from __future__ import annotations

import time
import warnings

import numpy as np
import pytest
from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st

from strew import Arrangement, InputError, Region, Shape
from strew._errors import Cancelled
from strew._limits import limits

DEADLINE_S = 8.0  # per call; generous for a loaded CI machine, far below a hang
WORK_LIMIT = 3000  # elements: larger expected outputs must be refused before starting

# No shrinking: a failing example is reported as found, so the suite's time stays bounded.
FUZZ = settings(max_examples=12, deadline=None, suppress_health_check=list(HealthCheck), derandomize=True,
                phases=(Phase.explicit, Phase.generate), database=None)


@st.composite
def polygons(draw):
    """(n, 2) float: degenerate, collinear, duplicate-point, tiny, huge and plain polygons."""
    kind = draw(st.sampled_from(["plain", "collinear", "duplicate", "tiny", "huge", "sliver", "few", "bowtie", "beyond"]))
    n = draw(st.integers(3, 8))
    base = np.array(draw(st.lists(st.tuples(st.floats(-1, 1), st.floats(-1, 1)), min_size=n, max_size=n)), float)
    if kind == "collinear":
        t = np.array(draw(st.lists(st.floats(-1, 1), min_size=n, max_size=n)))
        base = np.c_[t, 0.5 * t]
    elif kind == "duplicate":
        base = np.repeat(base[: max(1, n // 3)], 3, axis=0)[:n]
    elif kind == "sliver":
        base[:, 1] *= 1e-9
    elif kind == "few":
        base = base[: draw(st.integers(0, 2))]
    elif kind == "bowtie":
        base = np.array([[0, 0], [1, 1], [1, 0], [0, 1]], float)
    scale = {"tiny": 1e-9, "huge": 1e9, "beyond": 1e14}.get(kind, draw(st.sampled_from([1.0, 30.0, 200.0])))
    return base * scale


def _deadline():
    t0 = time.monotonic()
    return lambda: time.monotonic() - t0 > DEADLINE_S


def _valid(arr: Arrangement) -> None:
    assert isinstance(arr, Arrangement)
    for col in ("x", "y", "rotation", "scale"):
        assert np.all(np.isfinite(arr[col])), col
    assert np.all(arr.scale > 0)


def _call(fn, *args, **kwargs):
    """A valid result, or None after a clean InputError; a hang fails."""
    try:
        # repairs of self-intersecting input are announced; the work limit keeps each call
        # small (a run expected to make more elements is refused up front)
        with warnings.catch_warnings(), limits(elements=WORK_LIMIT):
            warnings.simplefilter("ignore")
            out = fn(*args, should_cancel=_deadline(), **kwargs)
    except InputError as exc:
        assert str(exc) and "\n" not in str(exc)
        return None
    except Cancelled:  # pragma: no cover - the failure being looked for
        pytest.fail(f"{getattr(fn, '__name__', fn)}: over the time bound of {DEADLINE_S} s")
    _valid(out)
    assert len(out) <= 4 * WORK_LIMIT  # the estimate is not off by orders of magnitude
    return out


def _region(pts) -> Region | None:
    try:
        return Region.from_paths([pts])
    except InputError:
        return None


def _shape(pts) -> Shape | None:
    try:
        sh = Shape.polygon(pts)
    except InputError:
        return None
    return sh


def _exemplar(pts, spacing: float) -> Arrangement | None:
    """Copies of the polygon on a jittered 4 x 4 grid of the given spacing."""
    sh = _shape(pts)
    if sh is None:
        return None
    g = np.mgrid[0:4, 0:4].reshape(2, -1).T * spacing
    g[:, 0] += 0.3 * spacing * (np.arange(16) % 2)
    try:
        return Arrangement({"p": sh}, [0] * 16, g[:, 0], g[:, 1])
    except InputError:
        return None


SQUARE = Region.rectangle(120, 120)


@FUZZ
@given(pts=polygons())
def test_fuzz_region_and_shape_construction(pts):
    r = _region(pts)
    if r is not None:
        assert r.area > 0 and all(np.isfinite(r.bounds))
    s = _shape(pts)
    if s is not None:
        assert np.all(np.isfinite(s.points))


@FUZZ
@given(shape_pts=polygons(), region_pts=polygons())
def test_fuzz_pack(shape_pts, region_pts):
    from strew.pack import pack

    sh = _shape(shape_pts)
    if sh is None:
        return
    for region in (SQUARE, _region(region_pts)):
        if region is None:
            continue
        out = _call(pack, sh, region, rng=0, max_failures=40)
        if out is not None and len(out):
            from strew.metrics import overlaps

            assert len(overlaps(out)[0]) == 0


@FUZZ
@given(region_pts=polygons())
def test_fuzz_ornament(region_pts):
    from strew.ornament import grow_elements

    region = _region(region_pts)
    if region is None:
        return
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            orn = grow_elements("dots", region, rng=0, max_elements=25, should_cancel=_deadline())
    except InputError:
        return
    except Cancelled:  # pragma: no cover
        pytest.fail("ornament: over the time bound")
    _valid(orn.render("outline"))


@FUZZ
@given(pts=polygons(), spacing=st.sampled_from([1e-6, 0.07, 12.0, 1e6]), region_pts=polygons())
def test_fuzz_grow(pts, spacing, region_pts):
    from strew.grow import grow

    ex = _exemplar(pts, spacing)
    if ex is None:
        return
    _call(grow, ex, count=15, rng=0)
    region = _region(region_pts)
    if region is not None:
        _call(grow, ex, count=15, region=region, rng=0)


@FUZZ
@given(pts=polygons(), spacing=st.sampled_from([1e-6, 0.07, 12.0, 1e6]), region_pts=polygons())
def test_fuzz_synth(pts, spacing, region_pts):
    from strew.synth import synthesize

    ex = _exemplar(pts, spacing)
    if ex is None:
        return
    for region in (Region.rectangle(60, 60), _region(region_pts)):
        if region is not None:
            _call(synthesize, ex, region, rng=0, optimize="none")
