"""FaultInjector: each fault shows in the observations (or the acting) at its time, nothing else.

Sensor and command faults are checked against a clean twin of the same seed
(a scripted robot: the injector wraps any Robot); the slip, which needs the
cable's physics, in the MuJoCo world.
"""

from __future__ import annotations

import numpy as np
import pytest

from tautwire.robot import Command, GripperCommand, Observation, Robot, RobotCommunicationError
from tautwire.scenario import (
    BiasDriftFault,
    Fault,
    FreezeFault,
    NanFault,
    RobotErrorFault,
    SlipFault,
    SpikeFault,
)
from tautwire.sim.build import robot_of
from tautwire.sim.fault_injector import SLIP_GRIP_FORCE, FaultInjector
from tautwire.sim.sim_robot import SimRobot
from tests.sim.scenes import anchor_and_gripper
from tests.tasks.scripted_robot import ScriptedRobot

DT = 0.004
PERIODS = 100


def twist(v: float) -> Command:
    t = np.zeros(12)
    t[0] = v
    return Command(t)


Samples = list[Observation]


def pair(faults: list[Fault], periods: int = PERIODS) -> tuple[Samples, Samples]:
    """Observations of a clean robot and of its faulty twin, same seed, same commands."""
    clean = ScriptedRobot(seed=3)
    faulty = FaultInjector(ScriptedRobot(seed=3), faults)
    a, b = [clean.observe()], [faulty.observe()]
    for k in range(periods):
        clean.act(twist(0.001 * k))
        faulty.act(twist(0.001 * k))
        a.append(clean.observe())
        b.append(faulty.observe())
    return a, b


def differing(a: list[Observation], b: list[Observation]) -> list[int]:
    """Sample indices whose wrench differs (time and poses must never differ)."""
    out = []
    for k, (x, y) in enumerate(zip(a, b, strict=True)):
        assert x.time == y.time
        np.testing.assert_array_equal(x.left.position, y.left.position)
        np.testing.assert_array_equal(x.right.position, y.right.position)
        fx, fy = x.wrench().force, y.wrench().force
        tx, ty = x.wrench().torque, y.wrench().torque
        if not (np.array_equal(fx, fy) and np.array_equal(tx, ty)):
            out.append(k)
    return out


def test_is_a_robot_and_without_faults_changes_nothing() -> None:
    a, b = pair([])
    assert isinstance(FaultInjector(ScriptedRobot(), []), Robot)
    assert differing(a, b) == []


def test_a_spike_is_added_to_one_sample_at_its_time() -> None:
    a, b = pair([SpikeFault(type="spike", at=0.1, force=(0.0, 0.0, 40.0))])
    k = round(0.1 / DT)
    assert differing(a, b) == [k]
    np.testing.assert_allclose(b[k].wrench().force - a[k].wrench().force, [0.0, 0.0, 40.0])
    np.testing.assert_array_equal(b[k].wrench().torque, a[k].wrench().torque)


def test_a_nan_poisons_one_sample_of_force_and_torque() -> None:
    a, b = pair([NanFault(type="nan", at=0.101)])
    k = round(0.1 / DT) + 1  # the first sample at or after 0.101 s
    assert differing(a, b) == [k]
    assert np.all(np.isnan(b[k].wrench().force)) and np.all(np.isnan(b[k].wrench().torque))


def test_a_freeze_repeats_the_last_sample_while_time_goes_on() -> None:
    a, b = pair([FreezeFault(type="freeze", at=0.1, duration=0.05)])
    frozen = [k for k, x in enumerate(a) if 0.1 - 1e-9 <= x.time < 0.15]
    first = frozen[0]
    assert len(frozen) == 13  # 0.1, 0.104, ..., 0.148 s
    assert differing(a, b) == frozen
    for k in frozen:
        np.testing.assert_array_equal(b[k].wrench().force, a[first - 1].wrench().force)
        np.testing.assert_array_equal(b[k].wrench().torque, a[first - 1].wrench().torque)
        assert b[k].time > b[k - 1].time


