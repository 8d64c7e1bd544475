import math

import numpy as np
import pytest

from tautwire.primitives import RotateAroundFeaturePoint, SingleArmTension
from tautwire.tasks import run_step
from tests.primitives.conftest import CONTACT, GRIPPER, context
from tests.primitives.spring_robot import SpringCableRobot


def tensioned(robot: SpringCableRobot, **kwargs: object):  # type: ignore[no-untyped-def]
    ctx = context(**kwargs)  # type: ignore[arg-type]
    assert run_step(robot, SingleArmTension("left", 3.0), ctx).success
    return ctx


def test_full_turn_estimates_the_contact() -> None:
    robot = SpringCableRobot(CONTACT, GRIPPER, 200.0, seed=3)
    ctx = tensioned(robot, estimation_period=0.08)
    report = run_step(robot, RotateAroundFeaturePoint("left", 2 * math.pi, speed=0.5), ctx)
    assert report.success, report
    estimate = ctx.estimator.contact_filter.estimate
    assert estimate is not None
    assert np.linalg.norm(estimate - CONTACT) < 0.002
    # the gripper went round at the cable's length, tension kept
    assert np.linalg.norm(robot.p - CONTACT) == pytest.approx(0.3 + 3.0 / 200.0, abs=0.005)
    assert robot.tension() == pytest.approx(3.0, abs=0.5)
    # the model's contact point is the estimate
    c = ctx.estimator.contact_index
    assert c is not None and np.allclose(ctx.graph.points[c].position, estimate)


def test_negative_angle_turns_the_other_way() -> None:
    robot = SpringCableRobot(CONTACT, GRIPPER, 200.0, seed=5)
    ctx = tensioned(robot)
    start = robot.p.copy()
    report = run_step(robot, RotateAroundFeaturePoint("left", -math.pi / 2, speed=0.5), ctx)
    assert report.success
    assert robot.p[1] < start[1] - 0.2  # clockwise seen from above: from +x towards -y


def test_contact_change_adds_a_feature_point() -> None:
    # a peg the straight span sweeps over while circling
    second = CONTACT + 0.15 * np.array([np.cos(1.5), np.sin(1.5), 0.0])
    robot = SpringCableRobot(
        CONTACT,
        GRIPPER,
        200.0,
        seed=6,
        second_contact=second,
        switch_time=2.0,
        switch_on_chord=True,
    )
    ctx = tensioned(robot, estimation_period=0.04)
    n_points = len(ctx.graph)
    report = run_step(robot, RotateAroundFeaturePoint("left", 2 * math.pi, speed=0.5), ctx)
    assert report.success
    assert len(ctx.estimator.changes) == 1
    assert len(ctx.graph) == n_points + 1
    estimate = ctx.estimator.contact_filter.estimate
    assert estimate is not None and np.linalg.norm(estimate - second) < 0.003


def test_slack_cable_fails_with_slipped() -> None:
    robot = SpringCableRobot(CONTACT, GRIPPER, 200.0, seed=8)
    ctx = tensioned(robot)
    robot.rest += 1.0  # the cable suddenly slips through the fixture
    report = run_step(robot, RotateAroundFeaturePoint("left", math.pi, speed=0.5), ctx)
    assert report.outcome == "failure" and report.cause in ("slipped", "timeout")
