"""RobotGuard on a scripted fake robot: every kind of bad sample, lost command and bound."""

from __future__ import annotations

import subprocess
import sys
import textwrap
from itertools import pairwise

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tautwire.errors import InvalidArgumentError, SimulationError
from tautwire.robot import WORKSPACE, Command, GripperCommand, Robot, RobotCommunicationError
from tautwire.tasks.robot_guard import (
    ERROR_TIME,
    STALE_TIME,
    RobotGuard,
    spike_bound,
)
from tests.tasks.scripted_robot import (
    ScriptedRobot,
    nan_force,
    nan_position,
    nan_time,
    repeat,
    same_time,
    spike,
)

DT = 0.004
LIMIT = 15.0


def guard_of(robot: ScriptedRobot, **kwargs: object) -> RobotGuard:
    options: dict[str, object] = {"force_limit": LIMIT, "force_noise": 0.05}
    options.update(kwargs)
    return RobotGuard(robot, **options)  # type: ignore[arg-type]


def twist(v: list[float]) -> Command:
    t = np.zeros(12)
    t[0:3] = v
    return Command(t)


def run(guard: RobotGuard, periods: int, command: Command | None = None) -> list[bool]:
    """Act (or hold when the sample is not fresh) ``periods`` times; return ``fresh`` each time."""
    fresh = []
    for _ in range(periods):
        if guard.fault is not None:
            break
        if guard.fresh:
            guard.act(command or Command())
        else:
            guard.hold()
        fresh.append(guard.fresh)
    return fresh


def test_is_a_robot_and_passes_clean_samples_unchanged() -> None:
    robot = ScriptedRobot()
    guard = guard_of(robot)
    assert isinstance(guard, Robot)
    assert guard.control_period == DT
    assert guard.observe() is robot.observe() and guard.fresh
    for _ in range(20):
        guard.act(twist([0.01, 0.0, 0.0]))
        assert guard.fresh and guard.observe() is robot.observe()
    assert guard.fault is None
    assert not any(guard.events.values())
    assert guard.time == pytest.approx(20 * DT)


def test_observe_returns_the_same_sample_until_the_next_command() -> None:
    robot = ScriptedRobot()
    guard = guard_of(robot)
    first = guard.observe()
    assert guard.observe() is first and guard.fresh


@pytest.mark.parametrize("edit", [nan_force, nan_position, nan_time], ids=lambda e: e.__name__)
def test_a_non_finite_sample_never_reaches_the_caller(edit: object) -> None:
    robot = ScriptedRobot()
    robot.edits[5] = edit  # type: ignore[assignment]
    guard = guard_of(robot)
    run(guard, 4)
    good = guard.observe()
    guard.act(Command())
    assert not guard.fresh
    assert guard.observe() is good
    guard.hold()
    assert guard.fresh and guard.observe().time == pytest.approx(6 * DT)
    assert guard.events["non_finite"] == 1 and guard.fault is None


def test_the_robot_holds_still_on_bad_data_with_its_gripper_commands() -> None:
    robot = ScriptedRobot()
    robot.edits[3] = nan_force
    guard = guard_of(robot)
    command = Command(np.full(12, 0.01), GripperCommand("grip_force", 2.0), GripperCommand("open"))
    for _ in range(3):
        guard.act(command)
    assert not guard.fresh
    guard.hold()
    held = robot.sent[-1]
    assert not np.any(held.twist)
    assert held.left == command.left and held.right == command.right


def test_a_frozen_sensor_is_stale_only_when_it_is_noisy() -> None:
    robot = ScriptedRobot()
    for k in range(3, 8):
        robot.edits[k] = repeat
    guard = guard_of(robot)
    fresh = run(guard, 10)
    assert fresh == [True, True, False, False, False, False, False, True, True, True]
    assert guard.events["frozen"] == 5
    noiseless = ScriptedRobot(noise=0.0)
    quiet = guard_of(noiseless, force_noise=0.0)
    assert all(run(quiet, 10))


