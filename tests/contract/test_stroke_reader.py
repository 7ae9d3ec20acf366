"""One stroke reader for grow's tools and synth's brush (issue 15 point 5)."""

from __future__ import annotations

import json

import numpy as np
import pytest

from strew import InputError
from strew.grow._tools import load_strokes
from strew.io.strokes import read_strokes
from strew.synth._stroke import read_stroke

HOLED_SVG = """<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">
<path d="M 10 10 L 90 10 L 90 90 L 10 90 Z M 40 40 L 40 60 L 60 60 L 60 40 Z" fill="black"/>
</svg>"""


def test_grow_and_synth_read_a_holed_outline_alike(tmp_path):
    f = tmp_path / "holed.svg"
    f.write_text(HOLED_SVG)
    grow, synth = load_strokes(f), read_stroke(f)
    # both rings: the hole's outline is a drawn line (synth used to drop it)
    assert len(synth) == len(grow) == 2
    for a, b in zip(grow, synth):
        assert np.array_equal(a, b)
    inner = min(synth, key=lambda s: np.ptp(s[:, 0]))
    assert np.allclose(np.ptp(inner, axis=0), [20, 20])


@pytest.mark.parametrize(
    "doc",
    [
        [[0, 0], [5, 0], [5, 5]],
        {"points": [[0, 0], [5, 0], [5, 5]]},
        {"paths": [{"points": [[0, 0], [5, 0], [5, 5]]}]},
        {"paths": [[[0, 0], [5, 0], [5, 5]]]},
    ],
)
def test_json_shapes_read_the_same_by_both_methods(tmp_path, doc):
    f = tmp_path / "s.json"
    f.write_text(json.dumps(doc))
    for reader in (load_strokes, read_stroke):
        (s,) = reader(f)
        assert np.array_equal(s, [[0, 0], [5, 0], [5, 5]])


def test_closed_path_repeats_its_first_point(tmp_path):
    f = tmp_path / "s.json"
    f.write_text(json.dumps({"paths": [{"points": [[0, 0], [5, 0], [5, 5]], "closed": True}]}))
    (s,) = read_stroke(f)
    assert np.array_equal(s[-1], s[0]) and len(s) == 4


@pytest.mark.parametrize(
    ("doc", "field"),
    [
        ({"paths": [{"points": [[0, 0]]}, {"points": [[0, "x"]]}]}, "paths[1].points"),
        ({"paths": [{"points": [[0, 0]]}, {"points": [[0, float("nan")]]}]}, "paths[1].points"),
        ({"paths": [[0, 1, 2]]}, "paths[0]"),
        ({"paths": 3}, "paths"),
        ({"points": []}, "points"),
        ({"paths": []}, "no stroke found"),
    ],
)
def test_messages_name_the_field_and_the_use(tmp_path, doc, field):
    f = tmp_path / "bad.json"
    f.write_text(json.dumps(doc, allow_nan=True))
    with pytest.raises(InputError, match=r"^flow bad\.json: ") as exc:
        read_strokes(f, "flow")
    assert field in str(exc.value)


def test_unsupported_extension_and_missing_file(tmp_path):
    with pytest.raises(InputError, match="brush .*unsupported extension"):
        read_stroke(tmp_path / "a.txt")
    with pytest.raises(InputError, match="strokes .*no such file"):
        load_strokes(tmp_path / "a.json")
