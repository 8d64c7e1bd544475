import numpy as np
import pytest

from tautwire.errors import InvalidArgumentError
from tautwire.model import PathGraph
from tautwire.primitives import PrimitiveContext, SingleArmTension, make_context
from tautwire.primitives.clip_sensing import JAW_TOP
from tautwire.primitives.context import ClipInfo
from tautwire.primitives.model_estimator import TensionState
from tautwire.primitives.single_arm_tension import SLACK_PULL_SPEED
from tautwire.robot import Command
from tautwire.tasks import TickRecord, run_step
from tautwire.tasks.runner import PROTECTIVE_STOP
from tests.primitives.conftest import CONTACT, GRIPPER, context
from tests.primitives.spring_robot import SpringCableRobot


@pytest.mark.parametrize("k", [10.0, 100.0, 1000.0])
@pytest.mark.parametrize("guess", [0.1, 10.0])
def test_tensions_with_a_stiffness_guess_off_by_ten(k: float, guess: float) -> None:
    robot = SpringCableRobot(CONTACT, GRIPPER, k, slack=0.01, seed=int(k))
    ctx = context(k_initial=k * guess)
    report = run_step(robot, SingleArmTension("left", 3.0), ctx)
    assert report.success, report
    assert robot.tension() == pytest.approx(3.0, abs=0.35)
    assert report.max_force < 15.0 and robot.true_max_force < 15.0
    assert ctx.tension == 3.0


def test_learns_the_stiffness_while_tensioning() -> None:
    robot = SpringCableRobot(CONTACT, GRIPPER, 200.0, slack=0.0, seed=4)
    ctx = context(k_initial=20.0)
    report = run_step(robot, SingleArmTension("left", 3.0, duration=3.0), ctx)
    assert report.success
    assert ctx.estimator.elasticity.k_hat == pytest.approx(200.0, rel=0.2)


def test_learns_only_near_the_set_point() -> None:
    # pulled from 2 cm of slack, the estimate must not fit the slack's samples
    robot = SpringCableRobot(CONTACT, GRIPPER, 500.0, slack=0.02, seed=5)
    ctx = context(k_initial=50.0)
    step = SingleArmTension("left", 3.0, duration=2.0)
    learnt_while_far = []

    def watch(rec: TickRecord) -> None:
        state = ctx.estimator.state
        assert state is not None
        if state.tension < 2.0:
            learnt_while_far.append(ctx.estimator.learn_elasticity)

    report = run_step(robot, step, ctx, on_tick=watch)
    assert report.success
    assert learnt_while_far and not any(learnt_while_far[:10])
    assert ctx.estimator.elasticity.k_hat == pytest.approx(500.0, rel=0.1)


def test_the_set_point_swings_by_the_excitation() -> None:
    step = SingleArmTension("left", 2.0, excitation=0.05, excitation_period=2.0)
    assert step.set_point(0.0) == pytest.approx(2.0)
    assert step.set_point(0.5) == pytest.approx(2.1)
    assert step.set_point(1.5) == pytest.approx(1.9)
    assert SingleArmTension("left", 2.0, excitation=0.0).set_point(0.5) == 2.0
    assert SingleArmTension("left", 2.0, tolerance=0.04).excitation == pytest.approx(0.02)


def test_no_contact_when_nothing_holds_the_cable() -> None:
    robot = SpringCableRobot(CONTACT, GRIPPER, 100.0, slack=10.0, seed=1)  # never taut
    report = run_step(robot, SingleArmTension("left", 3.0), context())
    assert report.outcome == "failure" and report.cause == "no_contact"


def test_force_limit_ends_the_step() -> None:
    robot = SpringCableRobot(CONTACT, GRIPPER, 1000.0, slack=0.0, seed=2)
    report = run_step(robot, SingleArmTension("left", 20.0), context(), force_limit=15.0)
    assert report.cause == "force_limit" and report.max_force > PROTECTIVE_STOP * 15.0


def test_arguments_are_checked() -> None:
    with pytest.raises(InvalidArgumentError):
        SingleArmTension("middle", 3.0)  # type: ignore[arg-type]
    with pytest.raises(InvalidArgumentError):
        SingleArmTension("left", -1.0)
    with pytest.raises(InvalidArgumentError):
        SingleArmTension("left", 3.0, excitation=0.1)  # not inside the 10 % tolerance
    with pytest.raises(InvalidArgumentError):
        SingleArmTension("left", 3.0, excitation_period=0.0)