def test_time_that_does_not_advance_is_stale() -> None:
    robot = ScriptedRobot()
    robot.edits[4] = same_time
    guard = guard_of(robot)
    assert run(guard, 6) == [True, True, True, False, True, True]
    assert guard.events["stale_time"] == 1


def test_a_freeze_of_50_ms_is_survived() -> None:
    robot = ScriptedRobot()
    frozen = round(0.05 / DT)
    for k in range(10, 10 + frozen):
        robot.edits[k] = repeat
    guard = guard_of(robot)
    fresh = run(guard, 60)
    assert len(fresh) == 60 and guard.fault is None
    assert fresh.count(False) == frozen


def test_stale_data_past_a_tenth_of_a_second_ends_with_sensor_stale_and_a_stop() -> None:
    robot = ScriptedRobot()
    for k in range(10, 200):
        robot.edits[k] = repeat
    guard = guard_of(robot)
    run(guard, 200, twist([0.02, 0.0, 0.0]))
    fault = guard.fault
    assert fault is not None and fault.cause == "sensor_stale"
    assert "frozen" in fault.detail or "repeated" in fault.detail
    # the first bad sample came after 10 commands; the robot held still from then on
    moving = [bool(np.any(c.twist)) for c in robot.sent]
    assert moving[:10] == [True] * 10 and not any(moving[10:])
    stale = robot.acts - 10
    assert (stale - 1) * DT <= STALE_TIME + DT + 1e-9 and stale * DT > STALE_TIME


def test_the_spike_bound_is_documented_and_uses_the_settings() -> None:
    bound = spike_bound(15.0, 0.05, 0.1, 0.004)
    assert bound == pytest.approx(7.5 + 2000.0 * 0.1 * 0.004 + 6.0 * np.sqrt(6.0) * 0.05)
    assert guard_of(ScriptedRobot()).spike_bound == pytest.approx(bound)
    assert 8.0 < bound < 12.0  # rejects the 12 N spike; a cable's pull stays within it


def test_a_single_spike_is_rejected_and_the_previous_good_sample_stands() -> None:
    robot = ScriptedRobot()
    robot.edits[6] = spike([0.0, 0.0, 40.0])
    guard = guard_of(robot)
    forces = []
    for _ in range(10):
        fresh_before = guard.fresh
        if fresh_before:
            forces.append(np.linalg.norm(guard.observe().wrench().force))
        guard.act(Command()) if fresh_before else guard.hold()
    assert guard.events["outlier"] == 1 and guard.fault is None
    assert max(forces) < 2.0


def test_a_sustained_force_over_the_limit_gets_through_on_the_next_sample() -> None:
    robot = ScriptedRobot(force=lambda t: np.array([0.0, 0.0, 40.0 if t > 0.0199 else 1.0]))
    guard = guard_of(robot)
    seen = []
    for _ in range(10):
        if guard.fresh:
            seen.append(float(np.linalg.norm(guard.observe().wrench().force)))
            guard.act(Command())
        else:
            seen.append(-1.0)
            guard.hold()
    first_high = round(0.02 / DT)  # the sample after 5 commands
    assert seen[first_high] == -1.0  # rejected once
    assert seen[first_high + 1] > LIMIT  # then passed on: within 2 samples of the jump


def test_never_two_outliers_in_a_row() -> None:
    """A force that rises faster than the bound allows is delayed, never hidden."""
    robot = ScriptedRobot(force=lambda t: np.array([0.0, 0.0, 3000.0 * t]))
    guard = guard_of(robot)
    fresh = run(guard, 12)
    assert all(a or b for a, b in pairwise(fresh))
    assert guard.fault is None


def test_tare_removes_an_offset_beyond_the_tolerance() -> None:
    load = np.array([0.0, 0.0, -0.12])
    robot = ScriptedRobot(force=lambda t: load + np.array([2.0, 0.0, 0.0]))
    robot.edits[3] = spike([0.0, 30.0, 0.0])  # a spike during the tare does not move the median
    guard = guard_of(robot, tare_samples=12, expected_load={"left": load}, tare_tolerance=0.3)
    fresh = run(guard, 40)
    assert fresh[:11] == [False] * 11 and all(fresh[12:])
    assert guard.offsets["left"] == pytest.approx([2.0, 0.0, 0.0], abs=0.05)
    forces = []
    for _ in range(200):
        guard.act(Command())
        forces.append(guard.observe().wrench().force)
    # what remains is the median's noise: 1.25 * 0.05 / sqrt(12) = 0.018 N per axis
    assert np.mean(forces, axis=0) == pytest.approx(load, abs=0.06)


