"""SVG import in bulk (issue 17.3): the kind candidates found on a grid of all objects'
invariants at once are those of the one-by-one test, object by object."""

from __future__ import annotations

import re

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from strew.io import _svg_flatten as fl
from strew.io import _svg_import as imp
from strew.io import _svg_match as match
from strew._errors import InputError
from strew.shape import Path


def _rows(rng: np.random.Generator, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Invariant rows of ``n`` objects in a few families of near-copies (so that many pairs
    lie near the tests' thresholds), some lines, some without a signature."""
    fam = rng.integers(0, max(1, n // 4), n)
    base = rng.uniform(0, 1.5, (n + 1, match._KMAX - 1))[fam]
    mags = base * rng.uniform(0.97, 1.03, base.shape) + rng.uniform(-0.012, 0.012, base.shape)
    mags = np.abs(mags)
    size = rng.uniform(1, 10, n)
    scale = rng.uniform(0.5, 2, n)
    radius = size**0.5 * rng.uniform(0.98, 1.02, n) * scale
    gyration = 0.5 * size**0.5 * rng.uniform(0.98, 1.02, n) * scale
    tol = rng.uniform(1e-4, 1e-2, n)
    area = np.where(rng.random(n) < 0.8, 1.0, -1.0)
    rows = np.c_[size * scale**2, radius, gyration, tol, area, mags]
    valid = rng.random(n) < 0.95
    rows[~valid] = match._invariants(None)
    return rows, valid


class _Sig:
    """The parts of a signature :func:`_candidates` reads."""

    def __init__(self, row: np.ndarray) -> None:
        self.size, self.radius, self.gyration, self.tolerance = (float(v) for v in row[:4])
        self.is_area = bool(row[4] == 1.0)


@settings(max_examples=40, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), n=st.integers(0, 120))
def test_candidate_pairs_are_the_one_by_one_candidates(seed, n):
    rows, valid = _rows(np.random.default_rng(seed), n)
    found = match._candidate_pairs(rows, valid)
    assert found is not None
    start, earlier = found
    assert len(start) == n + 1 and start[0] == 0 and start[-1] == len(earlier)
    for j in range(n):
        got = earlier[start[j] : start[j + 1]].tolist()
        if not valid[j]:
            assert got == []
            continue
        kinds = [i for i in range(j) if valid[i]]  # the earlier objects, as kinds
        sig = _Sig(rows[j])
        want = [kinds[k] for k in match._candidates(rows[kinds].reshape(len(kinds), rows.shape[1]), sig, rows[j].tolist())]
        assert got == want, j


def test_candidate_pairs_leave_non_finite_invariants_to_the_one_by_one_test():
    rows, valid = _rows(np.random.default_rng(1), 10)
    valid[:] = True
    rows[3, 7] = np.inf
    assert match._candidate_pairs(rows, valid) is None


# -- parsing: the split reading gives what the token-by-token scan gave --------------------
_FLOAT = r"[-+]?[0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?"
_PATH_TOKEN = re.compile(rf"([MmZzLlHhVvCcSsQqTtAa])|({_FLOAT})|[ ,\t\n\r\x0c]+|(.)", re.DOTALL)
_NUMBERS = re.compile(rf"({_FLOAT})|[ ,\t\n\r\x0c]+|(.)", re.DOTALL)


def _scan_numbers(text: str) -> list[float] | None:
    """parse_numbers as it was: one token at a time."""
    out = []
    for num, bad in _NUMBERS.findall(text):
        if bad:
            return None
        if num:
            out.append(float(num))
    return out


def _scan_path(d: str) -> fl.Segments | None:
    """parse_path as it was: one token at a time, the same builder."""
    tokens = _PATH_TOKEN.findall(d)
    b = fl._Builder()
    i, n = 0, len(tokens)
    started = False
    while i < n:
        cmd, num, bad = tokens[i]
        if bad:
            return None
        if not cmd:
            if num:
                return None
            i += 1
            continue
        i += 1
        low = cmd.lower()
        rel = cmd != cmd.upper()
        if low == "z":
            if not started:
                return None
            b.close()
            continue
        if not started and low != "m":
            return None
        started = True
        k = fl._ARGS[low]
        vals: list[str] = []
        while i < n:
            c2, num2, bad2 = tokens[i]
            if bad2 or c2:
                break
            if num2:
                vals.append(num2)
            i += 1
        if not vals or len(vals) % k:
            return None
        if low == "a" and any(vals[j + 3] not in ("0", "1") or vals[j + 4] not in ("0", "1") for j in range(0, len(vals), 7)):
            return None
        f = [float(v) for v in vals]
        for j in range(0, len(f), k):
            ox, oy = (b.cx, b.cy) if rel else (0.0, 0.0)
            if low == "m":
                (b.move if j == 0 else b.line)(f[j] + ox, f[j + 1] + oy)
            elif low == "l":
                b.line(f[j] + ox, f[j + 1] + oy)
            elif low == "h":
                b.line(f[j] + ox, b.cy)
            elif low == "v":
                b.line(b.cx, f[j] + oy)
            elif low == "c":
                b.cubic(f[j] + ox, f[j + 1] + oy, f[j + 2] + ox, f[j + 3] + oy, f[j + 4] + ox, f[j + 5] + oy)
            elif low == "s":
                x1, y1 = b.reflect()
                b.cubic(x1, y1, f[j] + ox, f[j + 1] + oy, f[j + 2] + ox, f[j + 3] + oy)
            elif low == "q":
                b.quad(f[j] + ox, f[j + 1] + oy, f[j + 2] + ox, f[j + 3] + oy)
            elif low == "t":
                x1, y1 = b.reflect()
                b.quad(x1, y1, f[j] + ox, f[j + 1] + oy)
            else:
                b.arc(f[j], f[j + 1], f[j + 2], f[j + 3] == 1.0, f[j + 4] == 1.0, f[j + 5] + ox, f[j + 6] + oy)
    return b.done()


def _same_segments(a: fl.Segments | None, b: fl.Segments | None) -> bool:
    if a is None or b is None:
        return a is b
    return all(np.array_equal(getattr(a, f), getattr(b, f), equal_nan=True) for f in ("code", "pts", "arc", "sub", "closed"))


_NUMBER_TEXT = st.text(alphabet="0123456789.eE+- ,\t\nx", max_size=16)
_PATH_TEXT = st.lists(
    st.one_of(st.sampled_from(list("MmZzLlHhVvCcSsQqTtAa")), st.sampled_from(["0", "1", "01", "-2.5", ".5", "1e2", "3.", "e", "+", " ", ",", "  ", "x"]),
              st.floats(-50, 50, allow_nan=False).map(lambda v: f"{v:.3g}")),
    max_size=40,
).map(" ".join)
_NUM = st.one_of(st.floats(-50, 50, allow_nan=False).map(lambda v: f"{v:.4g}"), st.sampled_from(["0", "1", "-.5", "1e1", "2.5.5", "3-4"]))
_ARGS = {"m": 2, "l": 2, "h": 1, "v": 1, "c": 6, "s": 4, "q": 4, "t": 2, "a": 7, "z": 0}


@st.composite
def _well_formed_path(draw):
    """Mostly valid path data: commands with their numbers, now and then one too few."""
    out = ["M", draw(_NUM), draw(_NUM)]
    for _ in range(draw(st.integers(0, 8))):
        cmd = draw(st.sampled_from(list("MmZzLlHhVvCcSsQqTtAa")))
        k = _ARGS[cmd.lower()] * draw(st.integers(1, 2)) - (1 if draw(st.integers(0, 9)) == 0 else 0)
        if cmd.lower() == "z":
            k = 0
        vals = [draw(_NUM) for _ in range(max(k, 0))]
        if cmd.lower() == "a" and len(vals) >= 5:
            vals[3], vals[4] = draw(st.sampled_from(["0", "1"])), draw(st.sampled_from(["0", "1"]))
        out += [cmd, *vals]
    return draw(st.sampled_from([" ", ","])).join(out)


@settings(max_examples=300, deadline=None)
@given(text=_NUMBER_TEXT)
def test_numbers_are_read_as_the_scan_read_them(text):
    assert fl.parse_numbers(text) == _scan_numbers(text)


@settings(max_examples=150, deadline=None)
@given(d=st.one_of(_PATH_TEXT, _well_formed_path()))
def test_path_data_is_read_as_the_scan_read_it(d):
    for text in (d, d.replace(" ", "")):
        try:
            want = _scan_path(text)
        except ArithmeticError as exc:  # an arc of a radius whose square underflows: both fail alike
            with pytest.raises(type(exc)):
                fl.parse_path(text)
            continue
        assert _same_segments(fl.parse_path(text), want)


@settings(max_examples=20, deadline=None)
@given(ds=st.lists(_well_formed_path(), min_size=1, max_size=12), seed=st.integers(0, 2**32 - 1))
def test_many_elements_flatten_as_each_alone(ds, seed):
    """flatten_many gives every element flatten's subpaths, bit for bit, at its own tolerance."""
    rng = np.random.default_rng(seed)
    tables = []
    for d in ds:
        try:
            segs = fl.parse_path(d)
        except ArithmeticError:
            continue
        if segs is not None:
            tables.append(segs)
    k = int(rng.integers(0, 6))  # polygons and polylines, some with repeated points
    for i in range(k):
        pts = rng.uniform(-5, 5, (int(rng.integers(1, 9)), 2)).round(int(rng.integers(0, 3)))
        tables.append(fl.shape_segments("polygon" if i % 2 else "polyline", {}, " ".join(f"{a},{b}" for a, b in pts)))
    tols = 10 ** rng.uniform(-4, 0.5, len(tables))
    for small in (400, 0):  # flatten's plain-float and array branches
        for segs, tol, got in zip(tables, tols, fl.flatten_many(tables, tols)):
            want = fl.flatten(segs, tol, small=small)
            assert len(got) == len(want)
            for (p, c, cv), (q, d, dv) in zip(got, want):
                assert (c, cv) == (d, dv) and np.array_equal(p, q)
    for got, want in zip(fl.flatten_many(tables, tols, plus_zero=True), fl.flatten_many(tables, tols)):
        assert len(got) == len(want)
        for (p, c, cv), (q, d, dv) in zip(got, want):  # what the identity map gives: -0.0 becomes 0.0
            assert (c, cv) == (d, dv) and np.array_equal(p, q + 0.0) and not np.signbit(p[p == 0]).any()


_POINTS_TEXT = st.one_of(
    st.lists(st.floats(-1e3, 1e3, allow_nan=False).map(lambda v: f"{v:.4g}"), max_size=12).map(" ".join),
    st.lists(st.sampled_from(["1", "-2", "3.5", ".5", "-.25", "1e3", "1E-2", "+4", "0", "-0", "007", "1.", "1.e5", ".5.5", "1-2", "e", "1e", "+", "1e5.5",
                              "1e999", "x", " ", ",", "\n", ",,"]), max_size=12).map(" ".join),
    _NUMBER_TEXT,
)


@settings(max_examples=150, deadline=None)
@given(texts=st.lists(_POINTS_TEXT, min_size=1, max_size=8), polygon=st.lists(st.booleans(), min_size=8, max_size=8))
def test_many_points_lists_read_as_each_alone(texts, polygon):
    """points_many gives each text shape_segments' table, bit for bit (signs of zero too),
    or leaves all of them to it."""
    got = fl.points_many(texts, polygon[: len(texts)])
    if got is None:  # left to the one-by-one reading: only when some text is not a plain list
        assert any(fl.parse_numbers(t) is None or len(fl.parse_numbers(t)) != len(t.replace(",", " ").split()) for t in texts)
        return
    for text, closed, segs in zip(texts, polygon, got):
        want = fl.shape_segments("polygon" if closed else "polyline", {}, text)
        assert _same_segments(segs, want)
        if segs is not None and want is not None:
            assert np.array_equal(np.signbit(segs.pts), np.signbit(want.pts))


def test_plain_points_lists_are_read_in_bulk():
    texts = ["0,0 4,0 4,3", "1 2 3 4", "", "-0,-1.5e2 7,8 9,10 11", "5,5"]
    got = fl.points_many(texts, [True, False, True, True, False])
    assert got is not None
    assert got[0].closed.tolist() == [True] and got[0].pts[:, 3].tolist() == [[4.0, 0.0], [4.0, 3.0]]
    assert got[1].closed.tolist() == [False] and len(got[1].code) == 1
    assert len(got[2].code) == 0 and len(got[4].code) == 0  # no segment
    assert got[3] is None  # an odd count: svgelements' reading
    assert fl.points_many(["1,2 3,4", "1 inf 2 3"], [True, True]) is None


@settings(max_examples=40, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), n=st.integers(1, 12))
def test_control_outlines_in_bulk_are_each_alone(seed, n):
    """The bulk control-outline hashes and points equal the one-object ones (they are
    looked up in one dictionary)."""
    rng = np.random.default_rng(seed)
    ds = ["M0,0 L5,1 L3,4 Z", "M0,0 C2,3 5,3 6,0 Q3,-2 0,0 Z", "M1,1 L4,1 M5,5 L6,7 L8,8 Z", "M0,0 A2,2 0 0 1 4,0 Z", "M0,0 L0,0 Z", "M0,0 Q1,1 2,0 T4,0 L4,4"]
    items = []
    for _ in range(n):
        r = rng.random()
        if r < 0.5:
            segs = fl.parse_path(ds[int(rng.integers(0, len(ds)))])
        else:
            segs = fl.shape_segments("polygon" if r < 0.75 else "polyline", {}, " ".join(f"{v:.2f}" for v in rng.uniform(-5, 5, 2 * int(rng.integers(1, 8)))))
        own = rng.uniform(-2, 2, (2, 3)) if rng.random() < 0.7 else np.array([[1.0, 0.0, 3.0], [0.0, 1.0, 4.0]])
        items.append(([None, "leaf", ""][int(rng.integers(0, 3))], segs, own))
    state, digest = match._outline_digests(items)
    for item, got, st_, dg in zip(items, match._control_outlines(items), state.tolist(), digest.tolist()):
        want = match.control_outline_of(*item)
        assert (got is None) == (want is None) == (st_ == 0)
        if got is not None:
            assert got[0] == want[0] and np.array_equal(got[1], want[1])
    # equal hashes, equal digests (objects whose digest is unique need no hash)
    keyed = [(o[0][1:], dg) for o, dg in zip(match._control_outlines(items), digest.tolist()) if o is not None]
    for a, da in keyed:
        for b, db in keyed:
            if a == b:
                assert da == db


def test_invariant_rows_in_bulk_are_each_alone():
    rng = np.random.default_rng(4)
    batch = []
    for _ in range(300):
        k = int(rng.integers(3, 9))
        t = np.sort(rng.uniform(0, 2 * np.pi, k))
        r = rng.uniform(0.01, 600, k) * 10.0 ** int(rng.integers(-3, 4))
        batch.append([Path(np.c_[r * np.cos(t), r * np.sin(t)], bool(rng.random() < 0.8))])
    sigs = [*match._signatures(batch), None]
    for sig in sigs:
        if sig is not None:
            sig.tolerance = float(rng.uniform(0, 1))
    assert sum(s is not None for s in sigs) > 250
    want = np.array([match._invariants(s) for s in sigs])
    assert np.array_equal(match._invariants_many(sigs), want, equal_nan=True)


# -- whole files: kinds and poses of known drawings ----------------------------------------
def _poly(rng: np.random.Generator) -> np.ndarray:
    """A star-shaped polygon (simple) with no rotational symmetry, about its centroid."""
    k = int(rng.integers(5, 9))
    t = np.sort(rng.uniform(0, 2 * np.pi, k))
    return rng.uniform(2, 6, (k, 1)) * np.c_[np.cos(t), np.sin(t)]


@settings(max_examples=10, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), kinds=st.integers(1, 4), n=st.integers(1, 60))
def test_copies_are_found_with_their_poses(seed, kinds, n):
    """Copies of a few polygons, moved by a transform or with the move written into their
    points (some from another first vertex: found by matching only), among distinct polygons: one kind per polygon, and each copy's pose relative
    to its kind's first copy is the one drawn (1e-6); bulk reading equals one by one."""
    from strew.io.svg import read_svg

    rng = np.random.default_rng(seed)
    protos = [_poly(rng) for _ in range(kinds)]
    parts, truth = [], []
    for i in range(n):
        x, y = rng.uniform(0, 500, 2)
        a, s = rng.uniform(-np.pi, np.pi), rng.uniform(0.5, 2)
        if rng.random() < 0.25:  # a shape of its own
            pts = _poly(rng) * s + (x, y)
            parts.append('<polygon points="' + " ".join(f"{p:.6f},{q:.6f}" for p, q in pts) + '"/>')
            truth.append(None)
            continue
        j = int(rng.integers(kinds))
        r = rng.random()
        if r < 0.6:  # coordinates written into the path, from another vertex now and then
            c, sn = np.cos(a), np.sin(a)
            pts = s * protos[j] @ np.array([[c, sn], [-sn, c]]) + (x, y)
            if r < 0.3:  # not the same control outline: found by matching only
                pts = np.roll(pts, int(rng.integers(1, len(pts))), axis=0)
            parts.append('<path d="M' + " L".join(f"{p:.9f},{q:.9f}" for p, q in pts) + ' Z"/>')
        else:
            pts = " ".join(f"{p:.9f},{q:.9f}" for p, q in protos[j])
            parts.append(f'<polygon transform="translate({x:.9f} {y:.9f}) rotate({np.degrees(a):.9f}) scale({s:.9f})" points="{pts}"/>')
        truth.append((j, x, y, a, s))
    text = '<svg xmlns="http://www.w3.org/2000/svg">' + "".join(parts) + "</svg>"
    arr = read_svg(text)
    with pytest.MonkeyPatch.context() as m:
        m.setattr(imp, "_MAX_BATCH", 1)
        single = read_svg(text)
    assert arr.kinds == single.kinds and np.array_equal(arr.kind, single.kind)
    for f in ("x", "y", "scale"):
        u, v = getattr(arr, f), getattr(single, f)
        assert np.all(np.abs(u - v) <= 1e-9 * np.maximum(1.0, np.abs(v)))
    # one kind per prototype used, one per distinct polygon
    used = {t[0] for t in truth if t is not None}
    assert len(arr.kinds) == len(used) + sum(t is None for t in truth)
    names = [arr.kinds[k] for k in arr.kind]
    first: dict[int, int] = {}
    for i, t in enumerate(truth):
        if t is None:
            continue
        j, x, y, a, s = t
        if j not in first:
            first[j] = i
            continue
        f = first[j]
        assert names[i] == names[f]
        # relative pose: the same between the drawn and the read
        _, x0, y0, a0, s0 = truth[f]
        assert abs(arr.scale[i] / arr.scale[f] - s / s0) <= 1e-6 * s / s0
        assert abs(np.angle(np.exp(1j * ((arr.rotation[i] - arr.rotation[f]) - (a - a0))))) <= 1e-6
        # the kind's origin maps to the element's position: the drawn copy's image of the
        # first copy's position relative to its own origin
        c0, s0n = np.cos(a0), np.sin(a0)
        local = np.array([arr.x[f] - x0, arr.y[f] - y0]) @ np.array([[c0, s0n], [-s0n, c0]]).T / s0
        c, sn = np.cos(a), np.sin(a)
        want = s * np.array([[c, -sn], [sn, c]]) @ local + (x, y)
        assert np.allclose([arr.x[i], arr.y[i]], want, rtol=0, atol=1e-6 * 500)


def test_straight_shapes_made_at_once_are_what_shape_makes():
    """read_svg makes the shapes of straight kinds in one pass (Shape._checked): the same
    points as Shape's own checks give, read-only and contiguous; points beyond the
    coordinate limit are still refused by Shape's message."""
    from strew.io.svg import read_svg
    from strew.shape import Shape

    rng = np.random.default_rng(7)
    polys = []
    for i in range(40):
        k = int(rng.integers(3, 8))
        t = np.sort(rng.uniform(0, 2 * np.pi, k))
        pts = np.c_[np.cos(t), np.sin(t)] * rng.uniform(1, 5, k)[:, None] + rng.uniform(0, 500, 2)
        if i % 5 == 0:  # the first point written again at the end
            pts = np.r_[pts, pts[:1]]
        tag = "polyline" if i % 7 == 0 else "polygon"
        polys.append(f'<{tag} points="{" ".join(f"{a:.3f},{b:.3f}" for a, b in pts)}"/>')
    arr = read_svg('<svg xmlns="http://www.w3.org/2000/svg">' + "".join(polys) + "</svg>")
    assert len(arr.kinds) >= 30
    for shape in arr.shapes.values():
        ref = Shape(shape.paths, shape.d, shape.style, shape.labels)
        assert len(ref.paths) == len(shape.paths)
        for p, q in zip(shape.paths, ref.paths):
            assert p.closed == q.closed and np.array_equal(p.points, q.points)
            assert not p.points.flags.writeable and p.points.flags.c_contiguous and p.points.dtype == np.float64
    huge = '<svg xmlns="http://www.w3.org/2000/svg"><polygon points="0,0 1000,0 1000,1000" transform="scale(1e10)"/></svg>'
    with pytest.raises(InputError, match="coordinate magnitude over"):
        read_svg(huge)


@settings(max_examples=60, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), grid=st.sampled_from([3, 5, 50]), shift=st.sampled_from([0.0, 1e6, 3e7]))
def test_rings_found_simple_are_valid_polygons(seed, grid, shift):
    """A ring _surely_simple calls simple is a valid polygon of positive area (GEOS's own
    verdict); on rings of points on a small integer grid (repeated points, spikes, straight
    vertices, touching edges) and far from the origin (rounding)."""
    import shapely

    rng = np.random.default_rng(seed)
    lens = rng.integers(3, match._SIMPLE_MAX + 3, 200)
    coords = rng.integers(0, grid, (int(lens.sum()), 2)) * rng.uniform(0.01, 10) + shift
    sure = match._surely_simple(coords, lens)
    polys = shapely.polygons(shapely.linearrings(coords, indices=np.repeat(np.arange(len(lens)), lens)))
    truth = shapely.is_valid(polys) & (shapely.area(polys) > 0)
    assert not (sure & ~truth).any()
    assert not sure[lens > match._SIMPLE_MAX].any()


