"""Release: the fingers open, the model's gripper point becomes free."""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from tautwire.model import PathGraph
from tautwire.primitives import make_context
from tautwire.primitives.release import Release, release_point
from tautwire.robot import Command, Observation
from tautwire.tasks import run_step

from .conftest import CONTACT, GRIPPER
from .spring_robot import SpringCableRobot

RIGHT = np.array([0.35, -0.3, 0.12])


def _two_held() -> PathGraph:
    """Anchor, left gripper (sensing), right gripper further along, a free end."""
    return PathGraph.from_positions(
        [CONTACT, GRIPPER, RIGHT, RIGHT - np.array([0.0, 0.0, 0.1])],
        mass_per_length=0.03,
        kinds=["fixed", "gripper", "gripper", "free"],
        labels=["A1", "left", "right", "end"],
    )


def test_release_point_frees_the_gripper_s_point_and_lets_the_end_hang() -> None:
    graph = _two_held()
    graph.edges[1].tension = 2.0
    moved = {"left": GRIPPER, "right": RIGHT + np.array([0.0, 0.05, 0.0])}
    assert release_point(graph, "right", moved)
    assert graph.index_of("gripper", "right") is None
    assert graph.points[2].kind == "free"
    assert graph.edges[1].tension == 0.0
    # nothing holds the cable beyond the left gripper now: it hangs from it
    assert np.allclose(graph.points[2].position[:2], GRIPPER[:2])
    assert graph.points[2].position[2] < GRIPPER[2]
    assert not release_point(graph, "right", moved)


class _Fingers(SpringCableRobot):
    """The spring robot with a right gripper whose fingers open at 40 mm/s on command."""

    def __init__(self, opens: bool = True) -> None:
        super().__init__(CONTACT, GRIPPER, stiffness=200.0, slack=0.01)
        self.opening = 0.006
        self.opens = opens

    def observe(self) -> Observation:
        obs = super().observe()
        return replace(obs, right=replace(obs.right, opening=self.opening))

    def act(self, command: Command) -> None:
        super().act(command)
        if command.right.mode == "open" and self.opens:
            self.opening = min(self.opening + 0.04 * self.control_period, 0.04)


def test_release_opens_the_fingers_then_edits_the_model() -> None:
    ctx = make_context(_two_held(), "left")
    robot = _Fingers()
    report = run_step(robot, Release("right"), ctx)
    assert report.success, report.detail
    assert robot.opening > 0.01
    assert ctx.graph.index_of("gripper", "right") is None
    assert ctx.graph.index_of("gripper", "left") == 1


def test_fingers_that_do_not_open_end_the_release_by_timeout_and_keep_the_model() -> None:
    ctx = make_context(_two_held(), "left")
    report = run_step(_Fingers(opens=False), Release("right"), ctx)
    assert report.cause == "timeout"
    assert ctx.graph.index_of("gripper", "right") == 2
