"""The palette document (§5.5, saved palettes): exemplars side by side and back, with
edited connectivity, the selection and empty exemplars (the hooks the studio saves and
loads its palette with, issue 15.6)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from strew import Arrangement, InputError, Shape, load, save
from strew.synth import Palette, palette_document, split_palette_document
from strew.synth._exemplars import grid, stones, stripes

SHAPES = {"dot": Shape.circle(1.0), "sq": Shape.rectangle(2.0, 2.0)}


def _exemplar(xy: np.ndarray, kinds: np.ndarray) -> Arrangement:
    return Arrangement(SHAPES, kinds, xy[:, 0], xy[:, 1])


_pts = st.lists(st.tuples(st.floats(-500, 500), st.floats(-500, 500), st.integers(0, 1)), min_size=0, max_size=12)


@settings(max_examples=40, deadline=None)
@given(st.lists(_pts, min_size=1, max_size=4), st.floats(0.0, 50.0) | st.none(), st.data())
def test_document_round_trip_restores_every_exemplar(parts, gap, data):
    exemplars = {}
    for i, p in enumerate(parts):
        a = np.array(p, dtype=float).reshape(-1, 3)
        ex = _exemplar(a[:, :2], a[:, 2].astype(int))
        if len(ex) >= 2:
            ex = ex.replace(extra={"connectivity": {"edges": [[0, 1]]}})
        exemplars[f"e{i}"] = ex
    if not any(len(e) for e in exemplars.values()):
        with pytest.raises(InputError, match="every exemplar is empty"):
            palette_document(exemplars)
        return
    sel = data.draw(st.lists(st.sampled_from(sorted(exemplars)), unique=True))
    doc = palette_document(exemplars, gap=gap, selection=sel)
    assert len(doc) == sum(len(e) for e in exemplars.values())
    back, selection = split_palette_document(doc)
    assert list(back) == list(exemplars)  # empty ones too, in order
    assert selection == sel
    for name, ex in exemplars.items():
        got = back[name]
        assert len(got) == len(ex)
        assert np.allclose(got.xy, ex.xy, atol=1e-9 * (1 + np.abs(ex.xy).max(initial=0)))
        assert np.array_equal(got.kind_names, ex.kind_names)
        assert "exemplar" not in got
        assert got.extra == ex.extra


def test_exemplars_lie_side_by_side_without_overlap():
    exemplars = {"grid": grid(), "stripes": stripes(), "stones": stones()}
    doc = palette_document(exemplars)
    tags = np.asarray(doc["exemplar"]).astype(str)
    boxes = [doc.select(tags == n).xy for n in exemplars]
    for a, b in zip(boxes, boxes[1:]):
        assert a[:, 0].max() < b[:, 0].min()
    assert doc.extra["palette"]["names"] == list(exemplars)


def test_palette_methods_use_the_document_and_save_connectivity(tmp_path):
    ex = grid().replace(extra={"connectivity": {"edges": [[0, 1], [1, 2]]}})
    pal = Palette({"g": ex, "s": stripes()})
    doc = pal.to_arrangement(selection=["s"])
    assert doc.extra["palette"]["selection"] == ["s"]
    assert doc.extra["palette"]["connectivity"] == {"g": [[0, 1], [1, 2]]}
    save(doc, tmp_path / "pal.json")
    back = Palette.from_arrangement(load(tmp_path / "pal.json"))
    assert back.names == ("g", "s")
    assert back["g"].extra["connectivity"]["edges"] == [[0, 1], [1, 2]]
    assert np.allclose(back["g"].xy, ex.xy) and np.allclose(back["s"].xy, stripes().xy)
    # an empty exemplar in a document is left out of a Palette (which holds none)
    doc2 = palette_document({"g": grid(), "empty": Arrangement(SHAPES, np.zeros(0, int), [], [])})
    assert Palette.from_arrangement(doc2).names == ("g",)


def test_bad_documents_are_named():
    doc = palette_document({"g": grid()})
    with pytest.raises(InputError, match="palette.offsets.g: must be"):
        split_palette_document(doc.replace(extra={"palette": {"offsets": {"g": "here"}}}))
    with pytest.raises(InputError, match="no 'exemplar' column"):
        split_palette_document(grid())