def test_deterministic() -> None:
    reports = []
    for _ in range(2):
        robot = SpringCableRobot(CONTACT, GRIPPER, 100.0, slack=0.01, seed=7)
        reports.append(run_step(robot, SingleArmTension("left", 3.0), context()))
        reports.append(robot.p.copy())
    assert reports[0] == reports[2]
    assert np.array_equal(reports[1], reports[3])


class SlippingCableRobot(SpringCableRobot):
    """From ``slip_time`` on, the cable slides through the fingers above ``friction`` [N]."""

    def __init__(self, *args: object, slip_time: float, friction: float = 0.2, **kw: object):
        super().__init__(*args, **kw)  # type: ignore[arg-type]
        self.slip_time = slip_time
        self.friction = friction

    def act(self, command: Command) -> None:
        super().act(command)
        if self.time >= self.slip_time and self.tension() > self.friction:
            distance = float(np.linalg.norm(self.contact - self.p))
            self.rest = distance - self.friction / self.k  # the cable slid through


@pytest.mark.parametrize("k", [10.0, 1500.0])
def test_knows_the_stiffness_at_the_end(k: float) -> None:
    # a generic 100 N/m guess, ten times off either way, and a noisy sensor
    robot = SpringCableRobot(CONTACT, GRIPPER, k, slack=0.005, noise=0.1, seed=11)
    ctx = context(k_initial=100.0, force_noise=0.1)
    step = SingleArmTension("left", 1.5)
    report = run_step(robot, step, ctx)
    assert report.success, report
    assert ctx.estimator.elasticity.k_hat == pytest.approx(k, rel=0.05)
    assert step.learn_time is not None and step.learn_time >= step.min_learn_time
    assert robot.true_max_force < 0.8 * 15.0


def test_learning_swing_is_larger_and_ends_in_the_hold_phase() -> None:
    robot = SpringCableRobot(CONTACT, GRIPPER, 500.0, slack=0.005, seed=12)
    ctx = context(k_initial=100.0)
    step = SingleArmTension("left", 2.0)
    set_points: dict[str, list[float]] = {"approach": [], "learning": [], "hold": []}

    def watch(rec: TickRecord) -> None:
        set_points[step.phase].append(step.set_point(step.elapsed))

    report = run_step(robot, step, ctx, on_tick=watch)
    assert report.success
    learning = np.asarray(set_points["learning"])
    hold = np.asarray(set_points["hold"])
    assert learning.max() == pytest.approx(2.0 * (1.0 + step.learn_excitation), rel=0.01)
    assert np.abs(hold - 2.0).max() <= 2.0 * step.excitation + 1e-9
    assert len(hold) * robot.control_period >= step.hold_time


def test_the_swing_keeps_under_the_force_limit() -> None:
    robot = SpringCableRobot(CONTACT, GRIPPER, 300.0, slack=0.005, seed=13)
    ctx = context(k_initial=100.0, force_limit=12.0)
    step = SingleArmTension("left", 9.0)
    report = run_step(robot, step, ctx)
    assert report.success, report
    assert robot.true_max_force < 12.0


def test_a_slip_fails_within_the_travel_bound() -> None:
    # taut at 1 s, then the cable slides through the fingers: D must not pull on and on
    robot = SlippingCableRobot(CONTACT, GRIPPER, 500.0, slack=0.005, seed=14, slip_time=1.0)
    ctx = context(k_initial=100.0)
    report = run_step(robot, SingleArmTension("left", 3.0), ctx)
    assert report.outcome == "failure" and report.cause == "slipped", report
    route = float(np.linalg.norm(robot.p - CONTACT))
    rest = float(np.linalg.norm(GRIPPER - CONTACT))
    # at most the rest length plus the stretch at the force limit plus the margins
    assert route <= rest * 1.05 + 0.03 + 15.0 / 100.0 + 0.01
    assert report.sim_time < 5.0


def test_a_soft_cable_on_a_stiff_guess_is_not_taken_for_a_slip() -> None:
    # 10 N/m at 4 N stretches 0.4 m, more than the guess's 15 N / 100 N/m
    robot = SpringCableRobot(CONTACT, GRIPPER, 10.0, slack=0.01, seed=15)
    report = run_step(robot, SingleArmTension("left", 4.0), context(k_initial=100.0))
    assert report.success, report


