"""G turns the gripper onto the cable and never edits the cable's contacts."""

from __future__ import annotations

import math

import numpy as np

from tautwire.primitives.gripper_alignment import GripperAlignment
from tautwire.tasks import TickRecord, run_step

from .conftest import CONTACT, GRIPPER, context
from .spring_robot import SpringCableRobot


def test_a_contact_declared_while_g_turns_in_place_is_dropped() -> None:
    robot = SpringCableRobot(CONTACT, GRIPPER, stiffness=200.0, noise=0.05, seed=2)
    robot.rest -= 3.0 / 200.0
    yaw = math.radians(40.0)
    robot.q = np.array([math.cos(yaw / 2), 0.0, 0.0, math.sin(yaw / 2)])
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
