"""G turns the gripper onto the cable and never edits the cable's contacts."""

from __future__ import annotations

import math

import numpy as np

from tautwire.primitives.gripper_alignment import GripperAlignment
from tautwire.tasks import TickRecord, run_step

from .conftest import CONTACT, GRIPPER, context
from .spring_robot import SpringCableRobot


def turned_robot(pull: float, yaw_deg: float, seed: int) -> SpringCableRobot:
    """A 200 N/m cable pulled to ``pull`` [N], the tool turned ``yaw_deg`` off it."""
    robot = SpringCableRobot(CONTACT, GRIPPER, stiffness=200.0, noise=0.05, seed=seed)
    robot.rest -= pull / 200.0
    yaw = math.radians(yaw_deg)
    robot.q = np.array([math.cos(yaw / 2), 0.0, 0.0, math.sin(yaw / 2)])
    return robot


def test_a_contact_declared_while_g_turns_in_place_is_dropped() -> None:
    robot = turned_robot(3.0, 40.0, seed=2)
    ctx = context(k_initial=200.0, estimation_period=0.04)
    ctx.tension = 3.0
    before = [(p.kind, p.label) for p in ctx.graph.points]
    ticks = [0]

    def declare(record: TickRecord) -> None:
        # what the contact filter does when the turning fingers move the force's line:
        # a new contact point 2 mm before the gripper
        ticks[0] += 1
        if ticks[0] == 20:
            graph = record.context.graph
            s = float(graph.arc_lengths()[-1]) - 0.002
            i = graph.insert_at_arc_length(s, kind="contact", label="estimated")
            graph.points[i].kind, graph.points[i].label = "contact", "estimated"

    report = run_step(robot, GripperAlignment("left"), ctx, on_tick=declare)
    assert report.success, report.detail
    assert ticks[0] > 20
    assert [(p.kind, p.label) for p in ctx.graph.points] == before
    # and the gripper's tool axis lies along the cable (here world -x or +x)
    x_axis = 1.0 - 2.0 * (robot.q[2] ** 2 + robot.q[3] ** 2)
    assert abs(x_axis) > math.cos(math.radians(3.0))


def test_the_turn_waits_while_the_tension_is_far_above_its_set_point() -> None:
    # the cable starts pulled to 8 N, the set point is 3 N: the fingers turn only
    # once the force control has let the cable out (random board 1695658280:
    # turning 85 deg against a cable resting on a clip pulled 13 N)
    robot = turned_robot(8.0, 60.0, seed=3)
    ctx = context(k_initial=200.0, estimation_period=0.04)
    ticks: list[tuple[float, float]] = []

    def watch(record: TickRecord) -> None:
        state = record.context.estimator.state
        assert state is not None
        turn = float(np.linalg.norm(record.command.twist[3:6]))
        ticks.append((state.tension, turn))

    report = run_step(robot, GripperAlignment("left", force=3.0), ctx, on_tick=watch)
    assert report.success, report.detail
    high = [turn for tension, turn in ticks if tension > 2.0 * 3.0]
    assert high, "the cable never read above twice its set point"
    assert max(high) < 1e-9
    assert max(turn for _, turn in ticks) > 0.05  # and it did turn, later
