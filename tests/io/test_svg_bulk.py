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


def _rows(rng: np.random.Generator, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Invariant rows of ``n`` objects in a few families of near-copies (so that many pairs
    lie near the tests' thresholds), some lines, some without a signature."""
    fam = rng.integers(0, max(1, n // 4), n)
    base = rng.uniform(0, 1.5, (n + 1, imp._KMAX - 1))[fam]
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
    rows[~valid] = imp._invariants(None)
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
    found = imp._candidate_pairs(rows, valid)
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
        want = [kinds[k] for k in imp._candidates(rows[kinds].reshape(len(kinds), rows.shape[1]), sig, rows[j].tolist())]
        assert got == want, j


def test_candidate_pairs_leave_non_finite_invariants_to_the_one_by_one_test():
    rows, valid = _rows(np.random.default_rng(1), 10)
    valid[:] = True
    rows[3, 7] = np.inf
    assert imp._candidate_pairs(rows, valid) is None


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


@settings(max_examples=300, deadline=None)
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


@settings(max_examples=40, deadline=None)
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