def test_tare_keeps_a_small_real_load() -> None:
    load = np.array([0.15, 0.0, -0.2])
    robot = ScriptedRobot(force=lambda t: load)
    guard = guard_of(robot, tare_samples=12, tare_tolerance=0.5)
    run(guard, 20)
    assert not np.any(guard.offsets["left"])
    forces = []
    for _ in range(200):
        guard.act(Command())
        forces.append(guard.observe().wrench().force)
    assert np.mean(forces, axis=0) == pytest.approx(load, abs=0.01)


def test_one_lost_command_is_survived_and_the_robot_kept_its_previous_one() -> None:
    robot = ScriptedRobot()
    robot.failures[5] = RobotCommunicationError("packet lost")
    guard = guard_of(robot)
    for k in range(10):
        guard.act(twist([0.01 * (k + 1), 0.0, 0.0]))
    assert guard.fault is None and guard.fresh
    assert guard.events["lost_command"] == 1
    assert robot.applied[5].twist[0] == pytest.approx(0.05)  # the 5th command again
    assert guard.observe().time == pytest.approx(10 * DT)


def test_lost_commands_past_a_tenth_of_a_second_end_with_robot_error_and_a_zero_twist() -> None:
    robot = ScriptedRobot()
    for k in range(5, 500):
        robot.failures[k] = RobotCommunicationError("link down")
    guard = guard_of(robot)
    run(guard, 100, twist([0.02, 0.0, 0.0]))
    fault = guard.fault
    assert fault is not None and fault.cause == "robot_error"
    assert "lost" in fault.detail
    lost = len(robot.sent) - 1 - 5  # the last call is the stop
    assert (lost - 1) * DT <= ERROR_TIME + 1e-9 < lost * DT
    assert not np.any(robot.sent[-1].twist)


@pytest.mark.parametrize("where", ["act", "observe"])
def test_any_other_robot_exception_ends_with_robot_error_after_a_stop(where: str) -> None:
    robot = ScriptedRobot()
    if where == "act":
        robot.failures[3] = RuntimeError("servo fault")
    else:
        robot.observe_failures[3] = RuntimeError("bus error")
    guard = guard_of(robot)
    run(guard, 10, twist([0.02, 0.0, 0.0]))
    fault = guard.fault
    assert fault is not None and fault.cause == "robot_error"
    assert "RuntimeError" in fault.detail
    assert not np.any(robot.sent[-1].twist)


def test_when_the_stop_fails_too_the_step_still_ends() -> None:
    robot = ScriptedRobot()
    for k in range(3, 10):
        robot.failures[k] = RuntimeError("servo fault")
    guard = guard_of(robot)
    run(guard, 10, twist([0.02, 0.0, 0.0]))
    assert guard.fault is not None and guard.fault.cause == "robot_error"
    assert len(robot.sent) == 5 and not np.any(robot.sent[-1].twist)


def test_an_exception_that_names_its_cause_keeps_it_and_is_not_commanded_again() -> None:
    class DivergedError(SimulationError):
        cause = "diverged"

    robot = ScriptedRobot()
    robot.failures[3] = DivergedError("blew up")
    guard = guard_of(robot)
    run(guard, 10)
    assert guard.fault is not None and guard.fault.cause == "diverged"
    assert len(robot.sent) == 4
    guard.stop()
    assert len(robot.sent) == 4


