"""A task on one model per cable: the step's cable, failures ending the task, open fingers."""

from __future__ import annotations

import numpy as np

from tautwire.model import PathGraph
from tautwire.primitives import PrimitiveContext, make_context
from tautwire.robot import Arm, Command, GripperCommand
from tautwire.tasks.cable_models import CableModels
from tautwire.tasks.runner import keep_fingers_open
from tautwire.tasks.task_runner import PlainStep, TaskHooks, run_task

from ..primitives.spring_robot import SpringCableRobot

CONTACT = np.array([0.1, 0.0, 0.1])
GRIPPER = np.array([0.4, 0.0, 0.1])


def _models() -> CableModels:
    graph = PathGraph.from_positions(
        [CONTACT, GRIPPER], 0.0, kinds=["fixed", "gripper"], labels=["A1", "left"]
    )

    def factory(cable: str, arm: Arm, g: PathGraph, k: float | None) -> PrimitiveContext:
        return make_context(g, arm, k_initial=200.0)

    return CableModels({"W1": graph}, frozenset(("left",)), factory)


def test_a_task_runs_its_steps_in_order_on_the_step_s_cable() -> None:
    robot = SpringCableRobot(CONTACT, GRIPPER, stiffness=200.0, slack=0.005)
    started: list[tuple[int, str | None]] = []
    steps = [
        PlainStep("single_arm_tension", "D", {"arm": "left", "force": 3.0, "cable": "W1"}),
        PlainStep("move", "", {"arm": "left", "by": [0.0, 0.05, 0.0], "taut": True}),
    ]
    hooks = TaskHooks(on_start=lambda i, s, m: started.append((i, m.cable)))
    reports = run_task(robot, steps, _models(), hooks)
    assert [r.outcome for r in reports] == ["success", "success"], [r.detail for r in reports]
    assert [r.cable for r in reports] == ["W1", "W1"]
    assert started == [(0, "W1"), (1, "W1")]
    assert abs(robot.tension() - 3.0) < 0.6


def test_a_step_no_model_fits_fails_as_a_precondition_and_ends_the_task() -> None:
    robot = SpringCableRobot(CONTACT, GRIPPER, stiffness=200.0, slack=0.005)
    ended: list[str | None] = []
    steps = [
        PlainStep("single_arm_tension", "D", {"arm": "left", "force": 3.0, "cable": "W9"}),
        PlainStep("single_arm_tension", "D", {"arm": "left", "force": 3.0}),
    ]
    hooks = TaskHooks(on_end=lambda i, s, m, r: ended.append(None if m is None else m.cable))
    reports = run_task(robot, steps, _models(), hooks)
    assert len(reports) == 1
    assert reports[0].cause == "precondition" and "W9" in reports[0].detail
    assert ended == [None]


def test_released_grippers_keep_their_fingers_open() -> None:
    command = Command(np.zeros(12), GripperCommand("hold"), GripperCommand("hold"))
    kept = keep_fingers_open(command, {"right"})
    assert kept.left.mode == "hold" and kept.right.mode == "open"
    assert keep_fingers_open(command, ()) is command
