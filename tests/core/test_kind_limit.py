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
