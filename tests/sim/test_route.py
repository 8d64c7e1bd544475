"""The initial cable route through fixtures and grippers."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from tautwire.errors import SimulationError
from tautwire.model.quaternion import rotate
from tautwire.sim import (
    AnchorSpec,
    CableSpec,
    GripperSpec,
    HoldSpec,
    PegSpec,
    SimOptions,
    WorldSpec,
)
from tautwire.sim.discretization import discretize_cable
from tautwire.sim.route import initial_vertices


def _world(length: float, peg_y: float = 0.05, orientation=(1.0, 0.0, 0.0, 0.0)) -> WorldSpec:
    return WorldSpec(
        fixtures=(AnchorSpec("A", [0.0, 0.0, 0.12]), PegSpec("P", [0.15, peg_y, 0.1], 0.006, 0.05)),
        cables=(
            CableSpec("W", length, 0.03, 200.0, 0.0025, "A", ("P",), (HoldSpec("left", length),)),
        ),
        left=GripperSpec([0.35, 0.15, 0.12], np.array(orientation)),
        right=GripperSpec([0.35, -0.25, 0.12]),
    )


def _vertices(world: WorldSpec) -> np.ndarray:
    opt = SimOptions()
    disc = discretize_cable(world.cables[0], world.force_limit, opt)
    return initial_vertices(world, world.cables[0], disc, opt.clip_length, 0.0, opt.pad_exit)


def test_route_bears_on_the_peg_on_the_far_side_of_the_bend() -> None:
    # The chord from anchor to gripper passes above the peg (y = 0.064 at
    # x = 0.15), so a taut route via the peg bends around its -y side.
    v = _vertices(_world(0.42))
    d = np.linalg.norm(v[:, :2] - [0.15, 0.05], axis=1)
    assert d.min() == pytest.approx(0.006 + 0.0025, abs=1e-3)
    closest = v[np.argmin(d)]
    assert closest[1] < 0.05
    assert np.allclose(v[0], [0.0, 0.0, 0.12]) and np.allclose(v[-1], [0.35, 0.15, 0.12])


def test_route_leaves_a_held_point_along_the_tool_axis() -> None:
    q = np.array([np.cos(0.2), 0.0, 0.0, np.sin(0.2)])  # tool x turned 0.4 rad about z
    v = _vertices(_world(0.42, orientation=q))
    x_tool = rotate(q, [1.0, 0.0, 0.0])
    exit_dir = (v[-2] - v[-1]) / np.linalg.norm(v[-2] - v[-1])
    assert exit_dir @ -x_tool == pytest.approx(1.0, abs=1e-9)


def test_a_route_much_longer_than_the_cable_is_refused() -> None:
    with pytest.raises(SimulationError, match="stretched"):
        _vertices(_world(0.3))


def test_a_run_refuses_a_route_that_starts_the_cable_stretched_naming_the_hold() -> None:
    # The route A -> P -> fingers needs 0.3849 m of cable up to the hold.
    # Held at 0.38 m the cable would start at about 1 N, far below the force
    # limit but above its weight (0.11 N). A scenario's world starts a run,
    # whose tare would take that pull for a sensor offset: it is refused.
    # A bare world (no run, no tare) may start that stretched.
    stretched = _world(0.38)
    _vertices(stretched)
    with pytest.raises(SimulationError, match=r"held_by \(arm left\) at >= 0\.3849 m") as err:
        _vertices(dataclasses.replace(stretched, start_at_rest=True))
    assert "above the 0.11 N its start allows (its weight: the sensor's tare" in str(err.value)
    _vertices(dataclasses.replace(_world(0.386), start_at_rest=True))  # 1 mm of slack
