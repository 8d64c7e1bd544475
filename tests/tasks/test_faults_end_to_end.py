"""One fault per run, end to end: primitive D on the anchor-rotate scene in MuJoCo.

The faults are injected by the simulator (``faults:``), handled by the core's
guard. What must hold (issue 10, "Faults"): spike, NaN, a freeze of 50 ms and
one lost command are survived and the step succeeds; a freeze past 0.1 s
ends with ``sensor_stale``; lost commands past 0.1 s with ``robot_error``
after a zero twist; a sustained force over the limit with ``force_limit``
within 3 samples; a sensor offset at the start is tared away; a slip ends
with a named cause. The true force never exceeds the limit.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

from tautwire.experiments.run_scenario import run_scenario
from tautwire.primitives import CAUSES, make_primitive
from tautwire.robot import Command
from tautwire.scenario import Scenario, parse_scenario
from tautwire.scenario.registry import scenario_path
from tautwire.sim.build import build_world, robot_of, truth_of
from tautwire.tasks import run_step
from tautwire.tasks.initial_model import initial_context
from tautwire.tasks.scenario_guard import scenario_guard

SCENE = scenario_path("anchor-rotate").read_text()
D_STEP = "  - {primitive: single_arm_tension, arm: left, force: 3.0}\n"
D_ONLY = SCENE.split("task:")[0] + "task:\n" + D_STEP
LIMIT = 15.0
DT = 0.004


def scene(*faults: str) -> Scenario:
    section = "faults:\n" + "".join(f"  - {f}\n" for f in faults) if faults else ""
    return parse_scenario(D_ONLY + section)


def run_d(*faults: str) -> tuple[dict[str, Any], float]:
    """The step of D and the true largest force [N] in the run."""
    result, _, truth = run_scenario(scene(*faults))
    (step,) = result.steps
    return step, truth.max_force


@pytest.mark.parametrize(
    "fault",
    [
        "{type: spike, at: 2.0, force: [0, 0, 40]}",  # while tensioned
        "{type: spike, at: 0.3, force: [0, 12, 0]}",  # while slack: no made-up contact
        "{type: nan, at: 2.0}",
        "{type: freeze, at: 2.0, duration: 0.05}",
        "{type: robot_error, at: 2.0}",
        "{type: bias_drift, at: 0.0, duration: 0.0, force: [2, 0, 0]}",  # an offset: tared
    ],
)
def test_a_survivable_fault_leaves_a_true_success(fault: str) -> None:
    step, true_max = run_d(fault)
    assert step["outcome"] == "success", step["detail"]
    assert step["truth"]["agrees"], step["truth"]["detail"]
    assert true_max < LIMIT


@pytest.mark.parametrize("duration", [0.2, 2.0])
def test_a_freeze_past_a_tenth_of_a_second_ends_with_sensor_stale(duration: float) -> None:
    step, true_max = run_d(f"{{type: freeze, at: 2.0, duration: {duration}}}")
    assert step["cause"] == "sensor_stale"
    assert 2.1 - 1e-6 <= step["sim_time"] <= 2.1 + 3 * DT  # fails just past 0.1 s of frozen data
    assert true_max < 3.5  # held still: the tension did not grow


def test_a_sustained_force_over_the_limit_ends_with_force_limit_within_3_samples() -> None:
    step, true_max = run_d("{type: bias_drift, at: 2.0, duration: 0.0, force: [0, 0, 20]}")
    assert step["cause"] == "force_limit"
    assert step["sim_time"] <= 2.0 + 3 * DT + 1e-9
    assert true_max < LIMIT


def test_a_slip_ends_with_a_named_cause_and_no_success() -> None:
    step, true_max = run_d("{type: slip, at: 2.0, duration: 1.0}")
    assert step["outcome"] == "failure" and step["cause"] in CAUSES
    assert step["truth"]["agrees"]
    assert true_max < LIMIT


class Recorder:
    """Records every command handed to the robot it wraps."""

    def __init__(self, robot: Any) -> None:
        self.robot = robot
        self.sent: list[Command] = []

    @property
    def control_period(self) -> float:
        return float(self.robot.control_period)

    def observe(self) -> Any:
        return self.robot.observe()

    def act(self, command: Command) -> None:
        self.sent.append(command)
        self.robot.act(command)


def test_lost_commands_past_a_tenth_of_a_second_end_with_robot_error_after_a_zero_twist() -> None:
    scenario = scene("{type: robot_error, at: 2.0, duration: 0.3}")
    world = build_world(scenario)
    recorder = Recorder(robot_of(world, None, scenario.faults))
    guard = scenario_guard(recorder, scenario)
    ctx = initial_context(scenario, estimation_period=0.04)
    step = scenario.task[0]
    report = run_step(guard, make_primitive(step.primitive, **step.params), ctx)
    assert report.cause == "robot_error" and "lost" in report.detail
    assert 2.1 - 1e-6 <= report.sim_time <= 2.1 + 3 * DT
    assert not np.any(recorder.sent[-1].twist)  # the stop was tried (and lost too)
    assert np.any(recorder.sent[-2].twist)
    assert truth_of(world).max_force < LIMIT