def test_a_bias_ramps_from_zero_to_its_force_and_stays() -> None:
    force = np.array([0.5, 0.0, -0.2])
    a, b = pair([BiasDriftFault(type="bias_drift", at=0.1, duration=0.2, force=tuple(force))])
    ramps = [float(np.clip((x.time - 0.1) / 0.2, 0.0, 1.0)) for x in a]
    assert differing(a, b) == [k for k, r in enumerate(ramps) if r > 0.0]
    assert ramps[-1] == 1.0
    for x, y, ramp in zip(a, b, ramps, strict=True):
        np.testing.assert_allclose(y.wrench().force - x.wrench().force, ramp * force, atol=1e-12)


def test_a_bias_of_zero_duration_is_a_constant_offset() -> None:
    a, b = pair([BiasDriftFault(type="bias_drift", at=0.0, duration=0.0, force=(2.0, 0.0, 0.0))])
    for x, y in zip(a, b, strict=True):
        np.testing.assert_allclose(y.wrench().force - x.wrench().force, [2.0, 0.0, 0.0])


@pytest.mark.parametrize(
    ("fault", "lost"),
    [
        (RobotErrorFault(type="robot_error", at=0.1), [25]),
        (RobotErrorFault(type="robot_error", at=0.1, count=3), [25, 26, 27]),
        (RobotErrorFault(type="robot_error", at=0.1, duration=0.02), [25, 26, 27, 28, 29]),
    ],
)
def test_a_robot_error_loses_commands_and_the_previous_one_is_applied(
    fault: RobotErrorFault, lost: list[int]
) -> None:
    inner = ScriptedRobot()
    robot = FaultInjector(inner, [fault])
    raised = []
    for k in range(40):
        try:
            robot.act(twist(0.001 * (k + 1)))
        except RobotCommunicationError:
            raised.append(k)
    assert raised == lost
    for k in lost:
        assert inner.applied[k].twist[0] == pytest.approx(0.001 * lost[0])  # the last one through
    assert inner.applied[lost[-1] + 1].twist[0] == pytest.approx(0.001 * (lost[-1] + 2))
    assert robot.observe().time == pytest.approx(40 * DT)  # time went on


def test_robot_of_wraps_the_robot_only_when_there_are_faults() -> None:
    world = anchor_and_gripper([0.0, 0.0, 0.2], [0.3, 0.0, 0.2], 0.33, noise_force=0.05)
    assert isinstance(robot_of(world, 0), SimRobot)
    faulty = robot_of(world, 0, [NanFault(type="nan", at=0.0)])
    assert isinstance(faulty, FaultInjector)
    assert np.all(np.isnan(faulty.observe().wrench().force))


def test_a_slip_drops_the_grip_so_the_cable_slides_then_it_is_grasped_again() -> None:
    """Pulling away at 5 cm/s: a held cable stretches, a slipping one slides through the fingers.

    The cable is held 0.25 m along, 1 cm slack, with a 10 cm free end.
    """
    forces = {}
    for name, faults in (("held", []), ("slip", [SlipFault(type="slip", at=0.1, duration=0.4)])):
        world = anchor_and_gripper(
            [0.0, 0.0, 0.2], [0.24, 0.0, 0.2], 0.35, stiffness=100.0, held_at=0.25
        )
        robot = robot_of(world, 0, faults)
        f = []
        for _ in range(150):
            obs = robot.observe()
            if name == "slip" and 0.1 + DT <= obs.time < 0.5:
                assert obs.left.grip_force == pytest.approx(SLIP_GRIP_FORCE)
                assert world.held("left") is None
            f.append(float(np.linalg.norm(obs.wrench().force)))
            robot.act(Command(np.r_[0.05, 0.0, 0.0, np.zeros(9)], GripperCommand("hold")))
        forces[name] = f
        if name == "slip":
            assert world.held("left") is not None  # the next hold grasped it again
            assert world.gripper_grip_force("left") > SLIP_GRIP_FORCE
    k = round(0.45 / DT)
    # held: 1.25 cm of stretch on 0.25 m of a 100 N/m, 0.35 m cable by then;
    # slipping: the fingers' friction 2 mu F = 0.2 N and the cable's weight
    assert forces["held"][k] > 1.5
    assert max(forces["slip"][round(0.1 / DT) : k]) < 0.4 * forces["held"][k]
