"""Flow mode: the bent lattice's bond network relaxed whole, last (issue 14 point 2;
:mod:`strew.grow._flow_net`): the option leaves the other modes alone. Its effect on the
bent lattice is tested in ``test_grow_flow_bent_lattice`` (one growth for the three passes).
"""

from __future__ import annotations

import pytest

from test_grow_flow14d_stretch import assert_flow_option_leaves_mode_alone, hex_ref  # noqa: F401 (a fixture)


@pytest.mark.parametrize("mode", ["fixed", "rotate"])
def test_flow_network_relaxation_leaves_the_other_modes_alone(hex_ref, mode):
    assert_flow_option_leaves_mode_alone(hex_ref, mode, "flow_net_rounds")