def test_signatures_of_rings_found_simple_are_shapelys():
    """Signatures made without shapely for rings found simple (their outlines made when
    asked) equal those made through shapely's validity test, field for field."""
    import shapely

    rng = np.random.default_rng(11)
    batch = []
    for i in range(300):
        k = int(rng.integers(3, 20))
        if i % 3:  # star-shaped, rounded (now and then self-intersecting)
            t = np.sort(rng.uniform(0, 2 * np.pi, k))
            pts = np.round(rng.uniform(2, 6, (k, 1)) * np.c_[np.cos(t), np.sin(t)] + rng.uniform(0, 1000, 2), 2)
        else:  # degenerate
            pts = rng.integers(0, 4, (k, 2)).astype(float)
        batch.append([Path(pts, True)])
    new = match._signatures(batch)
    with pytest.MonkeyPatch.context() as m:
        m.setattr(match, "_SIMPLE_MAX", 0)
        old = match._signatures(batch)
    assert sum(s is not None and s.outline is None for s in new) > 100  # the shortcut was taken
    for a, b in zip(new, old):
        assert (a is None) == (b is None)
        if a is None:
            continue
        assert (a.size, a.is_area, a.gyration, a.radius) == (b.size, b.is_area, b.gyration, b.radius)
        assert np.array_equal(a.centroid, b.centroid) and np.array_equal(a.moments, b.moments) and np.array_equal(a.points, b.points)
        assert shapely.equals_exact(match._outline(a), b.outline, tolerance=0)


