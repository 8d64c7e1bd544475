"""SimRobot: the Robot contract, determinism, and no ground truth in reach."""

from __future__ import annotations

import numpy as np
import pytest

from tautwire.model.quaternion import to_rotation
from tautwire.robot import Command, GripperCommand, Observation, Robot
from tautwire.sim.sim_robot import SimRobot
from tests.sim.scenes import anchor_and_gripper, peg_scene


def _run(seed: int, steps: int = 50) -> list[Observation]:
    world = peg_scene(noise_force=0.05, noise_torque=0.002)
    robot = SimRobot(world, seed=seed)
    twist = np.zeros(12)
    twist[0:3] = [0.01, 0.005, 0.0]
    out = []
    for _ in range(steps):
        robot.act(Command(twist=twist))
        out.append(robot.observe())
    return out


def test_conforms_to_the_robot_protocol() -> None:
    world = peg_scene()
    robot = SimRobot(world)
    assert isinstance(robot, Robot)
    assert robot.control_period == 0.004
    obs = robot.observe()
    assert obs.time == 0.0
    for state in (obs.left, obs.right):
        assert state.position.shape == (3,) and state.orientation.shape == (4,)
        assert np.isfinite(state.opening) and state.grip_force >= 0.0
    assert [w.arm for w in obs.wrenches] == ["left"]
    assert obs.wrench().force.shape == (3,) and obs.wrench().torque.shape == (3,)
    robot.act(Command())
    assert robot.observe().time == pytest.approx(0.004)


def test_twist_moves_the_grippers_for_one_control_period() -> None:
    world = anchor_and_gripper([0.0, 0.0, 0.3], [0.3, 0.0, 0.3], 0.32, 100.0)
    robot = SimRobot(world)
    start = robot.observe()
    twist = np.zeros(12)
    twist[0:3] = [0.0, 0.0, 0.05]  # left up
    twist[9:12] = [0.0, 0.0, 1.0]  # right turns about z
    for _ in range(25):
        robot.act(Command(twist=twist))
    obs = robot.observe()
    t = 25 * 0.004
    assert np.allclose(obs.left.position - start.left.position, [0.0, 0.0, 0.05 * t])
    turned = to_rotation(obs.right.orientation) * to_rotation(start.right.orientation).inv()
    assert np.allclose(turned.as_rotvec(), [0.0, 0.0, t])
    assert np.allclose(obs.right.position, start.right.position)


def test_gripper_commands_reach_the_fingers() -> None:
    world = peg_scene()
    robot = SimRobot(world)
    assert robot.observe().left.grip_force == world.options.hold_grip_force
    robot.act(Command(right=GripperCommand("grip_force", 3.0)))
    for _ in range(20):
        robot.act(Command(right=GripperCommand("grip_force", 3.0)))
    obs = robot.observe()
    assert obs.right.grip_force == 3.0
    assert obs.right.opening < 1e-3  # closed on nothing


def test_same_seed_same_trajectory_and_noise() -> None:
    a, b, c = _run(4), _run(4), _run(5)
    assert all(
        np.array_equal(x.wrench().force, y.wrench().force) for x, y in zip(a, b, strict=True)
    )
    assert not np.array_equal(a[-1].wrench().force, c[-1].wrench().force)
    assert np.array_equal(a[-1].left.position, c[-1].left.position)


def test_sensor_noise_has_the_scenario_std() -> None:
    world = anchor_and_gripper(
        [0.0, 0.0, 0.3], [0.3, 0.0, 0.3], 0.31, 100.0, noise_force=0.05, noise_torque=0.002
    )
    robot = SimRobot(world, seed=1)
    forces, truths = [], []
    for _ in range(400):
        robot.act(Command())
        forces.append(robot.observe().wrench().force)
        truths.append(world.wrench("left")[0])
    residual = np.array(forces) - np.array(truths)
    assert np.allclose(residual.std(axis=0), 0.05, rtol=0.15)


def test_no_ground_truth_is_reachable_from_the_public_api() -> None:
    robot = SimRobot(peg_scene())
    public = {name for name in dir(robot) if not name.startswith("_")}
    assert public == {"act", "observe", "control_period"}
    assert not hasattr(robot, "world") and not hasattr(robot, "_world")
    obs = robot.observe()
    fields = set(vars(obs)) | set(vars(obs.left)) | set(vars(obs.wrench()))
    assert fields <= {
        "time",
        "left",
        "right",
        "wrenches",
        "position",
        "orientation",
        "opening",
        "grip_force",
        "arm",
        "force",
        "torque",
    }
