import math

import numpy as np
import pytest

from tautwire.primitives import RotateAroundFeaturePoint, SingleArmTension
from tautwire.tasks import TickRecord, run_step
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
    # the model's contact point is the reported estimate (the lines' fused
    # with the centre of the gripper's own circle)
    reported = ctx.estimator.contact_estimate()
    assert reported is not None and reported.trusted
    assert np.linalg.norm(reported.position - CONTACT) < 0.002
    c = ctx.estimator.contact_index
    assert c is not None and np.allclose(ctx.graph.points[c].position, reported.position)


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


def test_the_turn_counted_is_the_grippers_about_the_contact() -> None:
    # the span from a point contact turns as the gripper does: at success the
    # gripper's own angle about the true contact is the angle asked, to what
    # the estimate's error e at the radius r can do (about e / r) and a period
    # (judged when the turn is done, before I's bias check holds still)
    robot = SpringCableRobot(CONTACT, GRIPPER, 200.0, seed=7)
    ctx = tensioned(robot)
    a0 = robot.p[:2] - CONTACT[:2]
    rotate = RotateAroundFeaturePoint("left", 1.2, speed=0.5)
    done: list[tuple[np.ndarray, np.ndarray]] = []

    def on_tick(record: TickRecord) -> None:
        if rotate._check is not None and not done:
            estimate = ctx.estimator.contact_position()
            assert estimate is not None
            done.append((robot.p.copy(), estimate))

    report = run_step(robot, rotate, ctx, on_tick=on_tick)
    assert report.success and done
    p, estimate = done[0]
    a1 = p[:2] - CONTACT[:2]
    true_turn = math.atan2(a0[0] * a1[1] - a0[1] * a1[0], float(a0 @ a1))
    e = float(np.linalg.norm(estimate[:2] - CONTACT[:2]))
    r = float(np.linalg.norm(a1))
    assert abs(true_turn - 1.2) < 1.5 * e / r + math.radians(0.5)
    # holding still for the check turns the gripper no further
    a2 = robot.p[:2] - CONTACT[:2]
    assert abs(math.atan2(a1[0] * a2[1] - a1[1] * a2[0], float(a1 @ a2))) < math.radians(0.5)


@pytest.mark.parametrize("sense", [1.0, -1.0])
def test_a_pegs_span_turns_with_its_tangent(sense: float) -> None:
    # the gripper spirals in about a peg of radius R: the span's direction
    # (tangent point to gripper) turns by the gripper's angle plus the change
    # of s asin(R / D); the count follows it, not the gripper's angle alone
    centre = np.array([0.1, 0.2, 0.0])
    radius = 0.02
    primitive = RotateAroundFeaturePoint("left", 2.0)
    primitive.turned = 0.0
    primitive._previous = None
    bend = (np.array([0.0, 0.0, 1.0]), sense, radius)

    def span_angle(phi: float, distance: float) -> float:
        return phi + sense * math.asin(radius / distance)

    phis = np.linspace(0.0, 1.5, 200)
    distances = np.linspace(0.30, 0.05, 200)
    for phi, distance in zip(phis, distances, strict=True):
        p = centre + distance * np.array([math.cos(phi), math.sin(phi), 0.0])
        primitive._track_angle(p, centre, bend)
    expected = span_angle(1.5, 0.05) - span_angle(0.0, 0.30)
    assert primitive.turned == pytest.approx(expected, abs=1e-9)
    # a jump of the estimate between periods turns a still gripper's span by
    # nothing: neither the gripper's angle nor the bend counts it
    before = primitive.turned
    p = centre + 0.05 * np.array([math.cos(1.5), math.sin(1.5), 0.0])
    jumped = centre + np.array([0.01, -0.01, 0.0])
    primitive._track_angle(p, jumped, bend)
    primitive._track_angle(p, jumped, bend)
    assert primitive.turned == pytest.approx(before, abs=1e-12)


@pytest.mark.parametrize("sense", [1.0, -1.0])
def test_a_peg_that_takes_over_from_a_point_adds_no_bend_of_its_own(sense: float) -> None:
    # the shipped harness's last peg: I starts about the clip before it (a
    # point), the peg is declared mid-turn; from then on the span turns as the
    # gripper does about the peg plus the change of the bend, and the change
    # itself adds nothing (it added asin(R / D), 4.4 deg of a 20 deg turn)
    peg = np.array([0.62, -0.40, 0.0])
    clip = np.array([0.50, -0.33, 0.0])
    radius = 0.0085
    primitive = RotateAroundFeaturePoint("right", -0.5)
    primitive.turned = 0.0
    primitive._previous = None
    p0 = peg + 0.11 * np.array([math.cos(-0.6), math.sin(-0.6), 0.0])
    primitive._track_angle(p0, clip, None)
    p1 = peg + 0.11 * np.array([math.cos(-0.62), math.sin(-0.62), 0.0])
    primitive._track_angle(p1, peg, (np.array([0.0, 0.0, 1.0]), sense, radius))
    # the same distance from the peg: its bend did not change, the gripper turned 0.02 rad
    assert primitive.turned == pytest.approx(-0.02, abs=1e-9)