@st.composite
def _plain_objects(draw):
    """SVG objects that carry geometry attributes only (some repeated, some moved copies
    written into their numbers, some self-intersecting, a few in a group)."""
    rng = np.random.default_rng(draw(st.integers(0, 2**32 - 1)))
    protos = [rng.uniform(-5, 5, (int(rng.integers(3, 7)), 2)) for _ in range(3)]
    out = []
    for _ in range(draw(st.integers(1, 30))):
        r = rng.random()
        pts = protos[int(rng.integers(3))]
        if r < 0.3:  # a moved, turned, scaled copy of a prototype
            a, s = rng.uniform(-3, 3), rng.uniform(0.5, 2)
            pts = s * pts @ np.array([[np.cos(a), np.sin(a)], [-np.sin(a), np.cos(a)]]) + rng.uniform(0, 300, 2)
        elif r < 0.5:  # a shape of its own
            pts = rng.uniform(0, 300, (int(rng.integers(3, 9)), 2))
        text = " ".join(f"{x:.3f},{y:.3f}" for x, y in pts)
        tag = rng.choice(["polygon", "polyline", "path", "rect", "circle"])
        if tag == "path":
            out.append(f'<path d="M{text.replace(" ", " L")} Z"/>')
        elif tag == "rect":
            out.append(f'<rect x="{pts[0, 0]:.3f}" y="{pts[0, 1]:.3f}" width="{abs(pts[1, 0]) + 1:.3f}" height="{abs(pts[1, 1]) + 0.5:.3f}"/>')
        elif tag == "circle":
            out.append(f'<circle cx="{pts[0, 0]:.3f}" cy="{pts[0, 1]:.3f}" r="{abs(pts[1, 0]) + 1:.3f}"/>')
        else:
            out.append(f'<{tag} points="{text}"/>')
    if len(out) > 3 and draw(st.booleans()):  # some in a group with a transform
        out = out[:-3] + ['<g transform="translate(5 7) rotate(30)">'] + out[-3:] + ["</g>"]
    return out


