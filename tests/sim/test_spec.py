"""World description and options: validation with clear messages."""

from __future__ import annotations

import numpy as np
import pytest

from tautwire.errors import InvalidArgumentError
from tautwire.sim import (
    AnchorSpec,
    CableSpec,
    ClipSpec,
    GripperSpec,
    HoldSpec,
    PegSpec,
    SimOptions,
    WorldSpec,
)

LEFT, RIGHT = GripperSpec([0.3, 0.1, 0.2]), GripperSpec([0.3, -0.1, 0.2])


def test_fixture_and_cable_fields_are_checked() -> None:
    with pytest.raises(InvalidArgumentError, match="position"):
        AnchorSpec("A", [0.0, 0.0])
    with pytest.raises(InvalidArgumentError, match="radius"):
        PegSpec("P", [0.0, 0.0, 0.0], -1.0, 0.05)
    with pytest.raises(InvalidArgumentError, match="push_force"):
        ClipSpec("C", [0.0, 0.0, 0.0], 0.0, 0.0)
    with pytest.raises(InvalidArgumentError, match="stiffness"):
        CableSpec("W", 0.4, 0.03, 0.0, 0.002)
    with pytest.raises(InvalidArgumentError, match="beyond its length"):
        CableSpec("W", 0.4, 0.03, 100.0, 0.002, holds=(HoldSpec("left", 0.5),))
    with pytest.raises(InvalidArgumentError, match="left"):
        HoldSpec("middle", 0.1)  # type: ignore[arg-type]
    assert np.allclose(ClipSpec("C", [0.0, 0.0, 0.0], np.pi / 2, 1.0).direction, [0.0, 1.0, 0.0])


def test_world_references_are_checked() -> None:
    cable = CableSpec("W", 0.4, 0.03, 100.0, 0.002, start="P", holds=(HoldSpec("left", 0.4),))
    with pytest.raises(InvalidArgumentError, match="not an anchor"):
        WorldSpec((PegSpec("P", [0.0, 0.0, 0.0], 0.01, 0.05),), (cable,), LEFT, RIGHT)
    cable = CableSpec("W", 0.4, 0.03, 100.0, 0.002, via=("X",), holds=(HoldSpec("left", 0.4),))
    with pytest.raises(InvalidArgumentError, match="not a fixture"):
        WorldSpec((), (cable,), LEFT, RIGHT)
    with pytest.raises(InvalidArgumentError, match="unique"):
        WorldSpec((AnchorSpec("W", [0.0, 0.0, 0.0]),), (cable,), LEFT, RIGHT)
    with pytest.raises(InvalidArgumentError, match="sensor_arms"):
        WorldSpec((), (), LEFT, RIGHT, sensor_arms=())


def test_options_are_checked() -> None:
    with pytest.raises(InvalidArgumentError, match="timestep"):
        SimOptions(timestep=0.0)
    with pytest.raises(InvalidArgumentError, match="pad_exit"):
        SimOptions(pad_exit=0.005)
    with pytest.raises(InvalidArgumentError, match="valid options"):
        SimOptions.from_kwargs(segmentz=4)
    assert SimOptions.from_kwargs(segments=12).segments == 12