class CreepingCableRobot(SpringCableRobot):
    """The rest length grows by ``creep`` [m/s] until ``until`` [s] (settling round a peg)."""

    def __init__(self, *args: object, creep: float, until: float, **kw: object):
        super().__init__(*args, **kw)  # type: ignore[arg-type]
        self.creep = creep
        self.until = until

    def act(self, command: Command) -> None:
        super().act(command)
        if self.time < self.until:
            self.rest += self.creep * self.control_period


def test_a_creeping_cable_is_learnt_once_it_has_settled() -> None:
    # 0.5 mm/s of creep for 4 s on a 1000 N/m cable: 0.5 N/s that no spring makes
    robot = CreepingCableRobot(
        CONTACT, GRIPPER, 1000.0, slack=0.005, seed=16, creep=5e-4, until=4.0
    )
    ctx = context(k_initial=100.0)
    report = run_step(robot, SingleArmTension("left", 2.0), ctx)
    assert report.success, report
    assert ctx.estimator.elasticity.k_hat == pytest.approx(1000.0, rel=0.1)


def test_a_cable_that_goes_slack_after_it_was_taut_has_slipped() -> None:
    """Taut at its set point, then slack for a second: D fails with ``slipped``."""
    from tautwire.primitives import SingleArmTension
    from tautwire.tasks import TickRecord, run_step
    from tests.primitives.conftest import CONTACT, GRIPPER, context
    from tests.primitives.spring_robot import SpringCableRobot

    robot = SpringCableRobot(CONTACT, GRIPPER, 200.0, seed=4)
    ctx = context()
    tension = SingleArmTension("left", 3.0, learn_timeout=30.0)

    def on_tick(record: TickRecord) -> None:
        if tension.phase != "approach" and robot.rest < 1.0:
            robot.rest += 1.0  # the cable slips through its fixture

    report = run_step(robot, tension, ctx, on_tick=on_tick)
    assert report.outcome == "failure" and report.cause == "slipped", report
    assert "below 0.33 of its set point" in report.detail


def test_slack_behind_a_clip_is_drawn_along_the_route_at_the_slack_speed() -> None:
    # random board 1627120487: after C into F4, 88 mm of slack lay behind
    # the clip; pulled with the gain of the stiff taut edge (2715 N/m) along
    # a direction that at 0.3 N was the tail's weight, D crawled at 3 mm/s
    ctx = context(k_initial=2715.0)
    step = SingleArmTension("left", 3.0)
    robot = SpringCableRobot(CONTACT, GRIPPER, 2715.0, slack=0.05, seed=1)
    obs = robot.observe()
    wandering = np.array([0.0, 0.3, -0.95])
    state = TensionState(
        tension=0.3,
        direction=wandering / np.linalg.norm(wandering),
        force=0.3 * wandering,
        raw_force=0.3 * wandering,
        contact=CONTACT.copy(),
        span=float(np.linalg.norm(CONTACT - GRIPPER)),
        taut=True,
    )
    pull, k_gain = step._slack_pull(ctx, obs, state, 3.0)
    line = (CONTACT - GRIPPER) / np.linalg.norm(CONTACT - GRIPPER)
    assert np.allclose(pull.direction, line)  # along the model's route
    assert pull.tension == state.tension and pull.contact is state.contact
    assert k_gain is not None
    speed = ctx.controller.force.speed(3.0, 0.0, k_gain)
    assert abs(speed) == pytest.approx(SLACK_PULL_SPEED)
    # the stiff edge's own gain is many times slower
    assert abs(ctx.controller.force.speed(3.0, 0.0, 2715.0)) < 0.3 * SLACK_PULL_SPEED


@pytest.mark.parametrize("held", [True, False])
def test_at_a_clip_in_line_with_the_point_before_it_d_tugs_to_tell_held_from_left(
    held: bool,
) -> None:
    # random board 1652323633 (seed 0): D's pull drew the cable out of clip
    # F2, whose line from the gripper passed through peg F1 behind it, and D
    # reported success against F1: only lifting about the clip tells them apart
    ctx, gripper, exit_point, far = _clip_scene("F2", 300.0)
    robot = SpringCableRobot(exit_point if held else far, gripper, 300.0, slack=0.005, seed=3)
    report = run_step(robot, SingleArmTension("left", 3.0), ctx)
    if held:
        assert report.success, report
        assert "at F2 swung aside" in report.detail and ": held" in report.detail
        # back at rest after the tug
        assert np.linalg.norm(robot.p[[1, 2]] - gripper[[1, 2]]) < 0.004
    else:
        assert not report.success
        assert report.cause == "left_fixture" and "F2" in report.detail, report