@settings(max_examples=40, deadline=None)
@given(objects=_plain_objects())
def test_objects_of_geometry_only_read_as_the_general_path_reads_them(objects):
    """Objects with geometry attributes only skip the walk's and prepare's lookups of names,
    transforms and styles (issue 17.3): the same arrangement, bit for bit, as the same
    objects each given an attribute that means nothing to the reader (``class``), which
    sends them through every lookup."""
    from strew.io.svg import read_svg

    def doc(objs):
        return '<svg xmlns="http://www.w3.org/2000/svg">' + "".join(objs) + "</svg>"

    marked = [o.replace("/>", ' class="c"/>', 1) if not o.startswith(("<g", "</g")) else o for o in objects]
    try:
        fast = read_svg(doc(objects))
    except InputError as exc:
        with pytest.raises(InputError, match=re.escape(str(exc).split(":", 1)[1].strip())):
            read_svg(doc(marked))
        return
    slow = read_svg(doc(marked))
    assert fast.kinds == slow.kinds and np.array_equal(fast.kind, slow.kind)
    for f in ("x", "y", "rotation", "scale"):
        assert np.array_equal(getattr(fast, f), getattr(slow, f))
    assert fast.columns.keys() == slow.columns.keys()
    assert all(np.array_equal(fast.columns[c], slow.columns[c]) for c in fast.columns)
    for name in fast.kinds:
        a, b = fast.shapes[name], slow.shapes[name]
        assert a.d == b.d and len(a.paths) == len(b.paths)
        assert all(p.closed == q.closed and np.array_equal(p.points, q.points) for p, q in zip(a.paths, b.paths))
