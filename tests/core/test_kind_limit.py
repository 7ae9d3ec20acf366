"""Exemplars with more kinds than kind-pair tables allow are refused at once (issue 17)."""

from __future__ import annotations

import numpy as np
import pytest

import strew
from strew import InputError
from strew._limits import MAX_KINDS
from strew.grow import grow
from strew.metrics import fidelity
from strew.synth import synthesize


def _distinct(k: int) -> strew.Arrangement:
    # every element its own shape, as a drawing of distinct polygons reads (one kind each)
    shapes = {f"s{i}": strew.Shape.circle(1.0 + 1e-4 * i, 8) for i in range(k)}
    side = int(np.ceil(np.sqrt(k)))
    i = np.arange(k)
    return strew.Arrangement(shapes, list(shapes), 3.0 * (i % side), 3.0 * (i // side))


@pytest.mark.parametrize("method", ["grow", "synth", "fidelity"])
def test_more_kinds_than_the_limit_are_refused_naming_the_exemplar(method):
    ex = _distinct(MAX_KINDS + 1)
    with pytest.raises(InputError, match=rf"^exemplar: 1,001 kinds, over the {MAX_KINDS:,}"):
        if method == "grow":
            grow(ex, count=50, rng=1)
        elif method == "synth":
            synthesize(ex, strew.Region.rectangle(50, 50), rng=1)
        else:
            fidelity(ex, ex)



@pytest.mark.parametrize("method", ["grow", "synth"])
def test_the_cli_names_the_positional_exemplar_without_a_flag(method, tmp_path, capsys):
    from strew.cli import main
    from strew.io import save

    path = tmp_path / "ex.json"
    save(_distinct(MAX_KINDS + 1), str(path))
    args = [method, str(path), "-o", str(tmp_path / "out.json")]
    args += ["--count", "20"] if method == "grow" else ["--size", "50x50"]
    assert main(args) == 2
    # the exemplar is an argument, not an option: no "--exemplar" (grow printed one)
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("strew: error: exemplar"), err
    assert not (tmp_path / "out.json").exists()
