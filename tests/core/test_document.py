"""The strew document: lossless round trips and validation messages."""

from __future__ import annotations

import json

import numpy as np
import pytest
from strew_testing import arrangements
from hypothesis import given

import strew
from strew import InputError
from strew.io.document import dumps, from_document, loads, to_document


@given(arrangements())
def test_json_round_trip_is_lossless(arr):
    text = dumps(arr)
    back = loads(text)
    assert back.equals(arr)
    assert dumps(back) == text  # JSON -> JSON is byte-exact


def test_round_trip_keeps_region_meta_and_extra(two_kind_arrangement, tmp_path):
    a = two_kind_arrangement.replace(extra={"edges": [[0, 1], [1, 2]]})
    p = tmp_path / "a.json"
    strew.save(a, p)
    b = strew.load(p)
    assert b.equals(a)
    assert b.extra == {"edges": [[0, 1], [1, 2]]}
    assert b.region.area == pytest.approx(96)


def test_nan_in_float_column_is_written_as_null():
    a = strew.Arrangement({"d": strew.Shape.circle(1)}, [0, 0], [0, 1], [0, 0], columns={"w": [1.0, np.nan]})
    doc = json.loads(dumps(a))
    assert doc["elements"]["w"] == [1.0, None]


def base_doc():
    return {
        "format": "strew.arrangement",
        "version": 1,
        "shapes": {"stone": {"paths": [{"points": [[0, 0], [1, 0], [0, 1]], "closed": True}]}},
        "elements": {"kind": ["stone", "stone"], "x": [0, 1], "y": [0, 1], "rotation": [0, 0], "scale": [1, 1]},
        "meta": {},
    }


def mutate(path, value):
    doc = base_doc()
    target = doc
    for key in path[:-1]:
        target = target[key]
    if value is KeyError:
        del target[path[-1]]
    else:
        target[path[-1]] = value
    return doc


@pytest.mark.parametrize(
    "doc, message",
    [
        (mutate(["elements", "x"], KeyError), "elements.x: missing column"),
        (mutate(["elements", "kind"], KeyError), "elements.kind: missing column"),
        (mutate(["elements", "y"], [0]), "elements.y: length 1 does not match elements.kind length 2"),
        (mutate(["elements", "kind"], ["stone", "leaf"]), "elements.kind[1]: unknown kind 'leaf'"),
        (mutate(["elements", "x"], [0, float("nan")]), "elements.x[1]: NaN or inf coordinate"),
        (mutate(["elements", "scale"], [float("inf"), 1]), "elements.scale[0]: NaN or inf coordinate"),
        (mutate(["elements", "x"], [0, "a"]), "elements.x[1]: must be a number"),
        (mutate(["version"], 3), "version: unsupported version 3"),
        (mutate(["version"], 2), "elements.z: missing column (version 2 documents carry"),
        (mutate(["version"], KeyError), "version: missing"),
        (mutate(["format"], "other"), "format: expected 'strew.arrangement'"),
        (mutate(["shapes"], KeyError), "shapes: missing"),
        (mutate(["shapes", "stone", "paths"], [{"points": [[0, 0], [1, float("inf")]]}]), "shapes.stone.paths[0].points: NaN or inf"),
        (mutate(["region"], {"paths": [{"points": [[0, 0], [1, 0]]}]}), "region: no closed path"),
        ([1, 2], "document: must be a JSON object"),
    ],
)
def test_validation_names_the_field(doc, message):
    with pytest.raises(InputError) as err:
        from_document(doc)
    assert message in str(err.value)


def test_malformed_json_and_nan_literals():
    with pytest.raises(InputError, match="malformed JSON"):
        loads("{ not json")
    text = json.dumps(base_doc()).replace('"x": [0, 1]', '"x": [0, NaN]')
    with pytest.raises(InputError, match=r"elements.x\[1\]: NaN or inf"):
        loads(text)


def test_to_document_shape(two_kind_arrangement):
    doc = to_document(two_kind_arrangement)
    assert doc["format"] == "strew.arrangement" and doc["version"] == 1
    assert list(doc["elements"]) == ["kind", "x", "y", "rotation", "scale", "color", "weight"]
    assert doc["shapes"]["bar"]["style"] == {"fill": "#c33"}
