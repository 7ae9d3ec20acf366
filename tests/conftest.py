"""Shared fixtures and hypothesis strategies for the strew test suite."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, settings
from hypothesis import strategies as st

settings.register_profile("strew", deadline=None, suppress_health_check=[HealthCheck.too_slow], max_examples=60)
settings.load_profile("strew")


@pytest.fixture
def two_kind_arrangement():
    from strew import Arrangement, Region, Shape

    shapes = {"dot": Shape.circle(1.0), "bar": Shape.rectangle(3.0, 1.0, style={"fill": "#c33"})}
    return Arrangement(
        shapes,
        ["dot", "bar", "dot", "bar"],
        [1.0, 5.0, 9.0, 5.0],
        [1.0, 1.0, 1.0, 5.0],
        [0.0, np.pi / 3, 0.0, -0.5],
        [1.0, 1.0, 0.5, 2.0],
        columns={"color": ["#111", "#222", "#333", "#444"], "weight": [0.5, 1.5, 2.5, 3.5]},
        region=Region.rectangle(12, 8),
        meta={"method": "test", "seed": 3},
    )


from strew_testing import angles, arrangements, fidelity_suite, finite, scales  # noqa: E402,F401  (re-exported)
