"""The planar map noded strip by strip (issue 19.6, memory) is the map of one global noding."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import strew.program._planar_map as pmod
from strew.program import Curve, Curves, induce


def _topology(curves: Curves, chunk: int, monkeypatch: pytest.MonkeyPatch) -> tuple:
    monkeypatch.setattr(pmod, "CHUNK_SEGMENTS", chunk)
    t = induce(curves)._t
    return (t.vertex_ij.tobytes(), t.edge_ij.flat.tobytes(), t.edge_ij.offsets.tobytes(), t.edge_source.tobytes(),
            t.edge_left.tobytes(), t.edge_right.tobytes(), tuple(p.wkb if p is not None else None for p in t.face_polygons),
            t.face_labels, t.edge_labels)


def _curves(seed: int, n: int, dup: int) -> Curves:
    rng = np.random.default_rng(seed)
    side = 20.0 * np.sqrt(n)
    p = rng.uniform(0, side, (n, 2))
    ang = rng.uniform(0, 2 * np.pi, n)
    q = p + rng.uniform(5, 60, n)[:, None] * np.c_[np.cos(ang), np.sin(ang)]
    cs = [Curve(np.stack([a, b]), left={"L"} if k % 3 == 0 else ()) for k, (a, b) in enumerate(zip(p, q))]
    # overlapping copies (reversed, and half-length collinear pieces), a long line across
    # every strip, a closed polyline
    cs += [Curve(np.stack([q[k], p[k]])) for k in range(dup)]
    cs += [Curve(np.stack([p[k], (p[k] + q[k]) / 2])) for k in range(dup, 2 * dup)]
    cs.append(Curve(np.array([[0.0, side / 2], [side, side / 2 + 1.0]])))
    t = np.linspace(0, 2 * np.pi, 40)
    cs.append(Curve(np.c_[side / 2 + 50 * np.cos(t), side / 3 + 50 * np.sin(t)]))
    return Curves(tuple(cs))


@settings(max_examples=6, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), n=st.integers(150, 450), dup=st.integers(0, 40), chunk=st.integers(40, 300))
def test_strips_give_the_global_map(seed: int, n: int, dup: int, chunk: int) -> None:
    curves = _curves(seed, n, dup)
    with pytest.MonkeyPatch.context() as mp:
        whole = _topology(curves, 10**9, mp)
        strips = _topology(curves, chunk, mp)
    assert strips == whole


def test_strips_cover_every_segment_once() -> None:
    """Strips of unequal size (n not a multiple of the strip count): no segment lost."""
    curves = _curves(7, 1001, 10)
    with pytest.MonkeyPatch.context() as mp:
        whole = _topology(curves, 10**9, mp)
        strips = _topology(curves, 97, mp)
    assert strips == whole
    assert len(whole[0]) > 0