def test_a_command_out_of_the_workspace_stops_at_the_boundary() -> None:
    y_max = WORKSPACE.upper[1]
    robot = ScriptedRobot(position=(0.3, y_max - 0.001, 0.1))
    guard = guard_of(robot, workspace=WORKSPACE)
    guard.act(twist([0.0, 0.1, 0.02]))  # 0.4 mm a period: out after 3
    for _ in range(3):
        guard.act(twist([0.0, 0.1, 0.02]))
    assert robot.p[1] == pytest.approx(y_max)
    assert robot.p[2] == pytest.approx(0.1 + 4 * 0.02 * DT)  # the other axes go on
    assert guard.fault is None and guard.events["workspace_stop"] >= 1
    guard.act(twist([0.0, -0.1, 0.0]))  # back in: allowed
    assert robot.p[1] < y_max


def test_pushing_out_of_the_workspace_for_a_tenth_of_a_second_fails() -> None:
    robot = ScriptedRobot(position=(0.3, WORKSPACE.upper[1], 0.1))
    guard = guard_of(robot, workspace=WORKSPACE)
    periods = run(guard, 100, twist([0.0, 0.05, 0.0]))
    fault = guard.fault
    assert fault is not None and fault.cause == "workspace"
    assert "workspace" in fault.detail
    assert len(periods) == round(0.1 / DT) + 1
    assert robot.p[1] == pytest.approx(WORKSPACE.upper[1])


def test_begin_step_forgets_the_previous_fault() -> None:
    robot = ScriptedRobot()
    robot.failures[2] = RuntimeError("once")
    guard = guard_of(robot)
    run(guard, 5)
    assert guard.fault is not None
    guard.begin_step()
    assert guard.fault is None
    run(guard, 5)
    assert guard.fault is None


def test_settings_are_validated() -> None:
    with pytest.raises(InvalidArgumentError, match="force_limit"):
        RobotGuard(ScriptedRobot(), force_limit=0.0)
    with pytest.raises(InvalidArgumentError, match="force_noise"):
        RobotGuard(ScriptedRobot(), force_limit=15.0, force_noise=-1.0)
    with pytest.raises(InvalidArgumentError, match="tare_samples"):
        RobotGuard(ScriptedRobot(), force_limit=15.0, tare_samples=-1)


EDITS = [nan_force, nan_position, nan_time, repeat, same_time, spike([0.0, 0.0, 50.0])]
SPIKE_INDEX = len(EDITS) - 1


@settings(max_examples=60, deadline=None)
@given(
    script=st.dictionaries(
        st.integers(min_value=1, max_value=80), st.sampled_from(range(len(EDITS))), max_size=40
    ),
    seed=st.integers(min_value=0, max_value=1000),
)
def test_whatever_the_robot_sends_the_guard_passes_on_only_finite_good_samples(
    script: dict[int, int], seed: int
) -> None:
    spikes = sorted(k for k, i in script.items() if i == SPIKE_INDEX)
    for a, b in pairwise(spikes):
        if b - a < 4 and a in script:  # isolated spikes only (two in a row are a real force)
            del script[b]
    robot = ScriptedRobot(seed=seed)
    robot.edits.update({k: EDITS[i] for k, i in script.items()})
    guard = guard_of(robot)
    times = []
    for _ in range(90):
        if guard.fault is not None:
            assert guard.fault.cause == "sensor_stale"
            break
        obs = guard.observe()
        if guard.fresh:
            assert np.all(np.isfinite(obs.wrench().force)) and np.isfinite(obs.time)
            assert np.all(np.isfinite(obs.left.position))
            assert np.linalg.norm(obs.wrench().force) < 5.0  # an isolated spike never passes
            times.append(obs.time)
            guard.act(Command())
        else:
            guard.hold()
    assert all(b > a for a, b in pairwise(times))


def test_the_guard_imports_without_the_simulator() -> None:
    code = textwrap.dedent(
        """
        import sys

        class BlockSimulator:
            def find_spec(self, name, path=None, target=None):
                if name == "mujoco" or name.startswith("mujoco."):
                    raise ImportError("mujoco is blocked in this test")
                return None

        sys.meta_path.insert(0, BlockSimulator())
        import tautwire.tasks.robot_guard, tautwire.tasks.runner
        assert "mujoco" not in sys.modules
        print("ok")
        """
    )
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "ok"