def test_against_an_anchor_d_does_not_tug() -> None:
    # the tug is for a clip in line with the point behind it; an anchor is
    # the fixed end itself, and Table I's D scenes end as they did
    robot = SpringCableRobot(CONTACT, GRIPPER, 300.0, slack=0.005, seed=5)
    report = run_step(robot, SingleArmTension("left", 3.0), context(k_initial=300.0))
    assert report.success, report
    assert "swung aside" not in report.detail
    assert np.linalg.norm(robot.p[[1, 2]] - GRIPPER[[1, 2]]) < 1e-3  # held still across the cable


def test_slack_drawn_through_a_clip_after_the_cable_was_taut_is_taken_up_anew() -> None:
    # random board 1729667587 (seed 30): taut at 3 N from clip F3, D drew
    # slack the model did not know of through F3 in a slip; the tension
    # stayed at 0.1 N for a second. A clip holds across, not along: D takes
    # the slack up again and holds (an anchor's slip still fails: above)
    ctx, gripper, exit_point, _ = _clip_scene("F3", 1000.0)
    robot = SpringCableRobot(exit_point, gripper, 1000.0, slack=0.005, seed=3)
    tension = SingleArmTension("left", 3.0)
    slipped: list[float] = []

    def on_tick(record: TickRecord) -> None:
        if tension.phase != "approach" and not slipped:
            robot.rest += 0.04  # 40 mm drawn through the clip at once
            slipped.append(record.observation.time)

    report = run_step(robot, tension, ctx, on_tick=on_tick)
    assert slipped
    assert report.success, report
    assert "took up slack drawn through F3 once" in report.detail
    # the gripper pulled on by the slack drawn
    assert robot.p[0] > gripper[0] + 0.035


def test_slack_drawn_through_two_clips_leaves_both_spans_behind_straight() -> None:
    # cable drawn through F3 comes through F2 too: F3 moves by both spans' slack
    a1, f2, f3 = np.array([0.0, 0.0, 0.08]), np.array([0.1, 0.0, 0.08]), np.array([0.2, 0.0, 0.08])
    sag12, sag23 = np.array([0.05, 0.0, 0.05]), np.array([0.15, 0.0, 0.06])
    gripper = np.array([0.35, 0.0, 0.1])
    graph = PathGraph.from_positions(
        [a1, sag12, f2, sag23, f3, gripper],
        mass_per_length=0.0,
        kinds=["fixed", "free", "fixed", "free", "fixed", "gripper"],
        labels=["A1", "", "F2", "", "F3", "left"],
    )
    s = graph.arc_lengths()
    slack12 = float(s[2] - s[0]) - 0.1
    slack23 = float(s[4] - s[2]) - 0.1
    total = float(s[5])
    ctx = make_context(graph, "left", k_initial=500.0)
    step = SingleArmTension("left", 3.0)
    step._through = ((4, slack23), (2, slack12))  # the route's order: nearest the gripper first
    note = step._draw_through(ctx)
    assert "through F3" in note and "through F2" in note
    labels = [p.label for p in ctx.graph.points]
    assert labels == ["A1", "F2", "F3", "left"]
    s = ctx.graph.arc_lengths()
    assert s[1] == pytest.approx(0.1)  # A1-F2 straight
    assert s[2] - s[1] == pytest.approx(0.1)  # F2-F3 straight
    assert s[3] == pytest.approx(total)  # no cable made or lost


def _clip_scene(clip: str, k: float) -> tuple[PrimitiveContext, np.ndarray, np.ndarray, np.ndarray]:
    """Anchor A1, clip ``clip`` and the left gripper in a line along x, the model's k ``k``.

    Returns:
        The context, the gripper's position, the clip's exit (jaws' top) and
        the anchor, at the exit's height.
    """
    info = ClipInfo(np.array([0.15, 0.0, 0.092]), 0.0, 4.0, 0.02)
    gripper = np.array([0.35, 0.0, 0.1])
    exit_point = info.exit_towards(gripper) + np.array([0.0, 0.0, JAW_TOP])
    far = np.array([0.0, 0.0, float(exit_point[2])])
    gripper[2] = exit_point[2]
    graph = PathGraph.from_positions(
        [far, info.position, gripper],
        mass_per_length=0.0,
        kinds=["fixed", "fixed", "gripper"],
        labels=["A1", clip, "left"],
    )
    return make_context(graph, "left", k_initial=k, clips={clip: info}), gripper, exit_point, far
