"""build_world: from a scenario file's text to a settled world."""

from __future__ import annotations

import numpy as np
import pytest

from tautwire.errors import InvalidArgumentError
from tautwire.robot import Robot
from tautwire.scenario import parse_scenario
from tautwire.sim.build import build_world, robot_of, truth_of, world_spec

SCENARIO = """
version: 1
name: peg-and-clip
seed: 3
robot:
  control_period: 0.004
  force_limit: 15.0
  sensor: {arm: both, noise_force: 0.05, noise_torque: 0.002}
  grippers:
    left:  {position: [0.35, 0.15, 0.12]}
    right: {position: [0.35, -0.25, 0.12], orientation: [1, 0, 0, 0]}
board:
  fixtures:
    - {name: A1, type: anchor, position: [0.0, 0.0, 0.12]}
    - {name: P1, type: peg, position: [0.15, 0.05, 0.10], radius: 0.006, height: 0.05}
    - {name: C1, type: clip, position: [0.30, -0.05, 0.08], yaw: 0.0, push_force: 2.5}
cables:
  - name: W1
    length: 0.42
    mass_per_length: 0.030
    stiffness: 200.0
    radius: 0.0025
    start: A1
    via: [P1]
    held_by: {arm: left, at: 0.42}
task:
  - {primitive: single_arm_tension, arm: left, force: 3.0}
"""


def test_spec_carries_every_scenario_field() -> None:
    spec = world_spec(parse_scenario(SCENARIO))
    assert spec.sensor_arms == ("left", "right")
    assert spec.noise_force == 0.05 and spec.noise_torque == 0.002 and spec.seed == 3
    assert [f.name for f in spec.fixtures] == ["A1", "P1", "C1"]
    assert spec.start_at_rest  # a scenario's world starts a run (its tare)
    cable = spec.cables[0]
    assert (cable.start, cable.via, cable.holds[0].arm, cable.holds[0].at) == (
        "A1",
        ("P1",),
        "left",
        0.42,
    )
    assert world_spec(parse_scenario(SCENARIO), seed=9).seed == 9


def test_built_world_holds_the_cable_and_senses_on_both_wrists() -> None:
    world = build_world(parse_scenario(SCENARIO), segment_length=0.03)
    robot = robot_of(world)
    assert isinstance(robot, Robot)
    obs = robot.observe()
    assert obs.time == 0.0 and obs.has_sensor("left") and obs.has_sensor("right")
    assert np.allclose(obs.left.position, [0.35, 0.15, 0.12])
    truth = truth_of(world)
    assert world.held("left") == ("W1", world.scene.discretizations["W1"].segments)
    assert np.allclose(truth.polyline("W1")[0], [0.0, 0.0, 0.12])
    assert np.allclose(truth.polyline("W1")[-1], [0.35, 0.15, 0.12], atol=1e-3)
    assert "A1" in truth.in_contact()


def test_unknown_option_names_the_valid_ones() -> None:
    with pytest.raises(InvalidArgumentError, match="timestep"):
        build_world(parse_scenario(SCENARIO), timestpe=0.001)
