"""strew info on a drawing where every shape is its own kind (issue 17: nothing hangs)."""

from __future__ import annotations

import json

import numpy as np

import strew
from strew.io import save
from strew.cli import main
from strew.cli.info import MAX_PAIR_KINDS


def _many_kinds(tmp_path, k):
    rng = np.random.default_rng(5)
    shapes = {f"k{i}": strew.Shape.circle(1.0 + 0.01 * i) for i in range(k)}
    names = list(shapes)
    xy = rng.uniform(0, 50 * np.sqrt(k), (k, 2))
    arr = strew.Arrangement(shapes, names, xy[:, 0], xy[:, 1])
    path = tmp_path / f"k{k}.json"
    save(arr, str(path))
    return path


def test_info_leaves_out_kind_pair_statistics_past_the_limit_and_says_so(tmp_path, capsys):
    # one term per pair of kinds: 9,174 kinds ran over 10 min and 4 GB before the limit
    path = _many_kinds(tmp_path, MAX_PAIR_KINDS + 1)
    assert main(["info", str(path), "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["count"] == MAX_PAIR_KINDS + 1
    assert d["nearest_neighbor_by_kind"] is None and d["pair_correlation"] is None
    assert main(["info", str(path)]) == 0
    assert f"not measured: {MAX_PAIR_KINDS + 1} kinds" in capsys.readouterr().out


def test_info_measures_kind_pairs_up_to_the_limit(tmp_path, capsys):
    path = _many_kinds(tmp_path, 3)
    assert main(["info", str(path), "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert len(d["nearest_neighbor_by_kind"]) == 3 * 3 - 3  # a>b for a != b; one element a kind has no a>a
